// The Bullet peer (bench/peers/bullet_peer.h): Bullet is given the engine's world faithfully
// (closed-form fall, masses, inertias, joint signs, scene files) and refuses what it cannot map.
#include "06_manifolds/scenes.h"
#include "peers/bullet_peer.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

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
