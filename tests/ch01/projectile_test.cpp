// A projectile under constant gravity: x(t) = x0 + v0 t + g t^2 / 2. Verlet and RK4 are exact
// for constant acceleration (up to round-off); semi-implicit Euler, which moves with the new
// velocity, ends exactly g h t / 2 ahead of the parabola in the direction of g.
#include "01_integrators/chapter.h"
#include "01_integrators/integrate.h"
#include "01_integrators/scenes.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

using namespace stepwise;
using namespace stepwise::test;

namespace {

struct Flight {
    Vec3 position;
    Vec3 velocity;
};

Flight fly(IntegratorKind method, Real dt, double seconds) {
    Settings settings;
    settings.dt = dt;
    settings.integrator = method;
    World world = makeWorld(settings);
    const int ball = addSphere(world, Vec3(1, 2, -3), Real(0.2));
    setVelocity(world, ball, Vec3(4, 12, 1), Vec3(0, 0, 0));
    Pipeline pipeline = makeChapter01Pipeline(world);
    simulate(world, pipeline, seconds);
    return {world.bodies[ball].transform.position, world.motionOf(ball)->linearVelocity};
}

Vec3 exactPosition(double t, const Vec3& gravity) {
    return Vec3(1, 2, -3) + Vec3(4, 12, 1) * Real(t) + Real(0.5 * t * t) * gravity;
}

}  // namespace

TEST_CASE("Verlet and RK4 follow the projectile's closed form", "[ch01][projectile]") {
    const Settings defaults;
    const double t = 2.0;
    for (IntegratorKind method : {IntegratorKind::Verlet, IntegratorKind::Rk4}) {
        const Flight flight = fly(method, Real(1.0 / 60.0), t);
        INFO(toString(method) << " position " << flight.position.transpose());
        CHECK((flight.position - exactPosition(t, defaults.gravity)).norm() < 1e-3);
        CHECK((flight.velocity - (Vec3(4, 12, 1) + Real(t) * defaults.gravity)).norm() < 1e-3);
    }
}

TEST_CASE("semi-implicit Euler's projectile is off the parabola by exactly g h t / 2", "[ch01][projectile]") {
    const Settings defaults;
    const double t = 2.0;
    for (Real dt : {Real(1.0 / 30.0), Real(1.0 / 60.0), Real(1.0 / 240.0)}) {
        const Flight flight = fly(IntegratorKind::SemiImplicitEuler, dt, t);
        // After n steps: x_n = x0 + v0 t + g h^2 n (n + 1) / 2 = exact + g h t / 2.
        const Vec3 expectedOffset = Real(0.5 * t) * dt * defaults.gravity;
        const Vec3 offset = flight.position - exactPosition(t, defaults.gravity);
        INFO("dt " << dt << " offset " << offset.transpose());
        CHECK((offset - expectedOffset).norm() < 1e-3);
        // The velocity is exact: a constant acceleration is integrated exactly by v += h g.
        CHECK((flight.velocity - (Vec3(4, 12, 1) + Real(t) * defaults.gravity)).norm() < 1e-3);
    }
}

TEST_CASE("the projectile scene shows Euler below the parabola and the others on it", "[ch01][projectile][scene]") {
    World world = buildProjectile();
    Pipeline pipeline = makeChapter01Pipeline(world);
    REQUIRE(pipeline.stages().size() == 1);
    CHECK(pipeline.stages()[0].name == "integrate:mixed");
    const World launch = world;
    const double t = 1.5;
    simulate(world, pipeline, t);
    const Real h = world.settings.dt;
    for (const Motion& motion : world.motions) {
        const Body& body = world.bodies[motion.bodyIndex];
        const double launchHeight = launch.bodies[motion.bodyIndex].transform.position.y();
        const double launchSpeedUp = launch.motionOf(motion.bodyIndex)->linearVelocity.y();
        REQUIRE(launchSpeedUp > 0);
        const double exactHeight = launchHeight + launchSpeedUp * t + 0.5 * world.settings.gravity.y() * t * t;
        const double below = exactHeight - body.transform.position.y();
        INFO(body.name << " below the parabola by " << below);
        if (integratorOf(world, motion) == IntegratorKind::SemiImplicitEuler)
            CHECK(below == Approx(-0.5 * world.settings.gravity.y() * h * t).epsilon(1e-3));
        else
            CHECK(std::abs(below) < 1e-3);
    }
}
