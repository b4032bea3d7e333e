// The stress scene generator (stress_scene.h).
#include "05_sap/stress_scene.h"

#include "math/random.h"
#include "world/json_reader.h"
#include "world/scene.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace stepwise {

namespace {

const Names<StressDensity> kDensities = {{"sparse", StressDensity::Sparse}, {"dense", StressDensity::Dense}};
const Names<StressShape> kShapes = {{"sphere", StressShape::Sphere},
                                    {"diamond", StressShape::Diamond},
                                    {"box", StressShape::Box},
                                    {"mixed", StressShape::Mixed},
                                    {"capsule", StressShape::Capsule},
                                    {"cylinder", StressShape::Cylinder},
                                    {"all", StressShape::All}};

/// Each kind of body fits in a ball of radius 0.5 m about its origin, so turned any way it stays
/// inside its 1 m cell.
struct StressShapes {
    Shape sphere = Shape::sphere(Real(0.5));
    // An octahedron, taller than wide: no face-to-face resting, GJK and EPA for every contact.
    // One hull shared by every diamond (Shape holds it by shared_ptr).
    Shape diamond = Shape::convex({Vec3(Real(0.35), 0, 0), Vec3(Real(-0.35), 0, 0), Vec3(0, Real(0.5), 0),
                                   Vec3(0, Real(-0.5), 0), Vec3(0, 0, Real(0.35)), Vec3(0, 0, Real(-0.35))});
    Shape box = Shape::box(Vec3(Real(0.35), Real(0.25), Real(0.25)));  // corner 0.497 m out
    Shape capsule = Shape::capsule(Real(0.2), Real(0.3));                // tip 0.5 m out
    // Cap rim at sqrt(0.3^2 + 0.35^2) = 0.461 m: a can a little wider than tall rests on either.
    Shape cylinder = Shape::cylinder(Real(0.3), Real(0.35));

    const Shape& pick(StressShape kind, int index) const {
        switch (kind) {
            case StressShape::Sphere: return sphere;
            case StressShape::Diamond: return diamond;
            case StressShape::Box: return box;
            case StressShape::Capsule: return capsule;
            case StressShape::Cylinder: return cylinder;
            case StressShape::Mixed: break;
            case StressShape::All: {
                const Shape* const every[] = {&sphere, &diamond, &box, &capsule, &cylinder};
                return *every[index % 5];
            }
        }
        const int which = index % 3;
        return which == 0 ? sphere : which == 1 ? diamond : box;
    }
};

/// Cells of the layout: columns along x and z, layers up y.
struct Grid {
    int columns = 1;  // along x and along z
    int layers = 1;
};

Grid layoutFor(const StressParams& params) {
    Grid grid;
    if (params.density == StressDensity::Sparse) {
        grid.columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(params.count))));
        grid.layers = 1;
    } else {
        grid.columns = static_cast<int>(std::ceil(math::cbrt(static_cast<double>(params.count))));
        grid.layers = (params.count + grid.columns * grid.columns - 1) / (grid.columns * grid.columns);
    }
    return grid;
}

}  // namespace

const char* toString(StressDensity density) { return nameOf(kDensities, density); }

const char* toString(StressShape shape) { return nameOf(kShapes, shape); }

const Names<StressShape>& stressShapeNames() { return kShapes; }

Real stressSpacing(StressDensity density) { return density == StressDensity::Dense ? Real(1) : Real(4); }

// [ch05-stress-scene]
void addStressBodies(World& world, const StressParams& params) {
    const Real spacing = stressSpacing(params.density);
    const Grid grid = layoutFor(params);
    const Real halfWidth = Real(0.5) * spacing * static_cast<Real>(grid.columns);

    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(halfWidth + 10, Real(0.5), halfWidth + 10));

    const StressShapes shapes;
    Random random(params.seed);
    // Each body sits at random in its own cell, up to 45% of the gap off the cell's centre:
    // neighbours never start touching, and a sparse layer is not lined up in rows and columns
    // (aligned columns would be a worst case for any sweep along x or z).
    const Real slack = Real(0.45) * (spacing - 1);
    world.bodies.reserve(world.bodies.size() + static_cast<std::size_t>(params.count));
    world.motions.reserve(world.motions.size() + static_cast<std::size_t>(params.count));
    for (int index = 0; index < params.count; ++index) {
        const int perLayer = grid.columns * grid.columns;
        const int layer = index / perLayer;
        const int column = (index % perLayer) % grid.columns;
        const int row = (index % perLayer) / grid.columns;
        BodyDef def;
        def.name = "b" + std::to_string(index);
        def.shape = shapes.pick(params.shape, index);
        // One draw per statement: the order of a call's arguments is unspecified, and two draws
        // in one call gave Clang other scenes than GCC. z first, GCC's order, keeps the scenes.
        const Real jitterZ = Real(random.uniform(-slack, slack));
        const Real jitterX = Real(random.uniform(-slack, slack));
        def.transform.position = Vec3(-halfWidth + spacing * (Real(0.5) + static_cast<Real>(column)) + jitterX,
                                      params.dropHeight + Real(0.5) + spacing * static_cast<Real>(layer),
                                      -halfWidth + spacing * (Real(0.5) + static_cast<Real>(row)) + jitterZ);
        def.transform.rotation = random.rotation();
        addBody(world, def);
    }
}
// [ch05-stress-scene]

World buildStressScene(const StressParams& params, const std::string& name) {
    World world = emptyWorld(name);
    addStressBodies(world, params);
    return world;
}

StressParams readStressParams(const JsonCursor& cursor) {
    // "seed" is the same number under its older name, still read so that older files load.
    cursor.expectObject({"count", "density", "shape", "drop_height", "arrangement", "seed"});
    if (cursor.has("arrangement") && cursor.has("seed")) cursor.fail("give \"arrangement\" or its older name \"seed\", not both");
    StressParams params;
    if (auto v = cursor.optional("count")) params.count = v->integer(1, kStressMaxCount);
    if (auto v = cursor.optional("density")) params.density = v->choice(kDensities);
    if (auto v = cursor.optional("shape")) params.shape = v->choice(kShapes);
    if (auto v = cursor.optional("drop_height")) params.dropHeight = v->inRange(0, kStressMaxDropHeight);
    for (const char* key : {"arrangement", "seed"})
        if (auto v = cursor.optional(key)) params.seed = static_cast<std::uint32_t>(v->integer(0, 1 << 30));
    return params;
}

std::string stressSceneFile(const StressParams& params, const Settings& settings, const std::string& name) {
    World empty = emptyWorld(name);
    empty.settings = settings;
    Json scene = parseStrictJson(saveSceneToString(empty), name);
    scene.erase("bodies");
    scene.erase("joints");
    scene.erase("forces");
    scene["generator"] = {{"stress",
                           {{"count", params.count},
                            {"density", toString(params.density)},
                            {"shape", toString(params.shape)},
                            {"drop_height", tidyNumber(params.dropHeight)},
                            {"arrangement", params.seed}}}};
    return scene.dump(2) + "\n";
}

}  // namespace stepwise
