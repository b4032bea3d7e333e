// The reference suite's metrics on hand-made trajectories whose answer is known by construction,
// and the score that compares them with a sidecar's tolerances (bench/engine/reference.h).
#include "engine/reference.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;
using namespace stepwise::engine_bench;

namespace {

/// A world of one dynamic 1 kg ball "ball" (and a static "ground"), no gravity unless given.
World oneBall(const Vec3& velocity = Vec3::Zero(), const Vec3& gravity = Vec3::Zero()) {
    World world;
    world.settings.gravity = gravity;
    BodyDef ground;
    ground.name = "ground";
    ground.type = BodyType::Static;
    ground.shape = Shape::box(Vec3(5, Real(0.5), 5));
    ground.transform.position = Vec3(0, Real(-0.5), 0);
    addBody(world, ground);
    BodyDef ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(Real(0.1));
    ball.mass = Real(1);
    ball.linearVelocity = velocity;
    addBody(world, ball);
    return world;
}

/// A trajectory of `world` whose ball follows `place(t)` (positions) for `frames` frames of `dt`.
template <class Place>
Trajectory ballPath(const World& world, int frames, double dt, Place place) {
    Trajectory run;
    run.dt = dt;
    run.start = world;
    run.end = world;
    for (int f = 0; f <= frames; ++f) {
        std::vector<Transform> poses = {world.bodies[0].transform, world.bodies[1].transform};
        poses[1].position = place(f * dt);
        run.poses.push_back(poses);
    }
    run.end.bodies[1].transform = run.poses.back()[1];
    return run;
}

Check check(const std::string& metric, double tolerance = 1) {
    Check c;
    c.metric = metric;
    c.body = "ball";
    c.tolerance = tolerance;
    c.why = "test";
    return c;
}

}  // namespace

TEST_CASE("closed_form_position: zero on the exact parabola, the offset where it leaves it", "[engine-bench]") {
    const Vec3 v0(3, 4, 0), g(0, Real(-9.81), 0);
    const World world = oneBall(v0, g);
    const auto parabola = [&](double t) { return Vec3(v0 * Real(t) + g * Real(t * t / 2)); };
    CHECK(measureError(check("closed_form_position"), ballPath(world, 60, 1.0 / 60, parabola)) < 1e-5);
    Trajectory off = ballPath(world, 60, 1.0 / 60, parabola);
    off.poses[30][1].position.z() += Real(0.05);
    CHECK(measureError(check("closed_form_position"), off) == Approx(0.05).margin(1e-5));
}

TEST_CASE("closed_form_rotation: the angle between the run and exp(w t) q0", "[engine-bench]") {
    World world = oneBall();
    world.motions[0].angularVelocity = Vec3(0, 2, 0);
    Trajectory run = ballPath(world, 100, 0.01, [](double) { return Vec3::Zero(); });
    for (int f = 0; f <= 100; ++f)  // 5% too fast: after 1 s the angle is 0.1 rad ahead
        run.poses[f][1].rotation = Quat(Eigen::AngleAxis<Real>(Real(2.1 * f * 0.01), Vec3::UnitY()));
    CHECK(measureError(check("closed_form_rotation"), run) == Approx(0.1).margin(1e-4));
}

TEST_CASE("bounce_apex: the first top after the first turn upwards", "[engine-bench]") {
    const std::vector<double> heights = {1.0, 0.5, 0.1, 0.3, 0.5, 0.6, 0.55, 0.3, 0.1, 0.2, 0.25};
    Check apex = check("bounce_apex");
    apex.expected = 0.64;
    const Trajectory run = ballPath(oneBall(), int(heights.size()) - 1, 0.1,
                                    [&](double t) { return Vec3(0, Real(heights[std::size_t(std::lround(t / 0.1))]), 0); });
    CHECK(measureError(apex, run) == Approx(0.04).margin(1e-6));
}

TEST_CASE("final_speed, displacement, max_coordinate, max_distance", "[engine-bench]") {
    World world = oneBall();
    Trajectory run = ballPath(world, 10, 0.1, [](double t) { return Vec3(Real(3 * t), Real(4 * t), 0); });
    run.end.motions[0].linearVelocity = Vec3(3, 4, 0);
    Check speed = check("final_speed");
    speed.expected = 4.5;
    CHECK(measureError(speed, run) == Approx(0.5).epsilon(1e-5));
    Check moved = check("displacement");
    moved.expected = 1;
    CHECK(measureError(moved, run) == Approx(4).epsilon(1e-5));  // moved 5 m
    Check beyond = check("max_coordinate");
    beyond.axis = 1;
    beyond.limit = 3.5;
    CHECK(measureError(beyond, run) == Approx(0.5).epsilon(1e-5));  // reached y = 4
    beyond.limit = 5;
    CHECK(measureError(beyond, run) == 0);
    Check far = check("max_distance");
    far.point = Vec3(Real(0.1), 0, 0);   // the ball's +x pole, ends at (3.1, 4, 0)
    far.to = Vec3::Zero();
    far.expected = 5;   // the largest distance is at the end: |(3.1, 4, 0)| = 5.0606
    CHECK(measureError(far, run) == Approx(std::hypot(3.1, 4.0) - 5).epsilon(1e-3));
}

TEST_CASE("period: the mean time between upward crossings of the centre", "[engine-bench]") {
    const double period = 1.3;
    Check swing = check("period");
    swing.center = 0.25;
    swing.expected = 1.2;
    const Trajectory run = ballPath(oneBall(), 500, 0.01, [&](double t) {
        return Vec3(Real(0.25 + 0.1 * std::sin(2 * M_PI * t / period)), 0, 0);
    });
    CHECK(measureError(swing, run) == Approx(0.1).margin(2e-4));
    const Trajectory still = ballPath(oneBall(), 100, 0.01, [](double) { return Vec3::Zero(); });
    CHECK(measureError(swing, still) == Approx(1.2));  // never crosses: the whole period is wrong
}

TEST_CASE("drift and sag: the largest sideways move and drop of a dynamic body", "[engine-bench]") {
    const Trajectory run = ballPath(oneBall(), 10, 0.1, [](double t) {
        return Vec3(Real(0.03 * t), Real(-0.02 * t), Real(0.04 * t));
    });
    CHECK(measureError(check("drift"), run) == Approx(0.05).epsilon(1e-4));
    CHECK(measureError(check("sag"), run) == Approx(0.02).epsilon(1e-4));
}

TEST_CASE("momentum and energy: changes between the start and the end", "[engine-bench]") {
    Trajectory run = ballPath(oneBall(Vec3(2, 0, 0)), 10, 0.1, [](double t) { return Vec3(Real(2 * t), 0, 0); });
    run.end.motions[0].linearVelocity = Vec3(1, 0, 0);
    CHECK(measureError(check("momentum"), run) == Approx(1));         // 2 -> 1 kg m/s
    CHECK(measureError(check("energy_change"), run) == Approx(0.75));  // 2 J -> 0.5 J
    CHECK(measureError(check("energy_gain"), run) == 0);
    run.end.motions[0].linearVelocity = Vec3(3, 0, 0);
    CHECK(measureError(check("energy_gain"), run) == Approx(1.25));   // 2 J -> 4.5 J
}

TEST_CASE("time_to_rest: when the kinetic energy stays below its fraction of the start", "[engine-bench]") {
    // 2 m/s (2 J, all of the start's energy) until t = 0.5 s, then still.
    const Trajectory run = ballPath(oneBall(Vec3(2, 0, 0)), 100, 0.01, [](double t) { return Vec3(Real(2 * std::min(t, 0.5)), 0, 0); });
    Check rest = check("time_to_rest");
    rest.kineticFraction = 0.001;
    CHECK(measureError(rest, run) == Approx(0.5).margin(0.011));
}

TEST_CASE("penetration, and the score: the worst error / tolerance, unmeasured never passes", "[engine-bench]") {
    Trajectory run = ballPath(oneBall(), 1, 0.1, [](double) { return Vec3::Zero(); });
    run.finalPenetration = 0.02;
    Sidecar sidecar;
    sidecar.checks = {check("penetration", 0.01), check("drift", 0.5)};
    Score score = scoreRun(sidecar, run);
    CHECK(score.errors[0] == Approx(0.02));
    CHECK(score.worst == Approx(2));
    CHECK(score.worstCheck == 0);
    CHECK_FALSE(score.meets());
    run.finalPenetration = 0.005;
    CHECK(scoreRun(sidecar, run).meets());
    run.finalPenetration = -1;  // not measured
    score = scoreRun(sidecar, run);
    CHECK(std::isnan(score.errors[0]));
    CHECK(std::isinf(score.worst));
    CHECK_FALSE(score.meets());
}
