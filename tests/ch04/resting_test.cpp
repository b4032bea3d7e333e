// Resting contact: bodies settle at the slop and stay; a heavy ball on a light one barely sinks;
// and why the pipeline splits integration around the solve.
#include "04_pgs/chapter.h"
#include "04_pgs/scenes.h"
#include "ch04_support.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace stepwise;

namespace {

struct RestingRecord {
    double minDepth = 1e9, maxDepth = 0;  // after the first second
    double drift = 0;                     // horizontal, m, after the run
};

RestingRecord rest(World& world, Pipeline& pipeline, int body, double seconds) {
    const Vec3 start = world.bodies[body].transform.position;
    RestingRecord record;
    test::simulate(world, pipeline, seconds, [&](const World& w) {
        if (w.time < 1) return;
        const double depth = test::overlapDepth(w, 0, body);
        record.minDepth = std::min(record.minDepth, depth);
        record.maxDepth = std::max(record.maxDepth, depth);
    });
    const Vec3 offset = world.bodies[body].transform.position - start;
    record.drift = std::hypot(static_cast<double>(offset.x()), static_cast<double>(offset.z()));
    return record;
}

}  // namespace

TEST_CASE("a ball set on the ground settles to the slop and does not drift over 10 s", "[ch04][resting]") {
    World world = test::makeWorld();
    test::addGround(world);
    const int ball = test::addSphere(world, Vec3(0, Real(0.5), 0), Real(0.5), BodyType::Dynamic, 1);
    Pipeline pipeline = makeChapter04Pipeline(world);
    const RestingRecord record = rest(world, pipeline, ball, 10);
    const double slop = world.settings.slop;
    INFO("depth " << record.minDepth << " to " << record.maxDepth << " m, slop " << slop << " m, drift " << record.drift);
    CHECK(test::relativeError(record.minDepth, slop) < 0.1);
    CHECK(test::relativeError(record.maxDepth, slop) < 0.1);
    CHECK(record.drift < 1e-4);
}

TEST_CASE("a box set on the ground settles to the slop and does not drift over 10 s", "[ch04][resting]") {
    World world = test::makeWorld();
    test::addGround(world);
    const int box = test::addBox(world, Vec3(0, Real(0.5), 0), Vec3(Real(0.5), Real(0.5), Real(0.5)),
                                 BodyType::Dynamic, Quat::Identity(), 1);
    Pipeline pipeline = makeChapter04Pipeline(world);
    const RestingRecord record = rest(world, pipeline, box, 10);
    const double slop = world.settings.slop;
    INFO("depth " << record.minDepth << " to " << record.maxDepth << " m, slop " << slop << " m, drift " << record.drift);
    CHECK(test::relativeError(record.minDepth, slop) < 0.1);
    CHECK(test::relativeError(record.maxDepth, slop) < 0.1);
    CHECK(record.drift < 1e-3);
}

TEST_CASE("a 10 kg ball on a 1 kg ball on the ground sinks less than twice the slop", "[ch04][resting]") {
    World world = buildRestingScene();
    Pipeline pipeline = makeChapter04Pipeline(world);
    const int light = world.findBody("light");
    const int heavy = world.findBody("heavy");
    double deepest = 0;
    test::simulate(world, pipeline, 5, [&](const World& w) {
        deepest = std::max({deepest, static_cast<double>(test::overlapDepth(w, 0, light)),
                            static_cast<double>(test::overlapDepth(w, light, heavy))});
    });
    INFO("deepest " << deepest << " m, slop " << world.settings.slop << " m");
    CHECK(deepest < 2 * world.settings.slop);
    CHECK(world.bodies[heavy].transform.position.y() > world.bodies[light].transform.position.y());  // still stacked
}

TEST_CASE("split integration rests at the slop; the seed's integrate-first order sinks by g dt^2 / beta more",
          "[ch04][resting]") {
    // Integrate-first: the solver's velocity only moves the body next step, after gravity took
    // g dt off it again, so at rest Baumgarte must keep asking for +g dt: beta/dt (d - slop) = g dt,
    // d = slop + g dt^2 / beta. Split: the positions move with the solved velocity itself, which
    // is zero once d = slop.
    auto settledDepth = [](StepOrder order) {
        World world = test::makeWorld();
        test::addGround(world);
        const int ball = test::addSphere(world, Vec3(0, Real(0.5), 0), Real(0.5), BodyType::Dynamic, 1);
        Pipeline pipeline = makeChapter04Pipeline(world, order);
        test::simulate(world, pipeline, 3);
        return static_cast<double>(test::overlapDepth(world, 0, ball));
    };
    const Settings settings;
    const double g = 9.81, dt = settings.dt;
    const double split = settledDepth(StepOrder::SplitIntegration);
    const double first = settledDepth(StepOrder::IntegrateFirst);
    INFO("split " << split << " m, integrate-first " << first << " m");
    CHECK(test::relativeError(split, settings.slop) < 0.02);
    CHECK(test::relativeError(first, settings.slop + g * dt * dt / settings.baumgarte) < 0.05);
}
