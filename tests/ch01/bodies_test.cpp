// Body types, per-body integrators, the split (velocities | positions) step, off-centre mass
// and the force generators.
#include "01_integrators/chapter.h"
#include "01_integrators/forces.h"
#include "01_integrators/integrate.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

#include <limits>

using namespace stepwise;
using namespace stepwise::test;

TEST_CASE("a static body never moves, whatever pulls on it", "[ch01][bodies]") {
    World world = makeWorld();
    const int ground = addGround(world);
    const int ball = addSphere(world, Vec3(0, 3, 0), Real(0.25));
    world.springs.push_back(Spring{ball, ground, Vec3::Zero(), Vec3(0, 0.5, 0), 1, 500, 2});
    world.dampings.push_back(Damping{-1, 1, 1});
    REQUIRE(world.motionOf(ground) == nullptr);
    const Transform before = world.bodies[ground].transform;
    Pipeline pipeline = makeChapter01Pipeline(world);
    simulate(world, pipeline, 3.0);
    CHECK(world.bodies[ground].transform.position == before.position);
    CHECK(world.bodies[ground].transform.rotation.coeffs() == before.rotation.coeffs());
    // The spring still acts on the ball: it hangs near the ground's anchor instead of falling away.
    CHECK(world.bodies[ball].transform.position.y() > -2);
}

TEST_CASE("a kinematic body moves by its set velocities only", "[ch01][bodies]") {
    for (IntegratorKind method : {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Rk4}) {
        Settings settings;
        settings.integrator = method;
        World world = makeWorld(settings);
        const Vec3 start(1, 2, 3), velocity(Real(0.5), Real(-1.0), 2), spin(0, 0, Real(1.5));
        const int platform = addBox(world, start, Vec3(1, Real(0.1), 1), BodyType::Kinematic);
        const int ball = addSphere(world, Vec3(1, 4, 3), Real(0.2));
        setVelocity(world, platform, velocity, spin);
        // Gravity, a spring to a dynamic ball, drag and a user force: none of them may move it.
        world.springs.push_back(Spring{ball, platform, Vec3::Zero(), Vec3::Zero(), 1, 1000, 5});
        world.dampings.push_back(Damping{-1, 2, 2});
        world.motionOf(platform)->force = Vec3(100, 100, 100);
        Pipeline pipeline = makeChapter01Pipeline(world);
        const double seconds = 2.0;
        simulate(world, pipeline, seconds);
        INFO(toString(method));
        const Motion& motion = *world.motionOf(platform);
        CHECK(motion.linearVelocity == velocity);
        CHECK(motion.angularVelocity == spin);
        CHECK((world.bodies[platform].transform.position - (start + Real(seconds) * velocity)).norm() < 1e-4);
        const Quat expected(Eigen::AngleAxis<Real>(Real(1.5 * seconds), Vec3::UnitZ()));
        CHECK(expected.angularDistance(world.bodies[platform].transform.rotation) < 1e-4);
    }
}

TEST_CASE("bodies can override the world's integrator, and the stage name says so", "[ch01][bodies][pipeline]") {
    World world = makeWorld();
    CHECK(makeChapter01Pipeline(world).stages().at(0).name == "integrate:semi_implicit_euler");
    const int a = addSphere(world, Vec3(0, 0, 0), Real(0.1));
    const int b = addSphere(world, Vec3(2, 0, 0), Real(0.1));
    CHECK(makeChapter01Pipeline(world).stages().at(0).name == "integrate:semi_implicit_euler");
    world.motionOf(a)->integrator = IntegratorKind::Rk4;
    CHECK(makeChapter01Pipeline(world).stages().at(0).name == "integrate:mixed");
    world.motionOf(b)->integrator = IntegratorKind::Rk4;
    CHECK(makeChapter01Pipeline(world).stages().at(0).name == "integrate:rk4");
    world.settings.integrator = IntegratorKind::Verlet;
    world.motionOf(a)->integrator.reset();
    world.motionOf(b)->integrator.reset();
    CHECK(makeChapter01Pipeline(world).stages().at(0).name == "integrate:verlet");

    // The override decides the result: an RK4 ball matches a world that runs RK4 for all.
    World mixed = makeWorld(zeroGravitySettings());
    World allRk4 = makeWorld(zeroGravitySettings());
    allRk4.settings.integrator = IntegratorKind::Rk4;
    for (World* w : {&mixed, &allRk4}) {
        const int ball = addSphere(*w, Vec3(1, 0, 0), Real(0.1));
        w->springs.push_back(Spring{ball, -1, Vec3::Zero(), Vec3::Zero(), 0, 50, 0});
    }
    mixed.motions[0].integrator = IntegratorKind::Rk4;
    for (int i = 0; i < 100; ++i) {
        integrate(mixed, Real(0.02));
        integrate(allRk4, Real(0.02));
    }
    CHECK(mixed.bodies[0].transform.position == allRk4.bodies[0].transform.position);
}

TEST_CASE("applyForces + integrateVelocities + integratePositions is one semi-implicit Euler step",
          "[ch01][bodies]") {
    World world = makeWorld();
    const int a = addBox(world, Vec3(0, 2, 0), Vec3(Real(0.3), Real(0.2), Real(0.1)));
    const int b = addSphere(world, Vec3(1, 1, 0), Real(0.2));
    setVelocity(world, a, Vec3(1, 0, 0), Vec3(1, 2, 3));
    world.springs.push_back(Spring{a, b, Vec3(Real(0.3), 0, 0), Vec3::Zero(), Real(0.5), 100, 1});
    world.springs.push_back(Spring{b, -1, Vec3::Zero(), Vec3(1, 3, 0), 1, 80, 0});
    world.dampings.push_back(Damping{a, Real(0.3), Real(0.2)});
    World split = world;
    for (int i = 0; i < 50; ++i) {
        integrate(world, Real(0.01));
        applyForces(split);
        integrateVelocities(split, Real(0.01));
        integratePositions(split, Real(0.01));
    }
    for (int body : {a, b}) {
        CHECK((world.bodies[body].transform.position - split.bodies[body].transform.position).norm() < 1e-5);
        CHECK((world.motionOf(body)->angularVelocity - split.motionOf(body)->angularVelocity).norm() < 1e-4);
    }
    // The step consumed the accumulated forces.
    CHECK(split.motionOf(a)->force == Vec3::Zero());
    CHECK(world.motionOf(a)->torque == Vec3::Zero());
}

TEST_CASE("a user force in Motion::force is applied once and then cleared", "[ch01][bodies]") {
    for (IntegratorKind method : {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Rk4}) {
        Settings settings = zeroGravitySettings();
        settings.integrator = method;
        World world = makeWorld(settings);
        const int ball = addSphere(world, Vec3::Zero(), Real(0.1), BodyType::Dynamic, 2);
        world.motionOf(ball)->force = Vec3(10, 0, 0);
        integrate(world, Real(0.1));
        integrate(world, Real(0.1));
        INFO(toString(method));
        CHECK(world.motionOf(ball)->linearVelocity.x() == Approx(0.5));   // F h / m, once
    }
}

TEST_CASE("the centre of mass is integrated and the shape origin recovered from it", "[ch01][bodies]") {
    // A hull whose centre of mass is far from the body origin, spinning freely.
    World world = makeWorld(zeroGravitySettings());
    BodyDef def;
    def.shape = Shape::convex({Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(1, 0, 1), Vec3(2, 1, 1)});
    def.angularVelocity = Vec3(Real(0.3), 2, Real(-1.0));
    const int body = addBody(world, def);
    const Motion& motion = *world.motionOf(body);
    REQUIRE(motion.localCenter.norm() > 1);
    const Vec3 center = worldCenterOfMass(world, body);
    const Vec3 origin = world.bodies[body].transform.position;
    Pipeline pipeline = makeChapter01Pipeline(world);
    simulate(world, pipeline, 2.0);
    CHECK((worldCenterOfMass(world, body) - center).norm() < 1e-4);
    CHECK((world.bodies[body].transform.position - origin).norm() > 0.1);  // the origin swings around it
}

TEST_CASE("drag decays velocities at its rate and springs pull with Hooke's law", "[ch01][bodies][forces]") {
    World world = makeWorld(zeroGravitySettings());
    const int ball = addSphere(world, Vec3(0, 0, 0), Real(0.1), BodyType::Dynamic, 3);
    const int box = addBox(world, Vec3(5, 0, 0), Vec3(1, 1, 1), BodyType::Dynamic, Quat::Identity(), 2);
    world.dampings.push_back(Damping{ball, Real(0.5), 0});
    world.springs.push_back(Spring{box, -1, Vec3(1, 0, 0), Vec3(7, 0, 1), 1, 40, 0});
    setVelocity(world, ball, Vec3(2, 0, 0));
    applyForces(world);
    CHECK((world.motionOf(ball)->force - Vec3(-0.5 * 3 * 2, 0, 0)).norm() < 1e-5);
    // Anchor at (6, 0, 0), pulled towards (7, 0, 1): stretch sqrt(2) - 1 along (1, 0, 1)/sqrt(2).
    const Vec3 expected = Real(40 * (std::sqrt(2.0) - 1)) * Vec3(1, 0, 1).normalized();
    CHECK((world.motionOf(box)->force - expected).norm() < 1e-4);
    CHECK((world.motionOf(box)->torque - Vec3(1, 0, 0).cross(expected)).norm() < 1e-4);

    // Over time, drag alone gives v(t) = v0 exp(-b t), to first order in h for Euler.
    World decay = makeWorld(zeroGravitySettings());
    const int puck = addSphere(decay, Vec3::Zero(), Real(0.1));
    setVelocity(decay, puck, Vec3(4, 0, 0));
    decay.dampings.push_back(Damping{-1, 1, 0});
    for (int i = 0; i < 1000; ++i) integrate(decay, Real(0.001));
    CHECK(decay.motionOf(puck)->linearVelocity.x() == Approx(4 * std::exp(-1.0)).epsilon(2e-3));
}

TEST_CASE("degenerate steps and springs give defined results", "[ch01][bodies]") {
    World world = makeWorld();
    const int ball = addSphere(world, Vec3(0, 1, 0), Real(0.1));
    const Transform before = world.bodies[ball].transform;
    integrate(world, 0);
    integrate(world, -1);
    integrate(world, std::numeric_limits<Real>::quiet_NaN());
    integrate(world, std::numeric_limits<Real>::infinity());
    CHECK(world.bodies[ball].transform.position == before.position);

    // A spring whose ends coincide has no direction; the step stays finite.
    world.springs.push_back(Spring{ball, -1, Vec3::Zero(), Vec3(0, 1, 0), 1, 100, 3});
    world.springs.push_back(Spring{ball, 99, Vec3::Zero(), Vec3::Zero(), 1, 100, 3});  // bad index: ignored
    for (IntegratorKind method : {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Rk4}) {
        world.settings.integrator = method;
        integrate(world, Real(0.01));
        CHECK(world.bodies[ball].transform.position.allFinite());
        CHECK(world.motionOf(ball)->linearVelocity.allFinite());
    }
}
