#pragma once
// Shared by the chapter 1 suites: a body on a zero-rest-length spring to a world anchor,
// without gravity, which is a harmonic oscillator with a closed-form solution
//   x(t) = anchor + d0 cos(w t) + (v0 / w) sin(w t),  w = sqrt(k / m),
// and a least-squares slope for measured convergence orders.

#include "01_integrators/integrate.h"
#include "support/fixture.h"

#include <cmath>
#include <vector>

namespace stepwise::test {

struct OscillatorSetup {
    double omega = 2 * 3.14159265358979323846;   // rad/s
    Vec3 anchor = Vec3(1, 2, 3);
    Vec3 offset = Vec3(Real(0.8), Real(-0.3), Real(0.5));
    Vec3 velocity = Vec3(Real(1.5), Real(2.0), Real(-1.0));
    Real mass = 2;
};

inline World makeOscillator(const OscillatorSetup& setup, IntegratorKind method) {
    World world = makeWorld(zeroGravitySettings(), "oscillator");
    world.settings.integrator = method;
    const int body = addSphere(world, setup.anchor + setup.offset, Real(0.1), BodyType::Dynamic, setup.mass);
    setVelocity(world, body, setup.velocity);
    Spring spring;
    spring.bodyA = body;
    spring.anchorB = setup.anchor;
    spring.stiffness = Real(setup.omega * setup.omega * setup.mass);
    world.springs.push_back(spring);
    return world;
}

inline Eigen::Vector3d exactOscillatorPosition(const OscillatorSetup& setup, double t) {
    return setup.anchor.cast<double>() + setup.offset.cast<double>() * std::cos(setup.omega * t) +
           setup.velocity.cast<double>() * (std::sin(setup.omega * t) / setup.omega);
}

inline Eigen::Vector3d exactOscillatorVelocity(const OscillatorSetup& setup, double t) {
    return -setup.offset.cast<double>() * (setup.omega * std::sin(setup.omega * t)) +
           setup.velocity.cast<double>() * std::cos(setup.omega * t);
}

/// Position error at `duration` after `steps` equal steps of integrate().
inline double oscillatorError(const OscillatorSetup& setup, IntegratorKind method, double duration, int steps) {
    World world = makeOscillator(setup, method);
    const Real dt = Real(duration / steps);
    for (int i = 0; i < steps; ++i) integrate(world, dt);
    return (world.bodies[0].transform.position.cast<double>() - exactOscillatorPosition(setup, duration)).norm();
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
