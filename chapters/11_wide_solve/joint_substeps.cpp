// The joint pass in each of chapter 11's substeps: springs' and drag's forces at the substep's
// state, the warm start, the sweeps, what the move did to the rows' errors, and the impulses
// stored for the next frame (joint_pass.cpp builds the rows).
#include "11_wide_solve/joint_pass.h"

#include "01_integrators/integrate.h"
#include "11_wide_solve/solve_steps.h"

namespace stepwise {

void advanceJointErrors(JointPass& pass, const SolverBodyState* states, Real h) {
    advancePackedErrors(pass.packed, states, h);
}

void warmStartJoints(JointPass& pass, SolverBodyState* states, bool warmStarting) {
    if (pass.packed.joints.empty()) return;
    if (!warmStarting) {  // every substep from zero, as the contacts
        resetPackedImpulses(pass.packed, pass.carried);
        return;
    }
    warmStartPacked(pass.packed, states);
}

void solveJoints(JointPass& pass, SolverBodyState* states, bool relax) { solvePacked(pass.packed, states, relax); }

void keepJointImpulses(JointPass& pass) { keepPackedImpulses(pass.packed, pass.carried); }

void storeJointImpulses(const JointPass& pass, World& world) {
    world.jointImpulses.resize(world.joints.size());
    for (std::size_t i = 0; i < pass.joints.size(); ++i)
        world.jointImpulses[static_cast<std::size_t>(pass.joints[i])] = pass.carried[i];
}

void evaluateSubstepForces(const World& world, const SolverBodies& bodies, JointPass& pass) {
    pass.forceStates.resize(world.motions.size());
    for (std::size_t i = 0; i < world.motions.size(); ++i) {
        const Motion& motion = world.motions[i];
        const int slot = bodies.slotOfBody[static_cast<std::size_t>(motion.bodyIndex)];
        MotionState& state = pass.forceStates[i];
        if (slot == 0) {
            state = readMotionState(world, motion);
            continue;
        }
        const SlotPose now = slotPose(bodies, slot);
        const SolverBodyState& velocity = bodies.states[static_cast<std::size_t>(slot)];
        state.center = now.center;
        state.rotation = now.rotation;
        state.linearVelocity = Vec3(velocity.linearVelocity[0], velocity.linearVelocity[1], velocity.linearVelocity[2]);
        state.angularVelocity = Vec3(velocity.angularVelocity[0], velocity.angularVelocity[1], velocity.angularVelocity[2]);
    }
    evaluateForces(world, pass.forceStates, pass.forces);
}

}  // namespace stepwise
