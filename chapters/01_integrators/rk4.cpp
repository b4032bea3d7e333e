// Classical fourth-order Runge-Kutta for the rigid-body ODE y' = f(t, y) with
// y = (x, q, v, w) and f = (v, 1/2 (0, w) q, F/m, I^-1 (torque - w x I w)):
//   k1 = f(y0)   k2 = f(y0 + h/2 k1)   k3 = f(y0 + h/2 k2)   k4 = f(y0 + h k3)
//   y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4)
// (Kutta 1901; any numerical analysis text, e.g. Hairer, Norsett & Wanner, Solving ODEs I, II.1).
// Forces are evaluated at each intermediate state of ALL bodies that use RK4 together: springs
// between them see both ends move, which is what makes the method fourth order for coupled
// systems. Bodies on other methods are held at their start-of-step state meanwhile.
#include "01_integrators/methods.h"
#include "01_integrators/rotation.h"

namespace stepwise {

namespace {

// f(y) at a stage. RK4 is defined on the raw stage values, so the quaternion's rate comes from
// the raw stage quaternion (dq/dt is linear in q), while forces and inertia use its normalised
// copy: RK4 then integrates the smooth ODE f(q / |q|), which equals the true one on unit
// quaternions, and only the final result is projected back onto them.
StateRate rateAt(const Motion& motion, const MotionState& state, const Quat& rawRotation, const Wrench& wrench,
                 bool gyroscopic) {
    const Acceleration acceleration = accelerationAt(motion, state, wrench, gyroscopic);
    StateRate rate;
    rate.center = state.linearVelocity;
    rate.rotation = quaternionDerivative(rawRotation, state.angularVelocity);
    rate.linearVelocity = acceleration.linear;
    rate.angularVelocity = acceleration.angular;
    return rate;
}

// y0 + h k. `rawRotation` receives the quaternion before normalisation.
MotionState advance(const MotionState& start, const StateRate& rate, Real h, Quat& rawRotation) {
    MotionState state;
    state.center = start.center + h * rate.center;
    rawRotation.coeffs() = start.rotation.coeffs() + h * rate.rotation.coeffs();
    state.rotation = rawRotation.normalized();
    state.linearVelocity = start.linearVelocity + h * rate.linearVelocity;
    state.angularVelocity = start.angularVelocity + h * rate.angularVelocity;
    return state;
}

}  // namespace

// [ch01-rk4]
void stepRk4(const World& world, const std::vector<int>& members, Real h, StepBuffers& buffers) {
    const bool gyroscopic = world.settings.gyroscopic != GyroscopicMode::Off;
    const size_t count = members.size();
    for (std::vector<StateRate>& slope : buffers.slopes) slope.resize(count);
    buffers.rawRotations.resize(count);

    // k1 from the start state, whose forces the caller already evaluated.
    for (size_t m = 0; m < count; ++m) {
        const int i = members[m];
        buffers.slopes[0][m] = rateAt(world.motions[i], buffers.start[i], buffers.start[i].rotation,
                                        buffers.startForces[i], gyroscopic);
    }

    // k2, k3, k4: move every member to its trial state, then evaluate all forces there.
    const Real stageOffsets[3] = {Real(0.5) * h, Real(0.5) * h, h};
    buffers.trial = buffers.start;
    for (int stage = 1; stage < 4; ++stage) {
        for (size_t m = 0; m < count; ++m) {
            const int i = members[m];
            buffers.trial[i] = advance(buffers.start[i], buffers.slopes[stage - 1][m], stageOffsets[stage - 1],
                                       buffers.rawRotations[m]);
        }
        evaluateStepForces(world, buffers.trial, buffers.trialForces);
        for (size_t m = 0; m < count; ++m) {
            const int i = members[m];
            buffers.slopes[stage][m] = rateAt(world.motions[i], buffers.trial[i], buffers.rawRotations[m],
                                              buffers.trialForces[i], gyroscopic);
        }
    }

    // The weighted mean slope, 1/6 (k1 + 2 k2 + 2 k3 + k4).
    for (size_t m = 0; m < count; ++m) {
        const StateRate& k1 = buffers.slopes[0][m];
        const StateRate& k2 = buffers.slopes[1][m];
        const StateRate& k3 = buffers.slopes[2][m];
        const StateRate& k4 = buffers.slopes[3][m];
        StateRate mean;
        mean.center = (k1.center + 2 * k2.center + 2 * k3.center + k4.center) / 6;
        mean.rotation.coeffs() =
            (k1.rotation.coeffs() + 2 * k2.rotation.coeffs() + 2 * k3.rotation.coeffs() + k4.rotation.coeffs()) / 6;
        mean.linearVelocity =
            (k1.linearVelocity + 2 * k2.linearVelocity + 2 * k3.linearVelocity + k4.linearVelocity) / 6;
        mean.angularVelocity =
            (k1.angularVelocity + 2 * k2.angularVelocity + 2 * k3.angularVelocity + k4.angularVelocity) / 6;
        const int i = members[m];
        buffers.next[i] = advance(buffers.start[i], mean, h, buffers.rawRotations[m]);
    }
}
// [ch01-rk4]

}  // namespace stepwise
