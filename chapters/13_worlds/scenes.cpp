// Chapter 13's scenes.
#include "13_worlds/scenes.h"

#include "04_pgs/scenes.h"
#include "10_skip_work/scenes.h"
#include "math/random.h"

#include <cmath>
#include <functional>

namespace stepwise {

namespace {

CompoundChild boxChild(const Vec3& halfExtents, const Vec3& position) {
    CompoundChild child;
    child.shape = Shape::box(halfExtents);
    child.transform.position = position;
    return child;
}

int addBodyWith(World& world, const std::string& name, const Shape& shape, const Vec3& position,
                BodyType type = BodyType::Dynamic, const Quat& rotation = Quat::Identity()) {
    BodyDef def;
    def.name = name;
    def.type = type;
    def.shape = shape;
    def.transform.position = position;
    def.transform.rotation = rotation;
    return addBody(world, def);
}

/// Where body `index` of a pile starts: columns 1.2 m apart, `perSide` to a side, layers 1.2 m
/// apart from 4 m up, jittered and turned at random. One draw per statement: the order in which a
/// call's arguments are evaluated is unspecified, and two draws in one call differ by compiler.
Transform pileDrop(int index, int perSide, Random& random) {
    const int x = index % perSide, z = (index / perSide) % perSide, level = index / (perSide * perSide);
    const Real jitterX = random.uniformReal(Real(-0.1), Real(0.1));
    const Real jitterZ = random.uniformReal(Real(-0.1), Real(0.1));
    const Real angle = random.uniformReal(0, 2 * kPi);
    Transform drop;
    drop.position = Vec3(Real(1.2) * (Real(x) - Real(0.5) * Real(perSide - 1)) + jitterX, Real(4) + Real(1.2) * Real(level),
                         Real(1.2) * (Real(z) - Real(0.5) * Real(perSide - 1)) + jitterZ);
    drop.rotation = Quat(angleAxis(angle, Vec3(1, 2, 3).normalized()));
    return drop;
}

}  // namespace

Shape tableShape(Real width, Real depth, Real height, Real thickness, Real leg) {
    std::vector<CompoundChild> children;
    children.push_back(boxChild(Vec3(width / 2, thickness / 2, depth / 2), Vec3(0, height - thickness / 2, 0)));
    const Real legHeight = height - thickness;
    for (const Real x : {-1, 1})
        for (const Real z : {-1, 1})
            children.push_back(boxChild(Vec3(leg / 2, legHeight / 2, leg / 2),
                                        Vec3(x * (width - leg) / 2, legHeight / 2, z * (depth - leg) / 2)));
    return Shape::compoundOf(std::move(children));
}

Shape chairShape() {
    Shape seat = tableShape(Real(0.45), Real(0.45), Real(0.45), Real(0.04), Real(0.04));
    std::vector<CompoundChild> children = seat.compound->children;
    children.push_back(boxChild(Vec3(Real(0.225), Real(0.25), Real(0.02)), Vec3(0, Real(0.7), Real(-0.205))));
    return Shape::compoundOf(std::move(children));
}

Shape gridMesh(int cells, Real size, const std::function<Real(Real x, Real z)>& height) {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    for (int row = 0; row <= cells; ++row)
        for (int column = 0; column <= cells; ++column) {
            const Real x = Real(column) * size, z = Real(row) * size;
            vertices.emplace_back(x, height(x, z), z);
        }
    const auto at = [cells](int row, int column) { return row * (cells + 1) + column; };
    for (int row = 0; row < cells; ++row)
        for (int column = 0; column < cells; ++column) {
            // Counter-clockwise seen from +y: (r, c), (r + 1, c + 1), (r, c + 1) and (r, c), (r + 1, c), (r + 1, c + 1).
            triangles.push_back({at(row, column), at(row + 1, column + 1), at(row, column + 1)});
            triangles.push_back({at(row, column), at(row + 1, column), at(row + 1, column + 1)});
        }
    return Shape::triangleMesh(std::move(vertices), std::move(triangles));
}

Shape tiledFloor(int tiles, Real size) {
    return gridMesh(tiles, size, [](Real, Real) { return Real(0); });
}

Real hillsHeight(Real x, Real z, Real amplitude) {
    return amplitude * (math::sin(Real(0.21) * x) * math::cos(Real(0.17) * z) + Real(0.4) * math::sin(Real(0.53) * x + Real(0.31) * z));
}

Shape hillsMesh(int cells, Real size, Real amplitude) {
    return gridMesh(cells, size, [amplitude](Real x, Real z) { return hillsHeight(x, z, amplitude); });
}

Shape flatHeightField(int tiles, Real size) {
    return Shape::heightFieldOf(tiles + 1, tiles + 1, size,
                                std::vector<Real>(static_cast<std::size_t>((tiles + 1) * (tiles + 1)), Real(0)));
}

World buildTerrain(int cells, Real size, Real amplitude) {
    World world = emptyWorld("terrain-" + std::to_string(cells));
    std::vector<Real> heights;
    for (int row = 0; row <= cells; ++row)
        for (int column = 0; column <= cells; ++column) {
            heights.push_back(hillsHeight(Real(column) * size, Real(row) * size, amplitude));
        }
    const Real half = Real(cells) * size / 2;
    addBodyWith(world, "hills", Shape::heightFieldOf(cells + 1, cells + 1, size, std::move(heights)), Vec3(-half, 0, -half),
                BodyType::Static);
    return world;
}

World buildCylinderScene() {
    World world = emptyWorld("worlds-cylinders");
    addGroundPlane(world, Real(0.8));
    // A can lying on its side, its axis along z, set rolling along x at 2 m/s.
    const int rolling = addBodyWith(world, "rolling-can", Shape::cylinder(Real(0.3), Real(0.6)), Vec3(-4, Real(0.301), 0),
                                    BodyType::Dynamic, Quat(angleAxis(kPi / 2, Vec3::UnitX())));
    Motion& roll = world.motions[static_cast<std::size_t>(world.bodies[static_cast<std::size_t>(rolling)].motionIndex)];
    roll.linearVelocity = Vec3(2, 0, 0);
    roll.angularVelocity = Vec3(0, 0, Real(-2) / Real(0.3));  // rolling without slipping
    // Cans standing, and three stacked.
    for (int i = 0; i < 3; ++i)
        addBodyWith(world, "can" + std::to_string(i), Shape::cylinder(Real(0.25), Real(0.4)),
                    Vec3(Real(1.5) * Real(i), Real(0.41), -2));
    for (int level = 0; level < 3; ++level)
        addBodyWith(world, "stacked" + std::to_string(level), Shape::cylinder(Real(0.3), Real(0.25)),
                    Vec3(4, Real(0.26) + Real(0.51) * Real(level), -2));
    addBodyWith(world, "table", tableShape(Real(1.6), Real(0.9), Real(0.75), Real(0.05), Real(0.06)), Vec3(1, Real(0.01), 2));
    addBodyWith(world, "chair", chairShape(), Vec3(1, Real(0.01), Real(3.1)));
    return world;
}

World buildSeamScene() {
    World world = emptyWorld("worlds-seams");
    world.settings.sleeping = false;  // the boxes slide without friction; nothing should rest
    const Shape box = Shape::box(Vec3::Constant(Real(0.5)));
    const struct {
        const char* floor;
        const char* slider;
        Shape shape;
        Real z;
    } lanes[] = {{"tiles", "box-on-tiles", tiledFloor(30, 1), 0}, {"height-field", "box-on-height-field", flatHeightField(30, 1), 5}};
    for (const auto& lane : lanes) {
        BodyDef floor;
        floor.name = lane.floor;
        floor.type = BodyType::Static;
        floor.shape = lane.shape;
        floor.transform.position = Vec3(0, 0, lane.z);
        floor.material.friction = 0;
        addBody(world, floor);
        BodyDef slider;
        slider.name = lane.slider;
        slider.shape = box;
        slider.transform.position = Vec3(2, Real(0.5), lane.z + Real(2.3));  // off the tiles' diagonals
        slider.material.friction = 0;
        const int index = addBody(world, slider);
        world.motions[static_cast<std::size_t>(world.bodies[static_cast<std::size_t>(index)].motionIndex)].linearVelocity =
            Vec3(5, 0, 0);
    }
    // A ball rolling down a 15-degree ramp of 0.5 m cells: every seam it crosses is one a rolling
    // contact presses into, so without the active edges it loses a fifth of its speed.
    const Real slope = Real(15) * kPi / 180;
    const int columns = 41, rows = 5;
    std::vector<Real> heights;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) heights.push_back(Real(10) - Real(column) * Real(0.5) * math::tan(slope));
    BodyDef ramp;
    ramp.name = "ramp";
    ramp.type = BodyType::Static;
    ramp.shape = Shape::heightFieldOf(rows, columns, Real(0.5), heights);
    ramp.transform.position = Vec3(0, -10, 10);
    ramp.material.friction = 1;
    addBody(world, ramp);
    const Real radius = Real(0.25);
    BodyDef ball;
    ball.name = "ball-on-ramp";
    ball.shape = Shape::sphere(radius);
    ball.transform.position = Vec3(2, -2 * math::tan(slope), 11) + (radius + Real(0.001)) * Vec3(math::sin(slope), math::cos(slope), 0);
    ball.material.friction = 1;
    addBody(world, ball);
    return world;
}

World buildTerrainPile(int bodies, unsigned seed) {
    World world = buildTerrain(64, 1, Real(1.5));
    world.name = "terrain-pile-" + std::to_string(bodies);
    Random random(seed);
    const Shape shapes[] = {Shape::box(Vec3(Real(0.3), Real(0.3), Real(0.3))), Shape::sphere(Real(0.3)),
                            Shape::capsule(Real(0.2), Real(0.3)), Shape::cylinder(Real(0.3), Real(0.3)),
                            tableShape(Real(0.8), Real(0.6), Real(0.5), Real(0.05), Real(0.05))};
    const int perSide = std::max(1, static_cast<int>(std::ceil(math::cbrt(static_cast<double>(bodies)))));
    for (int i = 0; i < bodies; ++i) {
        const Transform drop = pileDrop(i, perSide, random);
        addBodyWith(world, "body" + std::to_string(i), shapes[i % 5], drop.position, BodyType::Dynamic, drop.rotation);
    }
    return world;
}

Shape meshPileShape(int index) {
    if (index % 40 == 39) return tableShape(Real(0.8), Real(0.6), Real(0.5), Real(0.05), Real(0.05));
    switch (index % 4) {
        case 0: return Shape::box(Vec3(Real(0.3), Real(0.3), Real(0.3)));
        case 1: return Shape::sphere(Real(0.3));
        case 2: return Shape::capsule(Real(0.2), Real(0.3));
        default: return Shape::cylinder(Real(0.3), Real(0.3));
    }
}

World buildMeshTerrainPile(int cells, int bodies, unsigned seed) {
    World world = emptyWorld("mesh-terrain-pile-" + std::to_string(bodies));
    const Real half = Real(cells) / 2;
    addBodyWith(world, "hills", hillsMesh(cells, 1, Real(1.5)), Vec3(-half, 0, -half), BodyType::Static);
    Random random(seed);
    const int perSide = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(bodies) / 10))));
    for (int i = 0; i < bodies; ++i) {
        const Transform drop = pileDrop(i, perSide, random);
        const int body = addBodyWith(world, "body" + std::to_string(i), meshPileShape(i), drop.position, BodyType::Dynamic, drop.rotation);
        // Balls and capsules roll for ever on rigid hills without it (chapter 10's piles do the same).
        if (isRound(world.bodies[std::size_t(body)].shape))
            world.bodies[std::size_t(body)].material.rollingResistance = kPileRollingResistance;
    }
    return world;
}

void addChapter13Scenes(Registry& registry) {
    const char* category = "13 worlds to stand on";
    registry.addScene({"worlds-cylinders", 13, category, prose(R"(
        the cans stand on their faces and the stack of three holds; the can on its side rolls
        straight on; the table and the chair (compounds of boxes) stand on their legs)"),
                       [] { return buildCylinderScene(); }, {}});
    registry.addScene({"worlds-seams", 13, category, prose(R"(
        two frictionless boxes slide at 5 m/s over 1 m tiles of a mesh and a height field, and a ball
        rolls down a 15-degree ramp: none bumps at a seam; untick "active edges" and the ball rolls a
        quarter slower, braked at every seam)"),
                       [] { return buildSeamScene(); }, {}});
    registry.addScene({"worlds-terrain", 13, category, prose(R"(
        200 boxes, balls, capsules, cans and tables fall onto a height field of rolling hills and
        come to rest in its hollows; none sinks into the ground)"),
                       [] { return buildTerrainPile(200); }, {}});
    registry.addScene({"worlds-mesh-terrain", 13, category, prose(R"(
        200 bodies of the same mix fall onto the hills as a triangle mesh of 3,200 triangles; switch on
        the mesh-tree view and step its level: each level down halves the triangles a box holds, and
        a falling body's box meets only the few leaves under it)"),
                       [] {
                           World world = buildMeshTerrainPile(40, 200);
                           world.name = "worlds-mesh-terrain";
                           return world;
                       }, {}});
}

}  // namespace stepwise
