// Measured convergence orders: the slope of log(error) against log(dt) on problems with a
// closed-form solution. Float round-off sits near 1e-6 m here, so every point is checked to lie
// well above it (the double build, -DSTEPWISE_DOUBLE=ON, extends RK4's range).
#include "oscillator.h"

#include "01_integrators/rotation.h"

#include <catch2/catch.hpp>

using namespace stepwise;
using namespace stepwise::test;

namespace {

constexpr double kDuration = 1.3;  // s: 1.3 periods, where no error term happens to vanish

double measuredOrder(IntegratorKind method, const std::vector<int>& stepCounts, double& smallestError) {
    const OscillatorSetup setup;
    std::vector<double> dts, errors;
    for (int steps : stepCounts) {
        dts.push_back(kDuration / steps);
        errors.push_back(oscillatorError(setup, method, kDuration, steps));
        INFO(toString(method) << " steps " << steps << " error " << errors.back());
        CHECK(std::isfinite(errors.back()));
    }
    smallestError = *std::min_element(errors.begin(), errors.end());
    return logLogSlope(dts, errors);
}

}  // namespace

TEST_CASE("semi-implicit Euler converges with order 1 on the oscillator", "[ch01][convergence]") {
    double smallest = 0;
    const double order = measuredOrder(IntegratorKind::SemiImplicitEuler, {100, 200, 400, 800}, smallest);
    INFO("order " << order);
    REQUIRE(smallest > 1e-4);
    REQUIRE(order == Approx(1).margin(0.15));
}

TEST_CASE("velocity Verlet converges with order 2 on the oscillator", "[ch01][convergence]") {
    double smallest = 0;
    const double order = measuredOrder(IntegratorKind::Verlet, {50, 100, 200, 400}, smallest);
    INFO("order " << order);
    REQUIRE(smallest > 1e-4);
    REQUIRE(order == Approx(2).margin(0.15));
}

TEST_CASE("RK4 converges with order 4 on the oscillator", "[ch01][convergence]") {
    double smallest = 0;
    const std::vector<int> steps = isDoubleBuild() ? std::vector<int>{13, 26, 52, 104, 208} : std::vector<int>{13, 26, 52};
    const double order = measuredOrder(IntegratorKind::Rk4, steps, smallest);
    INFO("order " << order);
    REQUIRE(smallest > (isDoubleBuild() ? 1e-9 : 1e-5));
    REQUIRE(order == Approx(4).margin(0.3));
}

// Two masses, each on a spring to its own anchor and joined by a third spring, moving along x:
// normal modes w1 = sqrt(k/m) (in phase) and w2 = sqrt((k + 2 kc)/m) (against each other).
// RK4 only keeps its order here if both bodies move to every intermediate stage together.
TEST_CASE("RK4 keeps order 4 on coupled springs because it steps all its bodies as one system",
          "[ch01][convergence]") {
    const double mass = 1, k = 10, kc = 15;
    const double w1 = std::sqrt(k / mass), w2 = std::sqrt((k + 2 * kc) / mass);
    const double amplitude = 0.2, duration = 2.1;
    auto error = [&](IntegratorKind method, int steps) {
        World world = makeWorld(zeroGravitySettings());
        world.settings.integrator = method;
        const int left = addSphere(world, Vec3(Real(-1 + amplitude), 0, 0), Real(0.1), BodyType::Dynamic, Real(mass));
        const int right = addSphere(world, Vec3(1, 0, 0), Real(0.1), BodyType::Dynamic, Real(mass));
        world.springs.push_back(Spring{left, -1, Vec3::Zero(), Vec3(-1, 0, 0), 0, Real(k), 0});
        world.springs.push_back(Spring{right, -1, Vec3::Zero(), Vec3(1, 0, 0), 0, Real(k), 0});
        world.springs.push_back(Spring{left, right, Vec3::Zero(), Vec3::Zero(), 2, Real(kc), 0});
        for (int i = 0; i < steps; ++i) integrate(world, Real(duration / steps));
        // Displacements: left = A/2 (cos w1 t + cos w2 t), right = A/2 (cos w1 t - cos w2 t).
        const double leftExact = -1 + amplitude / 2 * (std::cos(w1 * duration) + std::cos(w2 * duration));
        const double rightExact = 1 + amplitude / 2 * (std::cos(w1 * duration) - std::cos(w2 * duration));
        return std::hypot(world.bodies[left].transform.position.x() - leftExact,
                          world.bodies[right].transform.position.x() - rightExact);
    };
    for (IntegratorKind method : {IntegratorKind::Rk4, IntegratorKind::Verlet}) {
        const std::vector<int> steps =
            method == IntegratorKind::Rk4 ? std::vector<int>{10, 20, 40} : std::vector<int>{100, 200, 400};
        std::vector<double> dts, errors;
        for (int count : steps) {
            dts.push_back(duration / count);
            errors.push_back(error(method, count));
            INFO(toString(method) << " steps " << count << " error " << errors.back());
            REQUIRE(errors.back() > 1e-5);
        }
        const double expected = method == IntegratorKind::Rk4 ? 4 : 2;
        INFO(toString(method) << " order " << logLogSlope(dts, errors));
        CHECK(logLogSlope(dts, errors) == Approx(expected).margin(method == IntegratorKind::Rk4 ? 0.3 : 0.15));
    }
}

// A steady spin: the exact orientation after t is a turn by |w| t. This pins RK4's fourth order
// for the orientation (its quaternion is only renormalised at the end of the step).
TEST_CASE("RK4 integrates the orientation of a steady spin with order 4", "[ch01][convergence]") {
    const Vec3 spin(Real(1.0), Real(-2.0), Real(2.5));
    const double duration = 1.7;
    std::vector<double> dts, errors;
    for (int steps : {4, 8, 16}) {
        Settings settings = zeroGravitySettings();
        settings.integrator = IntegratorKind::Rk4;
        settings.gyroscopic = GyroscopicMode::Off;
        World world = makeWorld(settings);
        const int body = addSphere(world, Vec3::Zero(), Real(0.5));
        setVelocity(world, body, Vec3::Zero(), spin);
        for (int i = 0; i < steps; ++i) integrate(world, Real(duration / steps));
        const Eigen::Quaterniond exact(Eigen::AngleAxisd(spin.cast<double>().norm() * duration,
                                                         spin.cast<double>().normalized()));
        const double angle = exact.angularDistance(world.bodies[body].transform.rotation.cast<double>());
        dts.push_back(duration / steps);
        errors.push_back(angle);
        INFO("steps " << steps << " angle error " << angle);
        REQUIRE(angle > 1e-5);
    }
    INFO("order " << logLogSlope(dts, errors));
    CHECK(logLogSlope(dts, errors) == Approx(4).margin(0.3));
}
