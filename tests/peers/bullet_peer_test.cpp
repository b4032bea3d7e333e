// The Bullet peer (bench/peers/bullet_peer.h): Bullet is given the engine's world faithfully
// (closed-form fall, masses, inertias, joint signs, scene files; chapter 13's meshes, height
// fields and compounds) and refuses what it cannot map.
#include "06_manifolds/scenes.h"
#include "13_worlds/scenes.h"
#include "peers/bullet_peer.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace stepwise;
using namespace stepwise::peers;

namespace {

World emptyWorld(const Vec3& gravity = Vec3(0, Real(-9.81), 0)) {
    World world;
    world.name = "peer-test";
    world.settings.gravity = gravity;
    return world;
}

int addDynamic(World& world, const std::string& name, const Shape& shape, const Vec3& position, Real mass,
               const Quat& rotation = Quat::Identity()) {
    BodyDef def;
    def.name = name;
    def.shape = shape;
    def.transform.position = position;
    def.transform.rotation = rotation;
    def.mass = mass;
    return addBody(world, def);
}

int addStatic(World& world, const std::string& name, const Shape& shape, const Vec3& position) {
    BodyDef def;
    def.name = name;
    def.type = BodyType::Static;
    def.shape = shape;
    def.transform.position = position;
    return addBody(world, def);
}

/// B's turn about the unit `axis` relative to A (both start unrotated), right-handed, rad.
Real turnAbout(const Quat& a, const Quat& b, const Vec3& axis) {
    const Quat relative = (a.conjugate() * b).normalized();
    return Real(2) * std::atan2(relative.vec().dot(axis), relative.w());
}

}  // namespace

TEST_CASE("a sphere dropped from rest falls as semi-implicit Euler's closed form", "[peers]") {
    World world = emptyWorld();
    const Real y0 = 10;
    addDynamic(world, "ball", Shape::sphere(Real(0.5)), Vec3(0, y0, 0), 1);
    const long frames = 60;
    const BulletRun run = runBullet(world, frames);
    // Symplectic Euler, v_k = -g k h and y_n = y0 - sum v_k h = y0 - g h^2 n (n + 1) / 2: Bullet's
    // integrator exactly. The continuous y0 - g t^2 / 2 differs by g h t / 2 = 8 cm here.
    const double g = 9.81, h = double(world.settings.dt), n = double(frames);
    const double discrete = double(y0) - g * h * h * n * (n + 1) / 2;
    CHECK(double(run.finalPoses[0].position.y()) == Approx(discrete).margin(1e-4));
    CHECK(double(run.finalLinearVelocities[0].y()) == Approx(-g * h * n).margin(1e-4));
    CHECK(std::abs(double(run.finalPoses[0].position.y()) - (double(y0) - g * (h * n) * (h * n) / 2)) > 0.05);
}

TEST_CASE("a box resting on the ground stays put for two seconds", "[peers]") {
    World world = emptyWorld();
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20));
    addDynamic(world, "box", Shape::box(Vec3::Constant(Real(0.5))), Vec3(0, Real(0.5), 0), 1);
    const BulletRun run = runBullet(world, 120);
    CHECK((run.finalPoses[1].position - Vec3(0, Real(0.5), 0)).norm() < Real(0.001));
    CHECK(run.finalPoses[0].position == Vec3(0, Real(-0.5), 0));
}

TEST_CASE("Bullet gets the engine's masses and inertias, principal frames included", "[peers]") {
    World world = emptyWorld();
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20));
    const int box = addDynamic(world, "box", Shape::box(Vec3(Real(0.5), Real(0.25), 1)), Vec3(0, 2, 0), 3);
    const int capsule = addDynamic(world, "capsule", Shape::capsule(Real(0.2), Real(0.5)), Vec3(3, 2, 0), 2);
    // A lopsided hull: its centre of mass is off its origin and its inertia is not diagonal.
    const Shape wedge = Shape::convex({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, Real(0.5)),
                                       Vec3(Real(0.3), Real(0.8), Real(0.4))});
    const int hull = addDynamic(world, "wedge", wedge, Vec3(-3, 2, 0), 5,
                                Quat(Eigen::AngleAxis<Real>(Real(0.4), Vec3(1, 1, 0).normalized())));
    REQUIRE(!world.motionOf(hull)->localCenter.isZero(Real(1e-3)));
    const Mat3& hullInertia = world.motionOf(hull)->inertiaLocal;
    REQUIRE(std::abs(hullInertia(0, 1)) > Real(1e-3) * hullInertia.trace());

    const BulletRun run = runBullet(world, 0);
    for (int body : {box, capsule, hull}) {
        const Motion& motion = *world.motionOf(body);
        const BulletMass& given = run.masses[std::size_t(body)];
        CHECK(given.mass == Approx(motion.mass).epsilon(1e-6));
        CHECK((given.localCenter - motion.localCenter).norm() < Real(1e-6));
        const Mat3 difference = given.inertiaInShapeAxes() - motion.inertiaLocal;
        CHECK(difference.norm() < Real(1e-4) * motion.inertiaLocal.norm());
        // No step taken: the pose read back through the principal frame is the one given.
        CHECK((run.finalPoses[std::size_t(body)].position - world.bodies[std::size_t(body)].transform.position).norm() < Real(1e-5));
        CHECK(run.finalPoses[std::size_t(body)].rotation.angularDistance(world.bodies[std::size_t(body)].transform.rotation) < Real(1e-5));
    }
    CHECK(run.masses[0].mass == 0);
}

TEST_CASE("the hull's centre of mass is where Bullet's body frame is: a turned-over wedge falls flat", "[peers]") {
    // A wedge dropped onto the ground comes to rest on a face, its pose close to still after 3 s
    // (a wrong centre of mass would rock it or stand it on an edge).
    World world = emptyWorld();
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20));
    const int hull = addDynamic(world, "wedge",
                                Shape::convex({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, Real(0.5)),
                                               Vec3(2, 0, Real(0.5)), Vec3(0, 1, Real(0.5))}),
                                Vec3(0, Real(0.5), 0), 5);
    const BulletRun run = runBullet(world, 180);
    CHECK(run.finalLinearVelocities[std::size_t(hull)].norm() < Real(0.01));
    CHECK(run.finalAngularVelocities[std::size_t(hull)].norm() < Real(0.01));
    const Aabb bounds = computeAabb(world.bodies[std::size_t(hull)].shape, run.finalPoses[std::size_t(hull)]);
    CHECK(std::abs(double(bounds.min.y())) < 0.01);  // resting on the ground, not in it
}

TEST_CASE("hinge and slider limits and motors turn the engine's way", "[peers]") {
    World world = emptyWorld(Vec3::Zero());
    const int post = addStaticBox(world, "post", Vec3::Zero(), Vec3::Constant(Real(0.1)));
    const int door = addDynamic(world, "door", Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.05))), Vec3(1, 0, 0), 1);
    const int cart = addDynamic(world, "cart", Shape::box(Vec3::Constant(Real(0.1))), Vec3(0, 0, 2), 1);
    JointDesc hinge;
    hinge.type = JointType::Hinge;
    hinge.bodyA = post;
    hinge.bodyB = door;
    hinge.localAnchorA = Vec3(Real(0.5), 0, 0);
    hinge.localAnchorB = Vec3(Real(-0.5), 0, 0);
    hinge.axis = Vec3::UnitY();
    hinge.limits = std::make_pair(Real(-1), Real(0.5));
    hinge.motor = JointMotor{1, 100};
    world.joints.push_back(hinge);
    JointDesc slider;
    slider.type = JointType::Slider;
    slider.bodyA = post;
    slider.bodyB = cart;
    slider.localAnchorA = Vec3(0, 0, 2);
    slider.axis = Vec3::UnitX();
    slider.limits = std::make_pair(Real(-1), Real(0.3));
    slider.motor = JointMotor{Real(0.5), 100};
    world.joints.push_back(slider);

    const BulletRun run = runBullet(world, 120);
    CHECK(double(turnAbout(Quat::Identity(), run.finalPoses[std::size_t(door)].rotation, Vec3::UnitY())) ==
          Approx(0.5).margin(0.05));
    CHECK(double(run.finalPoses[std::size_t(cart)].position.x()) == Approx(0.3).margin(0.02));
    CHECK(double(run.finalPoses[std::size_t(cart)].position.z()) == Approx(2).margin(0.01));
}

TEST_CASE("the repository's scene files run, or are refused naming what Bullet lacks", "[peers]") {
    const World ballOnBox = loadSceneFile("scenes/ball-on-box.json");
    const BulletRun run = runBullet(ballOnBox, 300);
    const int box = ballOnBox.findBody("box"), ball = ballOnBox.findBody("ball");
    CHECK(double(run.finalPoses[std::size_t(box)].position.y()) == Approx(0.5).margin(0.01));
    CHECK(double(run.finalPoses[std::size_t(ball)].position.y()) == Approx(1.25).margin(0.01));
    CHECK(run.substeps == 8);  // the scene's own settings

    // two-box-stack ties a ball to a box with a distance joint, which Bullet has no constraint for.
    const World stack = loadSceneFile("scenes/two-box-stack.json");
    CHECK_THROWS_WITH(runBullet(stack, 10),
                      Catch::Contains("joints[0] (distance, \"b0\" - \"ball\")") && Catch::Contains("unsupported"));
}

TEST_CASE("an unsupported setting is refused by name before any step", "[peers]") {
    World world = emptyWorld();
    addDynamic(world, "ball", Shape::sphere(1), Vec3::Zero(), 1);
    world.settings.integrator = IntegratorKind::Rk4;
    CHECK_THROWS_AS(runBullet(world, 1), BulletUnsupported);
    CHECK_THROWS_WITH(runBullet(world, 1), Catch::Contains("settings.integrator (rk4): unsupported"));
    world.settings.integrator = IntegratorKind::SemiImplicitEuler;
    world.motions[0].integrator = IntegratorKind::Verlet;
    CHECK_THROWS_WITH(runBullet(world, 1), Catch::Contains("bodies[0] (\"ball\").integrator"));
}

TEST_CASE("a pyramid of 10 rows stands in Bullet and every frame is timed", "[peers]") {
    const World pyramid = buildPyramid(10);
    REQUIRE(pyramid.dynamicBodyCount() == 55);
    long callbacks = 0;
    const BulletRun run = runBullet(pyramid, 120, BulletOptions{}, [&](long, const std::vector<Transform>& poses) {
        ++callbacks;
        CHECK(poses.size() == pyramid.bodies.size());
    });
    CHECK(callbacks == 120);
    REQUIRE(run.stepMs.size() == 120);
    CHECK(std::all_of(run.stepMs.begin(), run.stepMs.end(), [](double ms) { return ms > 0 && std::isfinite(ms); }));
    const std::size_t top = pyramid.bodies.size() - 1;
    CHECK((run.finalPoses[top].position - pyramid.bodies[top].transform.position).norm() < Real(0.05));
    const World after = worldAfterRun(pyramid, run);
    CHECK(computeEnergy(after).kinetic < 0.1);
}

TEST_CASE("a box comes to rest at the same height on a mesh floor and on a height field as on a box floor", "[peers][worlds]") {
    // The floors' tops at y = 0: a box, 10 x 10 tiles of two triangles, a flat 10 x 10-cell height
    // field. The box lands across a seam (x = 0, z = 0.3 in a tile), where a wrong normal would tip it.
    const auto restingHeight = [](const Shape& floor, const Vec3& floorPosition) {
        World world = emptyWorld();
        addStatic(world, "floor", floor, floorPosition);
        addDynamic(world, "box", Shape::box(Vec3(Real(0.5), Real(0.25), Real(0.5))), Vec3(0, Real(0.35), Real(0.3)), 2);
        const BulletRun run = runBullet(world, 120);
        CHECK(run.finalAngularVelocities[1].norm() < Real(0.01));
        return double(run.finalPoses[1].position.y());
    };
    const double onBox = restingHeight(Shape::box(Vec3(10, 1, 10)), Vec3(0, -1, 0));
    const double onMesh = restingHeight(tiledFloor(10, 1), Vec3(-5, 0, -5));
    const double onField = restingHeight(flatHeightField(10, 1), Vec3(-5, 0, -5));
    INFO("box floor " << onBox << " m, mesh " << onMesh << " m, height field " << onField << " m");
    CHECK(onBox == Approx(0.25).margin(0.005));  // Bullet's resting penetration: a few millimetres at most
    // Bullet's margins differ by shape pair (a box's 4 cm lies inside it, a triangle has none):
    // the same height to a millimetre, far within them.
    CHECK(onMesh == Approx(onBox).margin(0.001));
    CHECK(onField == Approx(onBox).margin(0.001));
}

TEST_CASE("a height field's cells are split along the engine's diagonal in Bullet, with or without holes", "[peers][worlds]") {
    // 3 x 3 cells, all at height 0 but the middle cell's corners off its split diagonal, raised to
    // 0.5: along the engine's diagonal, (r, c) to (r + 1, c + 1), the middle cell is a V-shaped
    // valley of two planes at 35 degrees whose floor stays at 0. A ball set down in it comes to
    // rest on both planes, its centre sqrt(1.5) r above the floor. Split the other way, the cell
    // would be a ridge 0.5 m high instead.
    const bool holes = GENERATE(false, true);  // a hole in a far corner: the peer's mesh form
    std::vector<Real> heights(16, Real(0));
    heights[1 * 4 + 2] = heights[2 * 4 + 1] = Real(0.5);
    if (holes) heights[0] = std::numeric_limits<Real>::quiet_NaN();
    World world = emptyWorld();
    addStatic(world, "field", Shape::heightFieldOf(4, 4, 1, heights), Vec3(-1, 0, -1));
    const Real radius = Real(0.2);
    addDynamic(world, "ball", Shape::sphere(radius), Vec3(Real(0.5), Real(0.4), Real(0.5)), 1);
    const BulletRun run = runBullet(world, 180);
    INFO((holes ? "mesh form" : "btHeightfieldTerrainShape") << ": ball at " << run.finalPoses[1].position.transpose());
    CHECK(double(run.finalPoses[1].position.y()) == Approx(std::sqrt(1.5) * double(radius)).margin(0.003));
    // The valley runs along x = z: the ball stays on it.
    CHECK(std::abs(double(run.finalPoses[1].position.x() - run.finalPoses[1].position.z())) < 0.003);
    CHECK(run.finalLinearVelocities[1].norm() < Real(0.01));
}

TEST_CASE("a hole in a height field lets a ball fall through, the cells around it hold one", "[peers][worlds]") {
    // 4 x 4 cells of 1 m; the middle grid point is a hole, so the four cells around it are: a
    // 2 m square opening.
    std::vector<Real> heights(25, Real(0));
    heights[2 * 5 + 2] = std::numeric_limits<Real>::quiet_NaN();
    World world = emptyWorld();
    addStatic(world, "ground", Shape::heightFieldOf(5, 5, 1, heights), Vec3(-2, 0, -2));
    const int over = addDynamic(world, "over-hole", Shape::sphere(Real(0.3)), Vec3(0, 1, 0), 1);
    const int beside = addDynamic(world, "beside", Shape::sphere(Real(0.3)), Vec3(Real(-1.7), 1, Real(1.7)), 1);
    const BulletRun run = runBullet(world, 60);
    CHECK(run.finalPoses[std::size_t(over)].position.y() < Real(-3));
    CHECK(double(run.finalPoses[std::size_t(beside)].position.y()) == Approx(0.3).margin(0.005));

    // A field whose every cell has a hole leaves Bullet nothing to collide: refused by name.
    World empty = emptyWorld();
    std::vector<Real> ring(9, Real(0));
    ring[4] = std::numeric_limits<Real>::quiet_NaN();
    addStatic(empty, "ground", Shape::heightFieldOf(3, 3, 1, ring), Vec3::Zero());
    CHECK_THROWS_AS(runBullet(empty, 1), BulletUnsupported);
    CHECK_THROWS_WITH(runBullet(empty, 1), Catch::Contains("bodies[0] (\"ground\").shape (heightfield): every cell has a hole"));
}

TEST_CASE("a compound's mass and inertia in Bullet are the engine's, and a table stands on its legs", "[peers][worlds]") {
    World world = emptyWorld();
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20));
    const Quat turn(Eigen::AngleAxis<Real>(Real(0.3), Vec3::UnitY()));
    const int table = addDynamic(world, "table", tableShape(Real(1.2), Real(0.8), Real(0.75), Real(0.05), Real(0.06)),
                                 Vec3(0, Real(0.001), 0), 12, turn);
    // A chair's back puts its centre of mass behind and above the seat's middle, off its origin.
    const int chair = addDynamic(world, "chair", chairShape(), Vec3(2, Real(0.001), 0), 5);
    REQUIRE(!world.motionOf(chair)->localCenter.isZero(Real(1e-3)));

    const BulletRun still = runBullet(world, 0);
    for (int body : {table, chair}) {
        const Motion& motion = *world.motionOf(body);
        const BulletMass& given = still.masses[std::size_t(body)];
        CHECK(given.mass == Approx(motion.mass).epsilon(1e-6));
        CHECK((given.localCenter - motion.localCenter).norm() < Real(1e-6));
        CHECK((given.inertiaInShapeAxes() - motion.inertiaLocal).norm() < Real(1e-4) * motion.inertiaLocal.norm());
        const Vec3 placed = world.bodies[std::size_t(body)].transform.position;
        CHECK((still.finalPoses[std::size_t(body)].position - placed).norm() < Real(1e-5));
    }

    // Two seconds later both stand where they were put, on their legs (the children where the
    // engine has them: a leg out of place would tilt them).
    const BulletRun run = runBullet(world, 120);
    for (int body : {table, chair}) {
        const Transform& pose = run.finalPoses[std::size_t(body)];
        INFO(world.bodies[std::size_t(body)].name << " at " << pose.position.transpose());
        CHECK((pose.position - world.bodies[std::size_t(body)].transform.position).norm() < Real(0.01));
        CHECK(pose.rotation.angularDistance(world.bodies[std::size_t(body)].transform.rotation) < Real(0.01));
        CHECK(std::abs(double(computeAabb(world.bodies[std::size_t(body)].shape, pose).min.y())) < 0.005);
    }
}

TEST_CASE("with Bullet's internal-edge correction a box slides over the seams of triangles at its speed", "[peers][worlds]") {
    // The engine's seam test (tests/ch13/worlds_test.cpp) in Bullet: a frictionless 1 m box at
    // 5 m/s over 20 m of 1 m tiles, as a mesh and as a height field. Without btInternalEdgeUtility
    // the triangles' edges catch the box's corners and most of its speed is lost.
    const bool field = GENERATE(false, true);
    World world = emptyWorld();
    BodyDef floor;
    floor.name = "floor";
    floor.type = BodyType::Static;
    floor.shape = field ? flatHeightField(30, 1) : tiledFloor(30, 1);
    floor.material.friction = 0;
    addBody(world, floor);
    BodyDef box;
    box.name = "box";
    box.shape = Shape::box(Vec3::Constant(Real(0.5)));
    box.transform.position = Vec3(2, Real(0.5), Real(15.3));
    box.linearVelocity = Vec3(5, 0, 0);
    box.material.friction = 0;
    addBody(world, box);
    BulletOptions corrected, uncorrected;
    uncorrected.internalEdges = false;
    const BulletRun on = runBullet(world, 240, corrected), off = runBullet(world, 240, uncorrected);
    INFO((field ? "height field" : "mesh") << ": " << on.finalLinearVelocities[1].x() << " m/s corrected, "
                                           << off.finalLinearVelocities[1].x() << " m/s not");
    CHECK(double(on.finalLinearVelocities[1].x()) == Approx(5).margin(0.025));
    CHECK(on.finalPoses[1].position.x() > Real(21.5));
    CHECK(off.finalLinearVelocities[1].x() < Real(4));
}
