#pragma once
// The three integrators as steps over a group of bodies (private to chapter 1; the public entry
// points are in integrate.h). Every method reads the start-of-step states and writes the
// end-of-step states of its own group only, so the groups do not depend on their order.

#include "01_integrators/forces.h"

#include <vector>

namespace stepwise {

/// The time derivative of a MotionState: (dx/dt, dq/dt, dv/dt, dw/dt).
struct StateRate {
    Vec3 center = Vec3::Zero();
    Quat rotation = Quat(0, 0, 0, 0);   // not a unit quaternion: a tangent
    Vec3 linearVelocity = Vec3::Zero();
    Vec3 angularVelocity = Vec3::Zero();
};

/// Buffers one step needs, one entry per Motion; kept between steps so stepping allocates nothing.
struct StepBuffers {
    std::vector<MotionState> start;   // the state at the beginning of the step
    std::vector<Wrench> startForces;  // generators at `start` plus the held Motion::force/torque
    std::vector<MotionState> next;    // the state at the end of the step
    std::vector<MotionState> trial;   // an intermediate state (RK4 stages, Verlet's end point)
    std::vector<Wrench> trialForces;
    std::vector<StateRate> slopes[4];  // RK4's k1..k4, one per group member
    std::vector<Quat> rawRotations;    // RK4 stage quaternions before normalisation
    std::vector<int> verletGroup;      // motion indices of the bodies each method advances
    std::vector<int> rk4Group;
};

/// Generators at `states` plus the forces a user put into Motion::force/torque.
void evaluateStepForces(const World& world, const std::vector<MotionState>& states, std::vector<Wrench>& wrenches);

/// Semi-implicit Euler: velocities first, then positions with the new velocities.
void eulerVelocityStep(const Motion& motion, const Mat3& worldInverseInertia, const Wrench& wrench,
                       GyroscopicMode gyroscopic, Real h, MotionState& state);
void eulerPositionStep(Real h, MotionState& state);

/// Velocity Verlet for the dynamic bodies in `members` (motion indices).
void stepVerlet(const World& world, const std::vector<int>& members, Real h, StepBuffers& buffers);

/// Classical RK4 for the dynamic bodies in `members`, advanced as one coupled system.
void stepRk4(const World& world, const std::vector<int>& members, Real h, StepBuffers& buffers);

}  // namespace stepwise
