#pragma once
// The state an integrator advances and the forces that drive it. Chapter 1 has three force
// generators: gravity (Settings::gravity), springs (World::springs) and drag (World::dampings).
// They are evaluated at any candidate state, not only the world's current one, because RK4 and
// velocity Verlet need forces at states in the middle or at the end of a step.

#include "world/world.h"

#include <vector>

namespace stepwise {

/// What the integrators advance for one moving body. The integrators work on the centre of
/// mass (the point whose motion F = m a describes), not on the shape origin the Body stores.
struct MotionState {
    Vec3 center = Vec3::Zero();            // centre of mass, world frame, m
    Quat rotation = Quat::Identity();      // body to world, unit length
    Vec3 linearVelocity = Vec3::Zero();    // of the centre of mass, m/s
    Vec3 angularVelocity = Vec3::Zero();   // world frame, rad/s
};

/// A force through the centre of mass plus a torque about it (both world frame).
struct Wrench {
    Vec3 force = Vec3::Zero();             // N
    Vec3 torque = Vec3::Zero();            // N m
};

/// The state of one moving body as the world stores it now.
MotionState readMotionState(const World& world, const Motion& motion);

/// One state per Motion, indexed like World::motions.
void readMotionStates(const World& world, std::vector<MotionState>& states);

/// Stores a state: velocities into the Motion, and the body's origin recovered from the
/// centre of mass, origin = center - R * localCenter.
void writeMotionState(World& world, Motion& motion, const MotionState& state);

/// Inertia and its inverse in world axes at a given orientation: R I R^T and R I^-1 R^T.
Mat3 worldInertiaAt(const Motion& motion, const Quat& rotation);
Mat3 worldInverseInertiaAt(const Motion& motion, const Quat& rotation);

/// Gravity, spring and drag forces on every motion at the given states (one state and one
/// wrench per Motion). Kinematic bodies receive nothing: only their set velocities move them.
void evaluateForces(const World& world, const std::vector<MotionState>& states, std::vector<Wrench>& wrenches);

/// Time derivative of the velocities (the accelerations) of a dynamic body at a state, under a
/// wrench. With `gyroscopic` the angular part is Euler's equation with its gyroscopic term,
/// dw/dt = I^-1 (torque - w x I w); without it dw/dt = I^-1 torque.
struct Acceleration {
    Vec3 linear = Vec3::Zero();
    Vec3 angular = Vec3::Zero();
};
Acceleration accelerationAt(const Motion& motion, const MotionState& state, const Wrench& wrench, bool gyroscopic);

/// Angular momentum of a moving body about its centre of mass, I_world w (world frame).
Vec3 angularMomentum(const World& world, int bodyIndex);

}  // namespace stepwise
