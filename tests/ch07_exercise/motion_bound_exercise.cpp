// Exercise check for chapter 7 (`ctest -L ch07-exercise`): rewrite closingSpeedBound in
// chapters/07_ccd/time_of_impact.cpp from the page's formula (the relative motion of the centres
// along n, where it closes, plus each body's turn rate times its largest lever arm, all per unit
// of the step fraction a sweep has left), and run this. The bound must be safe: along a fixed
// direction, the gap between two swept shapes never shrinks faster than it says, turning bodies
// included. It must also be tight where nothing turns: then it is exactly the centres' closing
// speed, and zero for bodies that move apart.
#include "02_gjk/support.h"
#include "07_ccd/time_of_impact.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

namespace {

// The gap between the shapes along a fixed unit direction n (A towards B), in double: how far
// apart two planes with normal n can be with A behind one and B in front of the other.
double gapAlong(const Shape& shapeA, const Sweep& a, const Shape& shapeB, const Sweep& b, const Vec3& n, double t) {
    const ConvexProxy proxyA{&shapeA, poseAt(a, Real(t))};
    const ConvexProxy proxyB{&shapeB, poseAt(b, Real(t))};
    return double(n.dot(proxyB.support(-n))) - double(n.dot(proxyA.support(n)));
}

Vec3 randomUnit(Random& random) {
    Vec3 v;
    do v = Vec3(Real(random.uniform(-1, 1)), Real(random.uniform(-1, 1)), Real(random.uniform(-1, 1)));
    while (v.norm() < Real(0.1) || v.norm() > 1);
    return v.normalized();
}

Shape randomShape(Random& random) {
    const auto size = [&] { return Real(random.uniform(0.05, 0.6)); };
    switch (int(random.uniform() * 3)) {
        case 0: return Shape::sphere(size());
        case 1: return Shape::capsule(size() / 2, size());
        default: return Shape::box(Vec3(size(), size(), size()));
    }
}

Sweep randomSweep(Random& random, bool turns, Real alpha0) {
    Transform start{Vec3(Real(random.uniform(-2, 2)), Real(random.uniform(-2, 2)), Real(random.uniform(-2, 2))),
                    Quat(Eigen::AngleAxis<Real>(Real(random.uniform(-3, 3)), randomUnit(random)))};
    Transform end = start;
    end.position += Real(random.uniform(0, 3)) * randomUnit(random);
    if (turns) end.rotation = Quat(Eigen::AngleAxis<Real>(Real(random.uniform(0.1, 3)), randomUnit(random))) * start.rotation;
    const Vec3 localCenter(Real(random.uniform(-0.1, 0.1)), Real(random.uniform(-0.1, 0.1)), 0);
    return sweepBetween(start, end, localCenter, alpha0);
}

}  // namespace

TEST_CASE("exercise: the gap along a fixed direction never closes faster than the bound", "[ch07-exercise]") {
    Random random(707);
    for (int trial = 0; trial < 400; ++trial) {
        const Real alpha0 = trial % 4 == 0 ? Real(random.uniform(0, 0.8)) : Real(0);
        const Shape shapeA = randomShape(random), shapeB = randomShape(random);
        const Sweep a = randomSweep(random, trial % 3 != 1, alpha0);
        const Sweep b = randomSweep(random, trial % 5 == 0, alpha0);
        const Vec3 n = randomUnit(random);
        const double bound = double(closingSpeedBound(a, shapeA, b, shapeB, n));
        // Over any stretch of the sweeps, the gap falls by at most bound * (t2 - t1).
        double worst = 0;
        for (int k = 0; k < 24; ++k) {
            const double span = 1 - double(alpha0);
            const double t1 = double(alpha0) + span * random.uniform(0, 0.7);
            const double t2 = t1 + span * random.uniform(0.05, 0.3);
            const double fall = gapAlong(shapeA, a, shapeB, b, n, t1) - gapAlong(shapeA, a, shapeB, b, n, t2);
            worst = std::max(worst, fall / (t2 - t1));
        }
        INFO("trial " << trial << ": the gap along n closes at " << worst << " m per unit t, your bound says " << bound);
        REQUIRE(worst <= bound * (1 + 1e-4) + 1e-3);  // float rounding of the gaps
    }
}

TEST_CASE("exercise: without turning, the bound is the centres' closing speed along n, per unit of t left",
          "[ch07-exercise]") {
    Random random(708);
    for (int trial = 0; trial < 400; ++trial) {
        const Real alpha0 = trial % 2 == 0 ? Real(random.uniform(0, 0.8)) : Real(0);
        const Shape shapeA = randomShape(random), shapeB = randomShape(random);
        const Sweep a = randomSweep(random, false, alpha0);
        const Sweep b = randomSweep(random, false, alpha0);
        const Vec3 n = randomUnit(random);
        const Real left = 1 - alpha0;
        const double closing = double(((a.center1 - a.center0) - (b.center1 - b.center0)).dot(n) / left);
        const double expected = std::max(0.0, closing);
        const double bound = double(closingSpeedBound(a, shapeA, b, shapeB, n));
        INFO("trial " << trial << " (alpha0 " << alpha0 << "): expected " << expected << ", your bound " << bound);
        // The engine reads a sweep's turn as 2 acos(|q0 . q1|): for two equal float quaternions that
        // is a few 1e-4 rad (2 acos(1 - 2^-24) = 6.9e-4), times the lever arms, per t left.
        const double floor = 2e-3 * double(maxLeverArm(shapeA, a.localCenter) + maxLeverArm(shapeB, b.localCenter)) / double(left);
        REQUIRE(std::abs(bound - expected) <= floor + 1e-4 * (1 + expected));
    }
}

TEST_CASE("exercise: a rod spinning in place next to a wall is bounded by its turn", "[ch07-exercise]") {
    const Shape rod = Shape::box(Vec3(Real(0.01), Real(0.5), Real(0.01)));
    const Shape wall = Shape::box(Vec3(Real(0.025), 3, 3));
    const Transform start{Vec3(-Real(0.33), 0, 0), Quat::Identity()};
    Transform end = start;
    end.rotation = Quat(Eigen::AngleAxis<Real>(Real(1.6), Vec3::UnitZ()));
    const Sweep spin = sweepBetween(start, end, Vec3::Zero());
    const Sweep still = stillSweep(Transform{}, Vec3::Zero());
    // The rod's corners are sqrt(0.01^2 + 0.5^2 + 0.01^2) from its centre; it turns 1.6 rad in the
    // step: 0.800 m per step (the page's exercise 3).
    const double expected = 1.6 * std::sqrt(0.25 + 0.0002);
    const double bound = double(closingSpeedBound(spin, rod, still, wall, Vec3::UnitX()));
    INFO("your bound for the spinning rod: " << bound << " m per step, expected " << expected);
    CHECK(std::abs(bound - expected) < 1e-3);
    // And the time of impact built on it stops the rod before an end reaches the wall.
    const ToiResult toi = timeOfImpact(rod, spin, wall, still, toiOptionsFor(Settings{}));
    REQUIRE(toi.state == ToiState::Hit);
    CHECK(gapAlong(rod, spin, wall, still, Vec3::UnitX(), double(toi.time)) > 0);
}
