// Free rotation: the gyroscopic term and the Dzhanibekov (tennis racket) flip. A box with three
// distinct moments of inertia spun about its intermediate axis is unstable: a tiny wobble grows
// until the body turns over, again and again, while its angular momentum L stays fixed in space.
#include "oscillator.h"
#include "01_integrators/chapter.h"
#include "01_integrators/forces.h"
#include "01_integrators/integrate.h"
#include "01_integrators/rotation.h"
#include "01_integrators/scenes.h"
#include "math/random.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

#include <limits>
#include <random>

using namespace stepwise;
using namespace stepwise::test;

namespace {

struct SpinRecord {
    double initialMomentum = 0, initialEnergy = 0;
    double worstMomentumChange = 0, worstEnergyChange = 0;   // relative
    double finalEnergy = 0;
    double lowestAlignment = 1;   // min of (intermediate axis . L direction)
    int flips = 0;                // sign changes of that alignment
    double worstQuaternionNorm = 0;
};

double rotationalEnergy(const World& world) {
    return 0.5 * world.motions[0].angularVelocity.cast<double>().dot(angularMomentum(world, 0).cast<double>());
}

SpinRecord spin(GyroscopicMode mode, IntegratorKind method, double seconds) {
    World world = buildTHandle(mode);
    world.settings.integrator = method;
    Pipeline pipeline = makeChapter01Pipeline(world);
    SpinRecord record;
    const Vec3 initialL = angularMomentum(world, 0);
    record.initialMomentum = initialL.norm();
    record.initialEnergy = rotationalEnergy(world);
    const Vec3 direction = initialL.normalized();
    double previousAlignment = 1;
    simulate(world, pipeline, seconds, [&](const World& w) {
        const double momentum = angularMomentum(w, 0).norm();
        const double energy = rotationalEnergy(w);
        record.worstMomentumChange =
            std::max(record.worstMomentumChange, std::abs(momentum / record.initialMomentum - 1));
        record.worstEnergyChange = std::max(record.worstEnergyChange, std::abs(energy / record.initialEnergy - 1));
        record.finalEnergy = energy;
        const double alignment = w.bodies[0].transform.rotate(Vec3::UnitZ()).dot(direction);
        record.lowestAlignment = std::min(record.lowestAlignment, alignment);
        if (std::abs(alignment) > 0.9 && alignment * previousAlignment < 0) ++record.flips;
        if (std::abs(alignment) > 0.9) previousAlignment = alignment;
        record.worstQuaternionNorm =
            std::max(record.worstQuaternionNorm, std::abs(double(w.bodies[0].transform.rotation.norm()) - 1));
    });
    return record;
}

}  // namespace

TEST_CASE("the T-handle flips with the implicit gyroscopic step and keeps |L| and energy", "[ch01][rotation]") {
    const SpinRecord record = spin(GyroscopicMode::Implicit, IntegratorKind::SemiImplicitEuler, 20.0);
    INFO("flips " << record.flips << " lowest alignment " << record.lowestAlignment);
    INFO("|L| change " << record.worstMomentumChange << " energy change " << record.worstEnergyChange);
    CHECK(record.lowestAlignment < -0.9);
    CHECK(record.flips >= 2);
    CHECK(record.worstMomentumChange < 1e-3);
    CHECK(record.worstEnergyChange < 1e-2);
    CHECK(record.worstQuaternionNorm < 1e-5);
}

TEST_CASE("the explicit gyroscopic step gains energy on the T-handle", "[ch01][rotation]") {
    const SpinRecord explicitRecord = spin(GyroscopicMode::Explicit, IntegratorKind::SemiImplicitEuler, 20.0);
    const SpinRecord implicitRecord = spin(GyroscopicMode::Implicit, IntegratorKind::SemiImplicitEuler, 20.0);
    INFO("explicit energy " << explicitRecord.initialEnergy << " -> " << explicitRecord.finalEnergy);
    INFO("implicit energy " << implicitRecord.initialEnergy << " -> " << implicitRecord.finalEnergy);
    CHECK(explicitRecord.finalEnergy > explicitRecord.initialEnergy);
    CHECK(explicitRecord.worstEnergyChange > 2 * implicitRecord.worstEnergyChange);
}

TEST_CASE("without the gyroscopic term the angular velocity never changes and nothing flips", "[ch01][rotation]") {
    World world = buildTHandle(GyroscopicMode::Off);
    const Vec3 initialOmega = world.motions[0].angularVelocity;
    Pipeline pipeline = makeChapter01Pipeline(world);
    const SpinRecord record = spin(GyroscopicMode::Off, IntegratorKind::SemiImplicitEuler, 20.0);
    simulate(world, pipeline, 5.0);
    CHECK((world.motions[0].angularVelocity - initialOmega).norm() < 1e-5);
    CHECK(record.flips == 0);
}

TEST_CASE("RK4 and Verlet integrate Euler's equations: the T-handle flips for them too", "[ch01][rotation]") {
    for (IntegratorKind method : {IntegratorKind::Rk4, IntegratorKind::Verlet}) {
        const SpinRecord record = spin(GyroscopicMode::Implicit, method, 20.0);
        INFO(toString(method) << " flips " << record.flips << " |L| change " << record.worstMomentumChange
                              << " energy change " << record.worstEnergyChange);
        CHECK(record.flips >= 2);
        CHECK(record.worstMomentumChange < 1e-2);
        CHECK(record.worstEnergyChange < 1e-2);
    }
}

TEST_CASE("one Newton step of the midpoint rule keeps energy / |L|^2, and the rescaled step keeps both",
          "[ch01][rotation]") {
    // Random inertias, spins and steps (seeded), including steps far too large for accuracy.
    std::mt19937 random(7);
    auto uniform = [&](double low, double high) { return Real(low + (high - low) * (random() / 4294967295.0)); };
    for (int trial = 0; trial < 50; ++trial) {
        const Mat3 inertia = Vec3(uniform(0.1, 2), uniform(0.1, 2), uniform(0.1, 2)).asDiagonal();
        const Vec3 omega(uniform(-20, 20), uniform(-20, 20), uniform(-20, 20));
        const Quat rotation = Quat(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)).normalized();
        const Real h = uniform(0.001, 0.5);
        auto invariants = [&](const Vec3& worldOmega) {
            const Vec3 bodyOmega = rotation.conjugate() * worldOmega;
            const double momentum = (inertia * bodyOmega).cast<double>().norm();
            const double energy = 0.5 * bodyOmega.cast<double>().dot((inertia * bodyOmega).cast<double>());
            return std::make_pair(momentum, energy);
        };
        const auto before = invariants(omega);
        const auto after = invariants(gyroscopicStepImplicit(omega, rotation, inertia, h));
        INFO("trial " << trial << " h " << h);
        const double tolerance = isDoubleBuild() ? 1e-12 : 1e-5;
        CHECK(after.first == Approx(before.first).epsilon(tolerance));
        CHECK(after.second == Approx(before.second).epsilon(tolerance));
    }
}

TEST_CASE("Catto's backward-Euler gyroscopic step damps the T-handle, and the midpoint step does not",
          "[ch01][rotation]") {
    auto momentumLoss = [](bool backwardEuler) {
        World world = buildTHandle(GyroscopicMode::Off);
        const double initial = angularMomentum(world, 0).norm();
        const Real h = world.settings.dt;
        const long frames = framesFor(world, 20.0);
        for (long frame = 0; frame < frames; ++frame) {
            Motion& motion = world.motions[0];
            const Quat rotation = world.bodies[0].transform.rotation;
            motion.angularVelocity = backwardEuler
                                         ? gyroscopicStepBackwardEuler(motion.angularVelocity, rotation, motion.inertiaLocal, h)
                                         : gyroscopicStepImplicit(motion.angularVelocity, rotation, motion.inertiaLocal, h);
            integratePositions(world, h);
        }
        return 1 - angularMomentum(world, 0).norm() / initial;
    };
    const double backwardEulerLoss = momentumLoss(true);
    const double midpointLoss = momentumLoss(false);
    INFO("|L| lost over 20 s: backward Euler " << backwardEulerLoss << ", midpoint " << midpointLoss);
    CHECK(backwardEulerLoss > 0.05);
    // Round-off only: about an ulp a step, one-sided, over 1,200 steps (1.2e-4 in float, 3e-13
    // in double), where backward Euler loses a third.
    CHECK(std::abs(midpointLoss) < 1200 * 2 * std::numeric_limits<Real>::epsilon());
}

TEST_CASE("the implicit gyroscopic step stays bounded for very fast spins", "[ch01][rotation]") {
    for (double spinRate : {60.0, 600.0, 6000.0}) {
        World world = buildTHandle(GyroscopicMode::Implicit);
        world.motions[0].angularVelocity = Vec3(Real(0.01 * spinRate), Real(0.002 * spinRate), Real(spinRate));
        const double initial = angularMomentum(world, 0).norm();
        Pipeline pipeline = makeChapter01Pipeline(world);
        simulate(world, pipeline, 5.0);
        INFO("spin " << spinRate << " rad/s");
        CHECK(angularMomentum(world, 0).norm() == Approx(initial).epsilon(1e-3));
        CHECK(world.bodies[0].transform.rotation.coeffs().allFinite());
    }
}

TEST_CASE("the rotation step turns a steady spin by exactly h |w|, where the first-order step lags", "[ch01][rotation]") {
    // Angle of the rotation between two orientations, in double (q and -q are the same rotation).
    const auto angleBetween = [](const Quat& a, const Quat& b) {
        const Eigen::Quaterniond difference = a.cast<double>() * b.cast<double>().conjugate();
        return 2 * std::atan2(difference.vec().norm(), std::abs(difference.w()));
    };
    // The series: cos x and sin(x)/x to within a few float ulps up to x = 2 (4 rad a step).
    for (int i = 0; i <= 400; ++i) {
        const double x = 2.0 * i / 400;
        Real cosine = 0, sineRatio = 0;
        turnSeries(Real(x * x), [](Real value) { return value; }, cosine, sineRatio);
        INFO("x = " << x);
        CHECK(std::abs(double(cosine) - std::cos(x)) < 4e-7);
        CHECK(std::abs(double(sineRatio) - (x > 0 ? std::sin(x) / x : 1.0)) < 4e-7);
    }
    // A brick at 10 rad/s for 2 s at 60 Hz: 20 rad. The first-order step turns by
    // 2 atan(h |w| / 2) a step, 0.046 rad short in all; the corrected one lands on it.
    const Vec3 spin(10, 0, 0);
    const Real h = Real(1) / 60;
    Quat firstOrder = Quat::Identity(), turned = Quat::Identity();
    for (int step = 0; step < 120; ++step) {
        firstOrder = integrateRotation(firstOrder, spin, h);
        turned = turnRotation(turned, spin, h);
    }
    const Quat exact(Eigen::AngleAxis<Real>(20, Vec3::UnitX()));
    const double perStepLag = double(h) * 10 - 2 * std::atan(double(h) * 10 / 2);
    CHECK(angleBetween(firstOrder, exact) == Approx(120 * perStepLag).epsilon(0.05));
    CHECK(angleBetween(turned, exact) < 1e-4);
    // Any spin, slow or too fast for the series: the same turn as the exact axis-angle rotation.
    Random random(12);
    for (int trial = 0; trial < 200; ++trial) {
        const Quat start = random.rotation();
        const Real rate = trial % 10 == 0 ? Real(500) : Real(random.uniform(0, 30));
        const Vec3 axis = random.rotation() * Vec3::UnitX();
        INFO("trial " << trial << ", " << rate << " rad/s");
        CHECK(angleBetween(turnRotation(start, rate * axis, h), rotateExactly(start, rate * axis, h)) < 2e-6 * (1 + rate * h));
    }
}
