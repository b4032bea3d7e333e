#pragma once
// Chapter 1: time integration of rigid bodies. Three integrators advance the full state
// (centre of mass, orientation, linear and angular velocity):
//   semi-implicit (symplectic) Euler   first order, symplectic, one force evaluation: the default
//   velocity Verlet                    second order, symplectic, two force evaluations
//   classical Runge-Kutta (RK4)        fourth order, not symplectic, four force evaluations
// Static bodies have no Motion and are never touched. Kinematic bodies move by their set
// velocities only. Each body may override Settings::integrator through Motion::integrator.

#include "world/world.h"

#include <string>

namespace stepwise {

/// Adds the force generators' forces and torques (gravity, springs, dampings) at the current
/// state to Motion::force and Motion::torque. Anything already there (a user's push) stays.
void applyForces(World& world);

/// First half of semi-implicit Euler for every moving body, whatever its integrator:
/// v += h F / m, w += h I^-1 torque (plus the gyroscopic step of Settings::gyroscopic).
/// Consumes Motion::force and Motion::torque (zeroes them). Kinematic velocities are kept.
void integrateVelocities(World& world, Real dt);

/// Second half: x += h v and q += h/2 (0, w) q for dynamic bodies (using the new velocities);
/// kinematic bodies move exactly along their set velocities.
void integratePositions(World& world, Real dt);

/// One full step with each body's own integrator. Forces come from the generators, evaluated
/// wherever the method needs them, plus whatever Motion::force/torque holds (held constant over
/// the step, then zeroed). Bodies that use RK4 are advanced together as one system.
/// A step with dt <= 0 or a non-finite dt changes nothing.
void integrate(World& world, Real dt);

/// The integrator a body uses: its override, else the world's setting.
IntegratorKind integratorOf(const World& world, const Motion& motion);

/// The method the dynamic bodies use ("semi_implicit_euler", "rk4", "verlet"), "mixed" when
/// they use more than one, and the world's setting when there is no dynamic body.
std::string integratorLabel(const World& world);

}  // namespace stepwise
