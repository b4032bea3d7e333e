#pragma once
// Orientation updates and the gyroscopic term. A rigid body's orientation q (body to world)
// changes as dq/dt = 1/2 (0, w) q with w the world-frame angular velocity; Euler's equation
// I dw/dt = torque - w x I w holds the gyroscopic term that makes spinning bodies precess and
// tumble (the Dzhanibekov effect).

#include "math/math.h"

namespace stepwise {

// The three small steps below are defined here, inline, because chapter 10's solver calls the
// rotation step for every body on every substep: a call across files would cost more than the step.

/// dq/dt = 1/2 (0, w) q, as quaternion coefficients (not a unit quaternion).
inline Quat quaternionDerivative(const Quat& rotation, const Vec3& angularVelocity) {
    const Quat spin(0, angularVelocity.x(), angularVelocity.y(), angularVelocity.z());
    Quat derivative = spin * rotation;
    derivative.coeffs() *= Real(0.5);
    return derivative;
}

/// q + h * derivative, renormalised.
inline Quat addScaledDerivative(const Quat& rotation, const Quat& derivative, Real h) {
    Quat result;
    result.coeffs() = rotation.coeffs() + h * derivative.coeffs();
    // A unit quaternion moved along its tangent leaves the unit sphere by O(h^2); projecting
    // back keeps it a rotation. The norm is ~1, never 0, for any finite step.
    result.normalize();
    return result;
}

// [ch01-quaternion-update]
/// One first-order step q + h/2 (0, w) q, renormalised. What semi-implicit Euler uses.
inline Quat integrateRotation(const Quat& rotation, const Vec3& angularVelocity, Real h) {
    // q1 = q0 + h dq/dt = q0 + h/2 (0, w) q0, then back onto the unit sphere. First order,
    // as accurate as the Euler step around it, and cheap: no trigonometry.
    return addScaledDerivative(rotation, quaternionDerivative(rotation, angularVelocity), h);
}
// [ch01-quaternion-update]

/// The exact rotation for a constant angular velocity over h: exp(h w / 2) q.
Quat rotateExactly(const Quat& rotation, const Vec3& angularVelocity, Real h);

/// Explicit gyroscopic step: w - h I^-1 (w x I w), with I and I^-1 in world axes.
Vec3 gyroscopicStepExplicit(const Vec3& angularVelocity, const Mat3& worldInertia, const Mat3& worldInverseInertia,
                            Real h);

/// Catto's implicit gyroscopic step ("Numerical Methods", GDC 2015; also Bullet's
/// computeGyroscopicImpulseImplicit_Body): one Newton step on backward Euler,
/// I (w1 - w0) + h w1 x I w1 = 0, in body axes where I is constant. Unconditionally stable but
/// dissipative: each step shrinks |L| by O((h |w x L| / |L|)^2).
Vec3 gyroscopicStepBackwardEuler(const Vec3& angularVelocity, const Quat& rotation, const Mat3& inertiaLocal, Real h);

/// The implicit gyroscopic step GyroscopicMode::Implicit uses: Catto's one Newton step, applied
/// to the implicit midpoint rule I (w1 - w0) + h m x I m = 0, m = (w0 + w1) / 2, then rescaled
/// to the old |L|. Keeps |L| and the rotational energy to round-off at any step size.
Vec3 gyroscopicStepImplicit(const Vec3& angularVelocity, const Quat& rotation, const Mat3& inertiaLocal, Real h);

}  // namespace stepwise
