// Chapter 6's stacking scenes.
#include "06_manifolds/scenes.h"

#include "04_pgs/scenes.h"
#include "06_manifolds/stacking_study.h"
#include "app/registry.h"

#include <cmath>
#include <string>

namespace stepwise {

namespace {

const Vec3 kUnitHalf(Real(0.5), Real(0.5), Real(0.5));

World stackingWorld(const std::string& name) {
    World world;
    world.name = name;
    addGroundPlane(world, kStackFriction);
    return world;
}

int addUnitBox(World& world, const std::string& name, const Vec3& center, Real mass) {
    return addCrate(world, name, center, kUnitHalf, mass, Material{kStackFriction, 0});
}

}  // namespace

World buildBoxStack(int count) {
    World world = stackingWorld("stack-" + std::to_string(count));
    for (int i = 0; i < count; ++i)
        addUnitBox(world, "box" + std::to_string(i), Vec3(0, Real(0.5) + static_cast<Real>(i), 0), 1);
    return world;
}

World buildPyramid(int rows) {
    World world = stackingWorld("pyramid-" + std::to_string(rows));
    const Real spacing = Real(1.05);
    for (int row = 0; row < rows; ++row) {
        const int boxes = rows - row;
        const Real left = -Real(0.5) * spacing * static_cast<Real>(boxes - 1);
        for (int i = 0; i < boxes; ++i)
            addUnitBox(world, "r" + std::to_string(row) + "b" + std::to_string(i),
                       Vec3(left + spacing * static_cast<Real>(i), Real(0.5) + static_cast<Real>(row), 0), 1);
    }
    return world;
}

World buildHeavyOnLight() {
    World world = stackingWorld("heavy-on-light");
    for (int i = 0; i < 3; ++i)
        addUnitBox(world, "light" + std::to_string(i), Vec3(Real(-1.1) + Real(1.1) * static_cast<Real>(i), Real(0.5), 0), 1);
    addCrate(world, "heavy", Vec3(0, Real(1.5), 0), Vec3(Real(1.6), Real(0.5), Real(0.5)), 100,
             Material{kStackFriction, 0});
    return world;
}

World buildMassTower(bool heaviestAtBottom) {
    World world = stackingWorld(heaviestAtBottom ? "tower-heavy-below" : "tower-heavy-above");
    const Real masses[] = {1000, 100, 10, 1};  // bottom to top when the heaviest is at the bottom
    for (int i = 0; i < 4; ++i) {
        const Real mass = heaviestAtBottom ? masses[i] : masses[3 - i];
        addUnitBox(world, "box" + std::to_string(static_cast<int>(mass)) + "kg", Vec3(0, Real(0.5) + static_cast<Real>(i), 0),
                   mass);
    }
    return world;
}

World buildCardHouse() {
    World world = stackingWorld("card-house");
    const Material card{Real(0.9), 0};
    const Vec3 cardHalf(Real(0.05), Real(0.6), Real(0.4));
    const Real lean = Real(0.35);  // rad from the vertical
    const Real height = 2 * cardHalf.y() * std::cos(lean);
    const Real foot = cardHalf.y() * std::sin(lean);
    for (int storey = 0; storey < 2; ++storey) {
        const int pairs = 2 - storey;
        const Real base = static_cast<Real>(storey) * (height + 2 * Real(0.05));
        for (int p = 0; p < pairs; ++p) {
            const Real x = (static_cast<Real>(p) - Real(0.5) * static_cast<Real>(pairs - 1)) * Real(1.1);
            for (int side : {-1, 1}) {
                const Real angle = static_cast<Real>(side) * lean;
                const Quat tilt(Eigen::AngleAxis<Real>(angle, Vec3::UnitZ()));
                // The plates' tops touch at x; their feet stand apart.
                const Vec3 center(x + static_cast<Real>(side) * (foot + cardHalf.x() * std::cos(lean)),
                                  base + Real(0.5) * height + Real(0.02), 0);
                addCrate(world, "card" + std::to_string(storey) + std::to_string(p) + (side < 0 ? "l" : "r"), center,
                         cardHalf, Real(0.5), card, tilt);
            }
        }
        if (storey == 0)
            addCrate(world, "floor", Vec3(0, height + Real(0.07), 0), Vec3(Real(1.3), Real(0.05), Real(0.4)), Real(0.5), card);
    }
    return world;
}

World buildStickingRamp(int* box) {
    World world = buildRampScene(Real(kPi / 6), Real(0.8), box);
    world.name = "stack-ramp";
    return world;
}

}  // namespace stepwise

namespace stepwise {

void addChapter06Scenes(Registry& registry) {
    const char* const category = "Stacking";
    registry.addScene({"stack-16", 6, category, "16 boxes stand: none moves sideways by more than a centimetre",
                       [] { return buildBoxStack(16); }, {}});
    registry.addScene({"pyramid-20", 6, category, "210 boxes in 20 rows stand still", [] { return buildPyramid(20); }, {}});
    registry.addScene({"heavy-on-light", 6, category, "100 kg on three 1 kg boxes sinks no more than the slop per contact",
                       [] { return buildHeavyOnLight(); }, {}});
    registry.addScene({"tower-heavy-below", 6, category, "1, 10, 100, 1000 kg from the top: it stands",
                       [] { return buildMassTower(true); }, {}});
    registry.addScene({"tower-heavy-above", 6, category, "1000 kg on top of 100, 10 and 1 kg: the hard case",
                       [] { return buildMassTower(false); }, {}});
    registry.addScene({"card-house", 6, category, "thin plates leaning on each other hold by friction",
                       [] { return buildCardHouse(); }, {}});
    registry.addScene({"stack-ramp", 6, category, "a box on a 30 degree ramp with mu 0.8 does not creep",
                       [] { return buildStickingRamp(); }, {}});
}

}  // namespace stepwise
