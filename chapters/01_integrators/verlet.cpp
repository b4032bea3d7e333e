// Velocity Verlet (Swope, Andersen, Berens & Wilson 1982), the "kick-drift-kick" form:
//   v_half = v0 + h/2 a(x0)          kick
//   x1     = x0 + h v_half           drift
//   v1     = v_half + h/2 a(x1)      kick
// Second order, symplectic and time-reversible for position-dependent forces, with two force
// evaluations per step (one when the last kick's forces are reused as the next step's first).
#include "01_integrators/methods.h"
#include "01_integrators/rotation.h"

namespace stepwise {

// [ch01-verlet]
void stepVerlet(const World& world, const std::vector<int>& members, Real h, StepBuffers& buffers) {
    const bool gyroscopic = world.settings.gyroscopic != GyroscopicMode::Off;
    const Real halfStep = Real(0.5) * h;
    buffers.trial = buffers.start;
    for (int i : members) {
        const Motion& motion = world.motions[i];
        const MotionState& start = buffers.start[i];
        const Acceleration a0 = accelerationAt(motion, start, buffers.startForces[i], gyroscopic);

        // Kick: half a step of acceleration.
        MotionState& half = buffers.next[i];
        half.linearVelocity = start.linearVelocity + halfStep * a0.linear;
        half.angularVelocity = start.angularVelocity + halfStep * a0.angular;

        // Drift: a whole step at the half-step velocities. For the orientation the drift is the
        // exact turn at constant angular velocity, the rotational twin of x0 + h v_half.
        MotionState& end = buffers.trial[i];
        end.center = start.center + h * half.linearVelocity;
        end.rotation = rotateExactly(start.rotation, half.angularVelocity, h);
        // Velocity-dependent forces (dashpots, drag) at the end need an end velocity; the Euler
        // guess v0 + h a0 is second-order accurate there, which keeps the method second order.
        end.linearVelocity = start.linearVelocity + h * a0.linear;
        end.angularVelocity = start.angularVelocity + h * a0.angular;
    }

    // Forces at the drifted positions, for every member at once (coupled springs see each other).
    evaluateStepForces(world, buffers.trial, buffers.trialForces);

    for (int i : members) {
        const Acceleration a1 = accelerationAt(world.motions[i], buffers.trial[i], buffers.trialForces[i], gyroscopic);
        MotionState& next = buffers.next[i];
        next.center = buffers.trial[i].center;
        next.rotation = buffers.trial[i].rotation;
        // Kick: the second half step of acceleration, at the new positions.
        next.linearVelocity += halfStep * a1.linear;
        next.angularVelocity += halfStep * a1.angular;
    }
}
// [ch01-verlet]

}  // namespace stepwise
