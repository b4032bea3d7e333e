#include "01_integrators/integrate.h"

#include "01_integrators/methods.h"
#include "01_integrators/rotation.h"

#include <set>

namespace stepwise {

namespace {

bool isDynamic(const World& world, const Motion& motion) {
    return world.bodies[motion.bodyIndex].type == BodyType::Dynamic;
}

// World is plain data owned by common/, so the step's scratch memory lives here, one set per
// thread, and keeps its capacity from step to step.
StepBuffers& stepBuffers() {
    thread_local StepBuffers buffers;
    return buffers;
}

// A kinematic body follows its set velocities exactly: straight line, steady turn.
void kinematicStep(Real h, MotionState& state) {
    state.center += h * state.linearVelocity;
    state.rotation = rotateExactly(state.rotation, state.angularVelocity, h);
}

}  // namespace

void evaluateStepForces(const World& world, const std::vector<MotionState>& states, std::vector<Wrench>& wrenches) {
    evaluateForces(world, states, wrenches);
    for (size_t i = 0; i < world.motions.size(); ++i) {
        if (!isDynamic(world, world.motions[i])) continue;
        wrenches[i].force += world.motions[i].force;
        wrenches[i].torque += world.motions[i].torque;
    }
}

void applyForces(World& world) {
    StepBuffers& buffers = stepBuffers();
    readMotionStates(world, buffers.start);
    evaluateForces(world, buffers.start, buffers.startForces);
    for (size_t i = 0; i < world.motions.size(); ++i) {
        world.motions[i].force += buffers.startForces[i].force;
        world.motions[i].torque += buffers.startForces[i].torque;
    }
}

// [ch01-semi-implicit-euler]
void eulerVelocityStep(const Motion& motion, const Mat3& worldInverseInertia, const Wrench& wrench,
                       GyroscopicMode gyroscopic, Real h, MotionState& state) {
    // v1 = v0 + h F / m
    state.linearVelocity += h * motion.inverseMass * wrench.force;

    // w1 = w0 + h I^-1 (torque - w x I w): the gyroscopic part first (explicitly, implicitly
    // or not at all), then the torque.
    if (gyroscopic == GyroscopicMode::Explicit) {
        const Mat3 worldInertia = worldInertiaAt(motion, state.rotation);
        state.angularVelocity = gyroscopicStepExplicit(state.angularVelocity, worldInertia, worldInverseInertia, h);
    } else if (gyroscopic == GyroscopicMode::Implicit) {
        state.angularVelocity = gyroscopicStepImplicit(state.angularVelocity, state.rotation, motion.inertiaLocal, h);
    }
    state.angularVelocity += h * (worldInverseInertia * wrench.torque);
}

void eulerPositionStep(Real h, MotionState& state) {
    // The positions move with the NEW velocities: x1 = x0 + h v1. This one choice (instead of
    // x1 = x0 + h v0) makes the method symplectic.
    state.center += h * state.linearVelocity;
    state.rotation = turnRotation(state.rotation, state.angularVelocity, h);
}
// [ch01-semi-implicit-euler]

void integrateVelocities(World& world, Real dt) {
    if (!(dt > 0) || !isFinite(dt)) return;
    for (Motion& motion : world.motions) {
        if (isDynamic(world, motion)) {
            const Body& body = world.bodies[motion.bodyIndex];
            MotionState state = readMotionState(world, motion);
            const Wrench wrench{motion.force, motion.torque};
            eulerVelocityStep(motion, worldInverseInertia(body, motion), wrench, world.settings.gyroscopic, dt, state);
            motion.linearVelocity = state.linearVelocity;
            motion.angularVelocity = state.angularVelocity;
        }
        motion.force = Vec3::Zero();
        motion.torque = Vec3::Zero();
    }
}

void integratePositions(World& world, Real dt) {
    if (!(dt > 0) || !isFinite(dt)) return;
    for (Motion& motion : world.motions) {
        MotionState state = readMotionState(world, motion);
        if (isDynamic(world, motion))
            eulerPositionStep(dt, state);
        else
            kinematicStep(dt, state);
        writeMotionState(world, motion, state);
    }
}

// [ch01-integrate]
void integrate(World& world, Real dt) {
    if (!(dt > 0) || !isFinite(dt)) return;
    StepBuffers& buffers = stepBuffers();
    readMotionStates(world, buffers.start);
    evaluateStepForces(world, buffers.start, buffers.startForces);
    buffers.next = buffers.start;

    // Sort the moving bodies by method. Each method reads `start` and writes only its own
    // bodies' entries of `next`, so the order below does not matter.
    std::vector<int>& verletGroup = buffers.verletGroup;
    std::vector<int>& rk4Group = buffers.rk4Group;
    verletGroup.clear();
    rk4Group.clear();
    for (size_t i = 0; i < world.motions.size(); ++i) {
        const Motion& motion = world.motions[i];
        if (!isDynamic(world, motion)) {
            kinematicStep(dt, buffers.next[i]);
            continue;
        }
        switch (integratorOf(world, motion)) {
            case IntegratorKind::SemiImplicitEuler: {
                const Mat3 inverseInertia = worldInverseInertia(world.bodies[motion.bodyIndex], motion);
                eulerVelocityStep(motion, inverseInertia, buffers.startForces[i], world.settings.gyroscopic, dt,
                                  buffers.next[i]);
                eulerPositionStep(dt, buffers.next[i]);
                break;
            }
            case IntegratorKind::Verlet: verletGroup.push_back(static_cast<int>(i)); break;
            case IntegratorKind::Rk4: rk4Group.push_back(static_cast<int>(i)); break;
        }
    }
    if (!verletGroup.empty()) stepVerlet(world, verletGroup, dt, buffers);
    if (!rk4Group.empty()) stepRk4(world, rk4Group, dt, buffers);

    for (size_t i = 0; i < world.motions.size(); ++i) {
        writeMotionState(world, world.motions[i], buffers.next[i]);
        world.motions[i].force = Vec3::Zero();
        world.motions[i].torque = Vec3::Zero();
    }
}
// [ch01-integrate]

IntegratorKind integratorOf(const World& world, const Motion& motion) {
    return motion.integrator ? *motion.integrator : world.settings.integrator;
}

std::string integratorLabel(const World& world) {
    std::set<IntegratorKind> used;
    for (const Motion& motion : world.motions)
        if (isDynamic(world, motion)) used.insert(integratorOf(world, motion));
    if (used.empty()) return toString(world.settings.integrator);
    if (used.size() > 1) return "mixed";
    return toString(*used.begin());
}

}  // namespace stepwise
