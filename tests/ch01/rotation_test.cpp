// Free rotation: the gyroscopic term and the Dzhanibekov (tennis racket) flip. A box with three
// distinct moments of inertia spun about its intermediate axis is unstable: a tiny wobble grows
// until the body turns over, again and again, while its angular momentum L stays fixed in space.
#include "01_integrators/chapter.h"
#include "01_integrators/forces.h"
#include "01_integrators/integrate.h"
#include "01_integrators/scenes.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

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
