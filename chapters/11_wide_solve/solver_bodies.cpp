// Chapter 11's solver bodies: the moving bodies gathered into slots once per frame, integrated
// every substep, written back at the end.
#include "11_wide_solve/solve_steps.h"

#include "01_integrators/forces.h"
#include "01_integrators/integrate.h"
#include "01_integrators/methods.h"
#include "01_integrators/rotation.h"
#include "06_manifolds/stabilisation.h"
#include "11_wide_solve/gyroscopic_pack.h"
#include "11_wide_solve/body_pack.h"
#include "11_wide_solve/wide_solver.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

// [ch11-prepare-bodies]
namespace {

void addSlot(const World& world, const Motion& motion, SolverBodies& bodies) {
    const Body& body = world.bodies[static_cast<std::size_t>(motion.bodyIndex)];
    const bool dynamic = body.type == BodyType::Dynamic;
    bodies.slotOfBody[static_cast<std::size_t>(motion.bodyIndex)] = static_cast<int>(bodies.states.size());
    SolverBodyState state;
    for (int k = 0; k < 3; ++k) {
        state.linearVelocity[k] = motion.linearVelocity[k];
        state.angularVelocity[k] = motion.angularVelocity[k];
    }
    bodies.states.push_back(state);
    SolverBodyInfo info;
    info.bodyIndex = motion.bodyIndex;
    info.inverseMass = dynamic ? motion.inverseMass : Real(0);  // a kinematic body: infinitely heavy
    info.inverseInertia = dynamic ? worldInverseInertia(body, motion) : Mat3::Zero();
    info.startCenter = body.transform.apply(motion.localCenter);
    info.startRotation = body.transform.rotation;
    const Mat3& inertia = motion.inertiaLocal;
    if (dynamic && !(inertia - Mat3::Identity() * inertia(0, 0)).isZero(0)) {
        const Quat& start = info.startRotation;
        bodies.gyroscopic.push_back(GyroscopicBody{
            {start.x(), start.y(), start.z(), start.w()},
            {inertia(0, 0), inertia(1, 1), inertia(2, 2), inertia(0, 1), inertia(0, 2), inertia(1, 2)},
            static_cast<int>(bodies.info.size())});
    }
    bodies.info.push_back(info);
}

}  // namespace

void prepareBodies(const World& world, SolverBodies& bodies) {
    bodies.states.assign(1, SolverBodyState{});  // slot 0: everything that does not move
    bodies.info.assign(1, SolverBodyInfo{});
    bodies.slotOfBody.assign(world.bodies.size(), 0);
    bodies.gyroscopic.clear();
    // The kinematic bodies first: below firstDynamic, a slot is one no row can push.
    for (const Motion& motion : world.motions)
        if (world.bodies[static_cast<std::size_t>(motion.bodyIndex)].type == BodyType::Kinematic && !motion.asleep)
            addSlot(world, motion, bodies);
    bodies.firstDynamic = static_cast<int>(bodies.states.size());
    for (const Motion& motion : world.motions)
        if (world.bodies[static_cast<std::size_t>(motion.bodyIndex)].type == BodyType::Dynamic && !motion.asleep)
            addSlot(world, motion, bodies);
}
// [ch11-prepare-bodies]

ContactSolveParams solveParams(const Settings& settings, Real h, Real frame) {
    ContactSolveParams params;
    params.substep = h;
    params.slop = settings.slop;
    params.maxPushOutSpeed = settings.maxPushOutSpeed;
    params.restitutionThreshold = settings.restitutionThreshold;
    params.mostSpin = mostSpin(h, frame);
    if (settings.stabilisation == Stabilisation::SoftStep) {
        // Chapter 6's soft contacts: Box2D v3's 30 Hz (at most a quarter of the substep rate),
        // twice as stiff against a body that cannot move.
        const Real hertz = std::min(settings.contactHertz, Real(0.25) / h);
        const Softness dynamicSoft = makeSoftness(hertz, settings.contactDampingRatio, h);
        const Softness staticSoft = makeSoftness(2 * hertz, settings.contactDampingRatio, h);
        params.dynamicBiasRate = dynamicSoft.biasRate;
        params.dynamicMassScale = dynamicSoft.massScale;
        params.dynamicImpulseScale = dynamicSoft.impulseScale;
        params.staticBiasRate = staticSoft.biasRate;
        params.staticMassScale = staticSoft.massScale;
        params.staticImpulseScale = staticSoft.impulseScale;
    } else {  // relax: rigid rows, Baumgarte's fraction per frame (chapter 6's relaxFeedback)
        params.dynamicBiasRate = params.staticBiasRate = relaxFeedback(settings, h, frame) / h;
    }
    return params;
}

void integrateVelocities(World& world, SolverBodies& bodies, Real h, bool firstSubstep, SolverPath path,
                         const std::vector<Wrench>* forces) {
    const Vec3 gravity = world.settings.gravity;
    // Chapter 1's order: the gyroscopic step, then the torque (each body's own; bodies do not interact here).
    if (world.settings.gyroscopic == GyroscopicMode::Implicit) {
        if (path == SolverPath::Wide) {
            gyroscopicStepWide(bodies.states.data(), bodies.gyroscopic, h);
        } else {
            for (const GyroscopicBody& body : bodies.gyroscopic) gyroscopicStepPack<1>(bodies.states.data(), &body, h);
        }
    }
    if (!forces && !firstSubstep) {  // most substeps: gravity alone, the same h g for every body
        const Real step[3] = {h * gravity[0], h * gravity[1], h * gravity[2]};
        for (std::size_t slot = static_cast<std::size_t>(bodies.firstDynamic); slot < bodies.states.size(); ++slot)
            for (int k = 0; k < 3; ++k) bodies.states[slot].linearVelocity[k] += step[k];
        return;
    }
    for (std::size_t slot = static_cast<std::size_t>(bodies.firstDynamic); slot < bodies.states.size(); ++slot) {
        SolverBodyState& state = bodies.states[slot];
        const SolverBodyInfo& info = bodies.info[slot];
        Vec3 acceleration = gravity;
        if (forces) {  // springs and drag too: chapter 1's forces at this substep's state, gravity among them
            const Wrench& wrench = (*forces)[world.bodies[static_cast<std::size_t>(info.bodyIndex)].motionIndex];
            acceleration = info.inverseMass * wrench.force;
            const Vec3 spin = h * (info.inverseInertia * wrench.torque);
            for (int k = 0; k < 3; ++k) state.angularVelocity[k] += spin[k];
        }
        if (firstSubstep) {  // a user's push, held for the frame's first substep as chapter 6 does
            Motion& motion = *world.motionOf(info.bodyIndex);
            acceleration += info.inverseMass * motion.force;
            const Vec3 spin = h * (info.inverseInertia * motion.torque);
            for (int k = 0; k < 3; ++k) state.angularVelocity[k] += spin[k];
            motion.force = motion.torque = Vec3::Zero();
        }
        for (int k = 0; k < 3; ++k) state.linearVelocity[k] += h * acceleration[k];
    }
}

Real mostSpin(Real h, Real solveTime) { return std::min(kMostTurnPerSubstep / h, kMostTurnPerSolve / solveTime); }

// The position step's rule (holdSpinPack) a body at a time, on both paths, before either, so that
// the wide and the scalar path agree.
void holdSpin(SolverBodies& bodies, Real most) {
    const Pack<1> dynamic = Pack<1>::splat(1);
    for (std::size_t slot = static_cast<std::size_t>(std::max(bodies.firstDynamic, 1)); slot < bodies.states.size(); ++slot) {
        Real* w = bodies.states[slot].angularVelocity;
        PackVec3<1> spin{Pack<1>::splat(w[0]), Pack<1>::splat(w[1]), Pack<1>::splat(w[2])};
        holdSpinPack(spin, dynamic, most);
        w[0] = spin.x[0], w[1] = spin.y[0], w[2] = spin.z[0];
    }
}

void integratePositions(SolverBodies& bodies, Real h, Real mostSpin, SolverPath path) {
    const int count = static_cast<int>(bodies.states.size());
    if (path == SolverPath::Wide) return integratePositionsWide(bodies.states.data(), count, h, mostSpin, bodies.firstDynamic);
    for (int slot = 1; slot < count; ++slot)
        integratePositionsPack<1>(bodies.states.data(), &slot, h, mostSpin, bodies.firstDynamic);
}

SlotPose slotPose(const SolverBodies& bodies, int slot) {
    const SolverBodyState& state = bodies.states[static_cast<std::size_t>(slot)];
    const SolverBodyInfo& info = bodies.info[static_cast<std::size_t>(slot)];
    const Quat delta(state.deltaRotation[3], state.deltaRotation[0], state.deltaRotation[1], state.deltaRotation[2]);
    return {info.startCenter + Vec3(state.deltaPosition[0], state.deltaPosition[1], state.deltaPosition[2]),
            (delta * info.startRotation).normalized()};
}

void writeBodiesBack(World& world, const SolverBodies& bodies) {
    for (std::size_t slot = 1; slot < bodies.states.size(); ++slot) {
        const SolverBodyState& state = bodies.states[slot];
        const SolverBodyInfo& info = bodies.info[slot];
        Motion& motion = *world.motionOf(info.bodyIndex);
        Transform& pose = world.bodies[static_cast<std::size_t>(info.bodyIndex)].transform;
        const SlotPose now = slotPose(bodies, static_cast<int>(slot));
        pose.rotation = now.rotation;
        pose.position = now.center - pose.rotation * motion.localCenter;
        motion.linearVelocity = Vec3(state.linearVelocity[0], state.linearVelocity[1], state.linearVelocity[2]);
        motion.angularVelocity = Vec3(state.angularVelocity[0], state.angularVelocity[1], state.angularVelocity[2]);
    }
}

/// Bodies that touch nothing, each through all the substeps at once: chapter 1's semi-implicit
/// Euler for the velocities and the turn, without gathering every body's state and forces again
/// each substep (which cost a one-body scene more than its integration), and the centre moved
/// along its exact parabola. The fast solve takes no springs, dampings or kinematic bodies, so
/// each body feels its weight and the user's force only, constant through the frame (a kinematic
/// body added since the plan takes chapter 1's functions).
void moveFreeBodies(World& world, Real h, int substeps) {
    const bool allDynamic = std::all_of(world.motions.begin(), world.motions.end(), [&](const Motion& motion) {
        return world.bodies[static_cast<std::size_t>(motion.bodyIndex)].type == BodyType::Dynamic;
    });
    if (!allDynamic) {
        for (int substep = 0; substep < substeps; ++substep) {
            applyForces(world);
            stepwise::integrateVelocities(world, h);
            stepwise::integratePositions(world, h);
        }
        return;
    }
    const GyroscopicMode gyroscopic = world.settings.gyroscopic;
    for (Motion& motion : world.motions) {
        const Body& body = world.bodies[static_cast<std::size_t>(motion.bodyIndex)];
        const Vec3 weight = motion.mass * world.settings.gravity;
        for (int substep = 0; substep < substeps; ++substep) {
            motion.force += weight;
            MotionState state = readMotionState(world, motion);
            const Vec3 velocityBefore = state.linearVelocity;
            eulerVelocityStep(motion, worldInverseInertia(body, motion), Wrench{motion.force, motion.torque}, gyroscopic,
                              h, state);
            motion.linearVelocity = state.linearVelocity;
            motion.angularVelocity = state.angularVelocity;
            motion.force = motion.torque = Vec3::Zero();
            eulerPositionStep(h, state);
            // [ch11-free-flight]
            // The force is the same all through the substep, so the centre's path is the parabola
            // x0 + v0 h + a h^2 / 2: it moves by the mean of the two velocities, where Euler's
            // step moved it by the new one, h (v1 - v0) / 2 too far. One substep is then exact.
            state.center -= (h / 2) * (state.linearVelocity - velocityBefore);
            // [ch11-free-flight]
            writeMotionState(world, motion, state);
        }
    }
}


}  // namespace stepwise
