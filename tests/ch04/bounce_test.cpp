// Restitution: bounce heights and head-on collisions against their closed forms.
#include "04_pgs/chapter.h"
#include "04_pgs/scenes.h"
#include "ch04_support.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace stepwise;

namespace {

// The restitution law acts on the approach speed the solver sees, which is the speed at the
// step that first detects the overlap. The closed form e^2 h assumes the bounce happens at the
// surface; a discrete step detects it up to v dt below, where gravity has added up to g dt to
// the speed. At 60 Hz with a 2 m drop that is ~10 cm/s on 6 m/s and up to 10 cm of depth, a
// few percent of e^2 h. 64 substeps (dt = 0.26 ms) bring both below 0.5 %.
constexpr int kBounceSubsteps = 64;

}  // namespace

TEST_CASE("a ball dropped from h bounces to e^2 h", "[ch04][bounce]") {
    const Real height = 2;
    World world = buildBounceScene(height);
    world.settings.substeps = kBounceSubsteps;
    Pipeline pipeline = makeChapter04Pipeline(world);
    // All four balls fall together; each one's first apex is recorded.
    const char* names[] = {"ball-e0.3", "ball-e0.6", "ball-e0.9"};
    const double restitutions[] = {0.3, 0.6, 0.9};
    test::FirstApex first[3];
    for (int i = 0; i < 3; ++i) first[i].body = world.findBody(names[i]);
    test::simulate(world, pipeline, 2.5, [&](const World& w) {
        for (test::FirstApex& ball : first) ball.record(w);
    });
    for (int i = 0; i < 3; ++i) {
        INFO("restitution " << restitutions[i] << ": apex " << first[i].apex << " m, e^2 h = "
                            << restitutions[i] * restitutions[i] * height << " m");
        CHECK(first[i].falling);
        CHECK(test::relativeError(first[i].apex, restitutions[i] * restitutions[i] * height) < 0.02);
    }
}

TEST_CASE("with e = 1 a ball never rises above its start", "[ch04][bounce]") {
    const Real height = 2;
    World world = buildBounceScene(height);
    world.settings.substeps = kBounceSubsteps;
    Pipeline pipeline = makeChapter04Pipeline(world);
    const int ball = world.findBody("ball-e1.0");
    const Real radius = world.bodies[ball].shape.radius;
    double highest = -1, lowestApex = 1e9;
    bool rising = false;
    double apex = 0;
    int bounces = 0;
    // Five bounces; after each apex, check it against the start.
    test::simulate(world, pipeline, 6.5, [&](const World& w) {
        const double bottom = w.bodies[ball].transform.position.y() - radius;
        const double vy = w.motionOf(ball)->linearVelocity.y();
        if (w.time > 0.1) highest = std::max(highest, bottom);
        if (vy > 0) {
            rising = true;
            apex = std::max(apex, bottom);
        } else if (rising) {
            rising = false;
            ++bounces;
            lowestApex = std::min(lowestApex, apex);
            apex = 0;
        }
    });
    INFO("highest " << highest << " m after the start at " << height << " m; lowest apex " << lowestApex);
    CHECK(bounces >= 4);
    CHECK(highest <= height);
    CHECK(lowestApex > 0.98 * height);  // and it keeps nearly all of it
}

TEST_CASE("head-on collisions conserve momentum and obey the restitution law", "[ch04][bounce]") {
    const double restitution = GENERATE(0.0, 0.5, 1.0);
    auto [world, light, heavy] = test::headOnCollision(restitution);
    const double momentumBefore = 1 * 3.0 + 3 * -0.5;
    const double approach = -0.5 - 3.0;  // v_heavy - v_light
    Pipeline pipeline = makeChapter04Pipeline(world);
    test::simulate(world, pipeline, 1.0);
    const double vLight = world.motionOf(light)->linearVelocity.x();
    const double vHeavy = world.motionOf(heavy)->linearVelocity.x();
    INFO("e = " << restitution << ": velocities after " << vLight << ", " << vHeavy);
    const double momentumAfter = 1 * vLight + 3 * vHeavy;
    CHECK(std::abs(momentumAfter - momentumBefore) / std::abs(momentumBefore) < 1e-4);
    CHECK(std::abs((vHeavy - vLight) - (-restitution * approach)) < 1e-3 * std::abs(approach));
    CHECK(world.motionOf(light)->linearVelocity.tail<2>().norm() < 1e-6);  // stays on the line
}
