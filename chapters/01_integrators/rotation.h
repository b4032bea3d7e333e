#pragma once
// Orientation updates and the gyroscopic term. A rigid body's orientation q (body to world)
// changes as dq/dt = 1/2 (0, w) q with w the world-frame angular velocity; Euler's equation
// I dw/dt = torque - w x I w holds the gyroscopic term that makes spinning bodies precess and
// tumble (the Dzhanibekov effect).

#include "math/math.h"

#include <cmath>
#include <limits>

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

// [ch01-turn-series]
/// Above this (h |w| / 2)^2 the series below are not used: a turn of more than 4 rad in one step.
constexpr Real kTurnSeriesLimit = 4;

/// cos x and sin(x) / x from y = x^2, by their Taylor series to x^12 (Horner, highest term
/// first): within 2e-7 of the true values for y <= kTurnSeriesLimit, and no square root is needed
/// to get x. `splat` makes a T from a Real, so chapter 10 runs the same arithmetic on eight lanes.
template <class T, class Splat>
inline void turnSeries(const T& y, Splat splat, T& cosine, T& sineRatio) {
    constexpr Real kCosine[] = {Real(1.0 / 479001600), Real(-1.0 / 3628800), Real(1.0 / 40320), Real(-1.0 / 720),
                                Real(1.0 / 24),        Real(-1.0 / 2),       Real(1)};
    constexpr Real kSineRatio[] = {Real(1.0 / 6227020800.0), Real(-1.0 / 39916800), Real(1.0 / 362880), Real(-1.0 / 5040),
                                   Real(1.0 / 120),          Real(-1.0 / 6),        Real(1)};
    cosine = splat(kCosine[0]);
    sineRatio = splat(kSineRatio[0]);
    for (int k = 1; k < 7; ++k) {
        cosine = cosine * y + splat(kCosine[k]);
        sineRatio = sineRatio * y + splat(kSineRatio[k]);
    }
}
// [ch01-turn-series]

// [ch01-turn-rotation]
/// The rotation step the pipeline uses: the exact turn by h |w| about w, exp(h w / 2) q, written
/// as cos(x) q + h sin(x)/x (1/2 (0, w) q) with x = h |w| / 2, then renormalised against round-off.
/// It is integrateRotation's step with the angle put right: the first-order step turns by
/// 2 atan(h |w| / 2), short by (h |w|)^3 / 12 a step (a brick spinning at 10 rad/s lags 2.6 degrees
/// after 2 s at 60 Hz), where this one is exact for a steady spin.
inline Quat turnRotation(const Quat& rotation, const Vec3& angularVelocity, Real h) {
    const Real halfStep = Real(0.5) * h;
    const Real y = halfStep * halfStep * angularVelocity.squaredNorm();
    Real cosine = 1, sineRatio = 1;
    if (y <= kTurnSeriesLimit) {
        turnSeries(y, [](Real value) { return value; }, cosine, sineRatio);
    } else if (y < std::numeric_limits<Real>::infinity()) {  // a spin too fast for the series
        const Real x = std::sqrt(y);
        cosine = math::cos(x);
        sineRatio = math::sin(x) / x;
    }  // else not finite: the first-order step, whose result the solver's checks catch
    const Quat derivative = quaternionDerivative(rotation, angularVelocity);
    Quat result;
    result.coeffs() = cosine * rotation.coeffs() + (h * sineRatio) * derivative.coeffs();
    result.normalize();
    return result;
}
// [ch01-turn-rotation]

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
