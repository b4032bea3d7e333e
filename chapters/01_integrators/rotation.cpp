#include "01_integrators/rotation.h"

namespace stepwise {

namespace {

// Solves m x = b for a 3x3 m by its closed-form inverse (far cheaper than a pivoting LU at this
// size). False when m is singular relative to its own scale, e.g. a body without inertia.
bool solve3(const Mat3& m, const Vec3& b, Vec3& x) {
    const Real determinant = m.determinant();
    const Real scale = m.cwiseAbs().maxCoeff();
    if (!(std::abs(determinant) > 16 * kEpsilon * scale * scale * scale)) return false;
    x = m.inverse() * b;
    return true;
}

}  // namespace


// [ch01-exact-rotation]
Quat rotateExactly(const Quat& rotation, const Vec3& angularVelocity, Real h) {
    // For constant w the orientation turns by the angle h |w| about w / |w|.
    const Real speed = angularVelocity.norm();
    if (!(speed * h > Real(1e-12))) return rotation;
    const Quat turn(angleAxis(speed * h, angularVelocity / speed));
    return (turn * rotation).normalized();
}
// [ch01-exact-rotation]

Vec3 gyroscopicStepExplicit(const Vec3& angularVelocity, const Mat3& worldInertia, const Mat3& worldInverseInertia,
                            Real h) {
    return angularVelocity - h * (worldInverseInertia * angularVelocity.cross(worldInertia * angularVelocity));
}

// [ch01-gyroscopic-backward-euler]
Vec3 gyroscopicStepBackwardEuler(const Vec3& angularVelocity, const Quat& rotation, const Mat3& inertiaLocal, Real h) {
    // Body axes: the inertia tensor is constant there.
    const Vec3 omega0 = rotation.conjugate() * angularVelocity;

    // Residual of backward Euler, f(w) = I (w - w0) + h w x (I w), at the first guess w = w0.
    const Vec3 residual = h * omega0.cross(inertiaLocal * omega0);

    // Jacobian df/dw = I + h ([w]x I - [I w]x).
    const Mat3 jacobian = inertiaLocal + h * (skew(omega0) * inertiaLocal - skew(inertiaLocal * omega0));

    // One Newton step, w1 = w0 - J^-1 f(w0). A body without inertia has nothing to solve.
    Vec3 correction;
    if (!solve3(jacobian, residual, correction)) return angularVelocity;
    return rotation * (omega0 - correction);
}
// [ch01-gyroscopic-backward-euler]

// [ch01-gyroscopic-implicit]
Vec3 gyroscopicStepImplicit(const Vec3& angularVelocity, const Quat& rotation, const Mat3& inertiaLocal, Real h) {
    if (angularVelocity == Vec3::Zero()) return angularVelocity;  // the common case of a body at rest
    const Vec3 omega0 = rotation.conjugate() * angularVelocity;
    const Vec3 momentum0 = inertiaLocal * omega0;

    // Implicit midpoint: f(w) = I (w - w0) + h m x (I m) with m = (w0 + w) / 2. At w = w0 the
    // residual is the same as backward Euler's; only the Jacobian halves:
    // df/dw = I + h/2 ([m]x I - [I m]x).
    const Vec3 residual = h * omega0.cross(momentum0);
    const Mat3 jacobian = inertiaLocal + (h / 2) * (skew(omega0) * inertiaLocal - skew(momentum0));
    Vec3 correction;
    if (!solve3(jacobian, residual, correction)) return angularVelocity;
    Vec3 omega1 = omega0 - correction;

    // This one Newton step keeps the ratio energy / |L|^2 exactly (the suite checks it), so it
    // only errs in the overall scale of w. Rescaling to the old |L| removes that error: both
    // invariants of torque-free motion are then kept to round-off, at any step size (projection
    // onto a first integral, Hairer, Lubich & Wanner, Geometric Numerical Integration, IV.4).
    const Real momentum1 = (inertiaLocal * omega1).norm();
    if (momentum1 > 0) omega1 *= momentum0.norm() / momentum1;

    return rotation * omega1;
}
// [ch01-gyroscopic-implicit]

}  // namespace stepwise
