// Exercise check for chapter 1 (`ctest -L ch01-exercise`): rewrite integrateRotation in
// chapters/01_integrators/rotation.h from the page's formula q1 = q0 + h/2 (0, w) q0, then
// normalise, and run this. It checks what any correct first-order update must do, with a
// message that says which property your version breaks.
#include "01_integrators/rotation.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace stepwise;

namespace {

Quat randomRotation(std::mt19937& random) {
    std::normal_distribution<double> gauss;
    Quat q(Real(gauss(random)), Real(gauss(random)), Real(gauss(random)), Real(gauss(random)));
    q.normalize();
    return q;
}

Vec3 randomSpin(std::mt19937& random, double maxRate) {
    std::uniform_real_distribution<double> rate(-maxRate, maxRate);
    return Vec3(Real(rate(random)), Real(rate(random)), Real(rate(random)));
}

// Angle of the rotation that takes b to a, in double (an acos of a float dot product could not
// resolve the small angles this needs); q and -q are the same rotation.
double angleBetween(const Quat& a, const Quat& b) {
    const Eigen::Quaterniond difference = a.cast<double>() * b.cast<double>().conjugate();
    return 2 * std::atan2(difference.vec().norm(), std::abs(difference.w()));
}

}  // namespace

TEST_CASE("exercise: the quaternion update stays a rotation and follows the spin", "[ch01-exercise]") {
    std::mt19937 random(1234);
    const Real h = Real(1) / 60;
    for (int trial = 0; trial < 1000; ++trial) {
        const Quat q0 = randomRotation(random);
        const Vec3 spin = randomSpin(random, 10);
        const Quat q1 = integrateRotation(q0, spin, h);
        INFO("trial " << trial << ", spin (" << spin.transpose() << ") rad/s");
        // Unit length: otherwise it is no rotation, and R(q) scales the body.
        REQUIRE(std::abs(q1.norm() - 1) < 1e-5);
        // It turns by about |w| h about w: a first-order step is off by O((|w| h)^2).
        const double turn = double(spin.norm()) * h;
        const double error = angleBetween(q1, rotateExactly(q0, spin, h));
        REQUIRE(error < 0.1 * turn * turn + 1e-5);
    }
}

TEST_CASE("exercise: the update's error shrinks with the step", "[ch01-exercise]") {
    // Spin about a fixed axis for one second: the error after 1 s must shrink when h halves
    // (for this normalised step it falls about fourfold, since about a fixed axis it only
    // misjudges the angle, by 2 atan(|w| h / 2) against |w| h).
    const Quat start = Quat::Identity();
    const Vec3 spin(0, 3, 0);
    auto errorAfterOneSecond = [&](int steps) {
        Quat q = start;
        for (int step = 0; step < steps; ++step) q = integrateRotation(q, spin, Real(1) / Real(steps));
        return angleBetween(q, rotateExactly(start, spin, 1));
    };
    const double coarse = errorAfterOneSecond(60);
    const double fine = errorAfterOneSecond(120);
    INFO("error after 1 s: " << coarse << " rad at 60 Hz, " << fine << " rad at 120 Hz");
    REQUIRE(coarse > 0);
    REQUIRE(fine < 0.6 * coarse);
}
