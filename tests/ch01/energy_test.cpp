// Long-run energy behaviour and the stability limit on the harmonic oscillator.
// Symplectic Euler conserves a nearby "shadow" energy, so the true energy oscillates in a band
// of relative width ~ h w and never drifts; RK4 is far more accurate per step but not
// symplectic: on this oscillator its amplification factor has modulus below one, so it
// loses energy, about (h w)^6 / 72 of it per step.
#include "oscillator.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace stepwise;
using namespace stepwise::test;

namespace {


struct EnergyRecord {
    double initial = 0;
    double minimum = 1e300, maximum = -1e300;
    double firstPeriodMin = 1e300, firstPeriodMax = -1e300;
    double lastPeriodMin = 1e300, lastPeriodMax = -1e300;
    std::vector<double> checkpoints;   // every 10,000 steps
};

EnergyRecord runEnergy(IntegratorKind method, double hOmega, int steps) {
    OscillatorSetup setup;
    World world = makeOscillator(setup, method);
    const Real dt = Real(hOmega / setup.omega);
    const int stepsPerPeriod = static_cast<int>(std::ceil(2 * 3.14159265358979323846 / hOmega));
    EnergyRecord record;
    record.initial = computeEnergy(world).total();
    for (int step = 1; step <= steps; ++step) {
        integrate(world, dt);
        const double energy = computeEnergy(world).total();
        record.minimum = std::min(record.minimum, energy);
        record.maximum = std::max(record.maximum, energy);
        if (step <= stepsPerPeriod) {
            record.firstPeriodMin = std::min(record.firstPeriodMin, energy);
            record.firstPeriodMax = std::max(record.firstPeriodMax, energy);
        }
        if (step > steps - stepsPerPeriod) {
            record.lastPeriodMin = std::min(record.lastPeriodMin, energy);
            record.lastPeriodMax = std::max(record.lastPeriodMax, energy);
        }
        if (step % 10000 == 0) record.checkpoints.push_back(energy);
    }
    return record;
}

}  // namespace

TEST_CASE("symplectic Euler keeps the oscillator's energy in a band over 100,000 steps", "[ch01][energy]") {
    const double hOmega = 0.2;
    const EnergyRecord euler = runEnergy(IntegratorKind::SemiImplicitEuler, hOmega, 100000);
    INFO("initial " << euler.initial << " band [" << euler.minimum << ", " << euler.maximum << "]");
    INFO("first period [" << euler.firstPeriodMin << ", " << euler.firstPeriodMax << "], last period ["
                          << euler.lastPeriodMin << ", " << euler.lastPeriodMax << "]");
    // The band is of relative width about h w ...
    CHECK(euler.maximum < euler.initial * (1 + hOmega));
    CHECK(euler.minimum > euler.initial * (1 - hOmega));
    // ... and the same band after 100,000 steps as in the first period: no drift.
    CHECK(std::abs(euler.lastPeriodMax - euler.firstPeriodMax) < 1e-3 * euler.initial);
    CHECK(std::abs(euler.lastPeriodMin - euler.firstPeriodMin) < 1e-3 * euler.initial);
}

TEST_CASE("RK4 loses the oscillator's energy steadily over 100,000 steps", "[ch01][energy]") {
    const double hOmega = 0.2;
    const EnergyRecord rk4 = runEnergy(IntegratorKind::Rk4, hOmega, 100000);
    INFO("initial " << rk4.initial << " final " << rk4.checkpoints.back());
    // Predicted loss: 1 - (1 - (h w)^6 / 72)^steps, about 8% here. Pin the direction and size.
    const double predictedRatio = std::pow(1 - std::pow(hOmega, 6) / 72, 100000);
    CHECK(rk4.checkpoints.back() / rk4.initial == Approx(predictedRatio).epsilon(0.02));
    CHECK(rk4.checkpoints.back() < 0.95 * rk4.initial);
    for (size_t i = 1; i < rk4.checkpoints.size(); ++i) CHECK(rk4.checkpoints[i] < rk4.checkpoints[i - 1]);
}

TEST_CASE("semi-implicit Euler is stable for h w below 2 and blows up above it", "[ch01][energy][stability]") {
    auto growth = [](double hOmega, int steps) {
        OscillatorSetup setup;
        World world = makeOscillator(setup, IntegratorKind::SemiImplicitEuler);
        const Real dt = Real(hOmega / setup.omega);
        double largest = 0;
        for (int step = 0; step < steps; ++step) {
            integrate(world, dt);
            largest = std::max(largest, (world.bodies[0].transform.position - setup.anchor).cast<double>().norm());
        }
        return largest / setup.offset.norm();
    };
    // Below the limit the amplitude stays bounded (the discrete orbit is an ellipse that
    // stretches as h w approaches 2)...
    for (double hOmega : {0.5, 1.0, 1.5, 1.9}) {
        INFO("h w = " << hOmega);
        CHECK(growth(hOmega, 5000) < 20);
    }
    // ... above it one eigenvalue of the step has modulus > 1: growth by ~1.9x per step at 2.1.
    for (double hOmega : {2.1, 2.5}) {
        INFO("h w = " << hOmega);
        CHECK(growth(hOmega, 60) > 1e6);
    }
}
