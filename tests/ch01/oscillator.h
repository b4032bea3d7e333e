#pragma once
// Shared by the chapter 1 suites: the chapter's harmonic oscillator (01_integrators/oscillator.h)
// set up off the origin, and a least-squares slope for measured convergence orders.

#include "01_integrators/integrate.h"
#include "01_integrators/oscillator.h"
#include "support/fixture.h"

#include <cmath>
#include <vector>

namespace stepwise::test {

/// The suites' oscillator: off the origin, moving in all three axes, heavier than 1 kg, so no
/// term of the closed form is trivially zero.
struct OscillatorSetup : Oscillator {
    OscillatorSetup() {
        anchor = Vec3(1, 2, 3);
        offset = Vec3(Real(0.8), Real(-0.3), Real(0.5));
        velocity = Vec3(Real(1.5), Real(2.0), Real(-1.0));
        mass = 2;
    }
};

inline World makeOscillator(const Oscillator& setup, IntegratorKind method) {
    World world = makeWorld(zeroGravitySettings(), "oscillator");
    world.settings.integrator = method;
    addOscillator(world, setup);
    return world;
}

/// Position error at `duration` after `steps` equal steps of integrate().
inline double oscillatorError(const Oscillator& setup, IntegratorKind method, double duration, int steps) {
    World world = makeOscillator(setup, method);
    const Real dt = Real(duration / steps);
    for (int i = 0; i < steps; ++i) integrate(world, dt);
    return (world.bodies[0].transform.position.cast<double>() - setup.exactPosition(duration)).norm();
}

/// Least-squares slope of log(y) against log(x).
inline double logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        n += 1, sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

inline bool isDoubleBuild() { return sizeof(Real) == sizeof(double); }

}  // namespace stepwise::test
