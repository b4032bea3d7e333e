#pragma once
// The harmonic oscillator every integrator in this chapter is measured against: a body on a
// zero-rest-length spring to a fixed anchor, without gravity, whose motion has the closed form
//   x(t) = anchor + d0 cos(w t) + (v0 / w) sin(w t),   w = sqrt(k / m).
// The convergence bench and the chapter's suites build it here, so they measure the same thing.

#include "world/world.h"

namespace stepwise {

struct Oscillator {
    double omega = 2 * 3.14159265358979323846;   // rad/s
    Vec3 anchor = Vec3::Zero();
    Vec3 offset = Vec3::UnitX();                 // d0: initial displacement from the anchor, m
    Vec3 velocity = Vec3::Zero();                // v0: initial velocity, m/s
    Real mass = 1;                               // kg

    Eigen::Vector3d exactPosition(double t) const;
};

/// Adds the oscillator's body (a small sphere) and its spring (k = m w^2) to a world; gravity
/// stays the caller's (set it to zero for the closed form to hold). Returns the body index.
int addOscillator(World& world, const Oscillator& oscillator);

}  // namespace stepwise
