// Chapter 10's scenes, and the pyramids and pile the later chapters measure on.
#include "10_skip_work/scenes.h"

#include "04_pgs/scenes.h"
#include "06_manifolds/scenes.h"
#include "math/random.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace stepwise {

World buildPyramidRow(int count, int rows, Real spacing) {
    const std::string touching = spacing == kTouchingSpacing ? "-touching" : "";
    World world = emptyWorld("pyramids-" + std::to_string(count) + "x" + std::to_string(rows) + touching);
    // The ground reaches 5 m beyond the widest row and the outer pyramids (chapter 4's 40 m square
    // ground is narrower than a 100-row pyramid's 105 m base).
    const Real halfWidth = std::max(Real(20), Real(0.5) * spacing * static_cast<Real>(rows) + 5);
    const Real halfDepth = std::max(Real(20), Real(1.5) * static_cast<Real>(count) + 5);
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(halfWidth, Real(0.5), halfDepth), Quat::Identity(),
                 Material{});
    for (int pyramid = 0; pyramid < count; ++pyramid) {
        const Real z = Real(3) * (static_cast<Real>(pyramid) - Real(0.5) * static_cast<Real>(count - 1));
        for (int row = 0; row < rows; ++row) {
            const int boxes = rows - row;
            const Real left = -Real(0.5) * spacing * static_cast<Real>(boxes - 1);
            for (int i = 0; i < boxes; ++i)
                addCrate(world, "p" + std::to_string(pyramid) + "r" + std::to_string(row) + "b" + std::to_string(i),
                         Vec3(left + spacing * static_cast<Real>(i), Real(0.5) + static_cast<Real>(row), z),
                         Vec3::Constant(Real(0.5)), 1, Material{});
        }
    }
    return world;
}

namespace {

Shape pileShape(int index, Random& random, PileSizes sizes) {
    const Real size = random.uniformReal(sizes.smallest, sizes.largest);
    switch (index % 4) {
        case 0: {  // one draw per statement (z, then y)
            const Real z = random.uniformReal(sizes.smallest, sizes.largest);
            const Real y = random.uniformReal(sizes.smallest, sizes.largest);
            return Shape::box(Vec3(size, y, z));
        }
        case 1: return Shape::sphere(size);
        case 2: {
            // An irregular hull: the corners of a box, each pulled in or out a little.
            std::vector<Vec3> points;
            for (int corner = 0; corner < 8; ++corner)
                points.push_back(Vec3(corner & 1 ? size : -size, corner & 2 ? size : -size, corner & 4 ? size : -size) *
                                 random.uniformReal(Real(0.7), Real(1.1)));
            points.push_back(Vec3(0, Real(1.4) * size, 0));
            return Shape::convex(points);
        }
        default: return Shape::capsule(Real(0.6) * size, size);
    }
}

}  // namespace

World buildMixedPile(int count, bool roundShapes) { return buildMixedPile(count, roundShapes, PileSizes{}); }

World buildMixedPile(int count, bool roundShapes, PileSizes sizes) {
    const bool unlike = sizes.smallest != PileSizes{}.smallest || sizes.largest != PileSizes{}.largest;
    World world = emptyWorld((roundShapes ? (unlike ? "unlike-pile-" : "mixed-pile-") : "angular-pile-") + std::to_string(count));
    addGroundPlane(world);
    const int side = 12;  // bodies per row and column of a layer
    const Real spacing = Real(1.5);
    const Real halfWidth = Real(0.5) * spacing * side;
    const Real wallHeight = Real(1.5) + spacing * static_cast<Real>((count + side * side - 1) / (side * side));
    for (int wall = 0; wall < 4; ++wall) {
        const bool alongX = wall < 2;
        const Real offset = (wall % 2 == 0 ? -1 : 1) * (halfWidth + Real(0.25));
        addStaticBox(world, "wall" + std::to_string(wall),
                     alongX ? Vec3(offset, wallHeight / 2, 0) : Vec3(0, wallHeight / 2, offset),
                     alongX ? Vec3(Real(0.25), wallHeight / 2, halfWidth + Real(0.5))
                            : Vec3(halfWidth + Real(0.5), wallHeight / 2, Real(0.25)));
    }
    Random random(10);
    for (int i = 0; i < count; ++i) {
        const int layer = i / (side * side), cell = i % (side * side);
        BodyDef def;
        def.name = "body" + std::to_string(i);
        def.shape = pileShape(roundShapes ? i : 2 * (i % 2), random, sizes);  // boxes and hulls only: 0 and 2
        def.transform.position = Vec3(-halfWidth + spacing * (Real(0.5) + static_cast<Real>(cell % side)),
                                      Real(1.5) + spacing * static_cast<Real>(layer),
                                      -halfWidth + spacing * (Real(0.5) + static_cast<Real>(cell / side)));
        def.transform.rotation = random.rotation();
        def.density = 500;
        // Round bodies roll, or spin in place on one point, for ever on rigid surfaces, and one
        // moving body keeps its whole island awake: they get a little rolling resistance.
        if (isRound(def.shape)) def.material.rollingResistance = kPileRollingResistance;
        addBody(world, def);
    }
    return world;
}

void addChapter10Scenes(Registry& registry) {
    const char* category = "10 skipping work";
    registry.addScene({"islands-pyramids", 10, category, prose(R"(
        four 10-row pyramids, four islands: all sleep half a second after they come to rest; move
        a box with the gizmo and only its pyramid wakes)"),
                       [] { return buildPyramidRow(4, 10); }, {}});
}

}  // namespace stepwise
