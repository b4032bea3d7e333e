#pragma once
// The engine's number type and small geometric types, on top of Eigen.
// Real is float by default (what games ship); -DSTEPWISE_DOUBLE=ON switches the whole engine
// to double so the suites can check that nothing depends on the precision by accident.

#include "math/functions.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace stepwise {

#ifdef STEPWISE_DOUBLE
using Real = double;
#else
using Real = float;
#endif

using Vec3 = Eigen::Matrix<Real, 3, 1>;
using Mat3 = Eigen::Matrix<Real, 3, 3>;
using Quat = Eigen::Quaternion<Real>;

constexpr Real kPi = Real(3.14159265358979323846);
constexpr Real kDegree = kPi / 180;   // one degree in radians
constexpr Real kRealMax = std::numeric_limits<Real>::max();
constexpr Real kEpsilon = std::numeric_limits<Real>::epsilon();

#if defined(_MSC_VER)
#define STEPWISE_ALWAYS_INLINE __forceinline
#else
#define STEPWISE_ALWAYS_INLINE __attribute__((always_inline)) inline
#endif

/// q v q* for a unit q, operation for operation as Eigen's `q * v` (Quaternion::_transformVector),
/// so with the same bits; spelled out and always inlined here because compilers leave Eigen's out
/// of line in the contact cache's loops, and a call there costs as much as the turn.
STEPWISE_ALWAYS_INLINE Vec3 turnVector(const Quat& q, const Vec3& v) {
    const Vec3 axis = q.vec();
    Vec3 uv = axis.cross(v);
    uv += uv;
    return v + q.w() * uv + axis.cross(uv);
}

/// The same for q* v q (the inverse turn).
STEPWISE_ALWAYS_INLINE Vec3 turnVectorBack(const Quat& q, const Vec3& v) { return turnVector(q.conjugate(), v); }

/// A rigid transform: rotate, then translate. Maps body-local points to world points.
struct Transform {
    Vec3 position = Vec3::Zero();
    Quat rotation = Quat::Identity();

    STEPWISE_ALWAYS_INLINE Vec3 apply(const Vec3& local) const { return position + turnVector(rotation, local); }
    STEPWISE_ALWAYS_INLINE Vec3 applyInverse(const Vec3& world) const { return turnVectorBack(rotation, world - position); }
    STEPWISE_ALWAYS_INLINE Vec3 rotate(const Vec3& local) const { return turnVector(rotation, local); }
    STEPWISE_ALWAYS_INLINE Vec3 rotateInverse(const Vec3& world) const { return turnVectorBack(rotation, world); }
};

/// Axis-aligned bounding box in world space.
struct Aabb {
    Vec3 min = Vec3::Constant(kRealMax);
    Vec3 max = Vec3::Constant(-kRealMax);

    bool overlaps(const Aabb& other) const {
        return (min.array() <= other.max.array()).all() && (other.min.array() <= max.array()).all();
    }
    void grow(const Vec3& point) {
        min = min.cwiseMin(point);
        max = max.cwiseMax(point);
    }
    void grow(const Aabb& other) {
        min = min.cwiseMin(other.min);
        max = max.cwiseMax(other.max);
    }
    Vec3 center() const { return Real(0.5) * (min + max); }
    Vec3 extents() const { return Real(0.5) * (max - min); }
};

inline bool isFinite(Real value) { return std::isfinite(value); }
inline bool isFinite(const Vec3& v) { return v.allFinite(); }

/// The skew-symmetric matrix [v]x with [v]x w = v x w.
inline Mat3 skew(const Vec3& v) {
    Mat3 m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
}

/// Any unit vector perpendicular to a unit vector (Box2D/Erin Catto's branch-free choice).
inline Vec3 anyPerpendicular(const Vec3& unit) {
    const Vec3 helper = std::abs(unit.x()) >= Real(0.57735) ? Vec3(unit.y(), -unit.x(), 0) : Vec3(0, unit.z(), -unit.y());
    return helper.normalized();
}

/// The rotation by `angle` (rad) about the unit `axis`: Eigen::AngleAxis's quaternion, with this
/// build's sin and cos (math/functions.h) instead of the C library's.
inline Quat angleAxis(Real angle, const Vec3& axis) {
    const Real half = Real(0.5) * angle;
    const Vec3 vec = math::sin(half) * axis;
    return Quat(math::cos(half), vec.x(), vec.y(), vec.z());
}

/// Spherical linear interpolation from a (t = 0) to b (t = 1) along the shorter arc: Eigen's
/// Quaternion::slerp (Shoemake, "Animating rotation with quaternion curves", SIGGRAPH 1985), with
/// this build's acos and sin. Nearly equal rotations interpolate linearly.
inline Quat slerp(const Quat& a, Real t, const Quat& b) {
    const Real one = Real(1) - kEpsilon;
    const Real d = a.dot(b), absD = std::abs(d);
    Real scale0 = Real(1) - t, scale1 = t;
    if (absD < one) {
        const Real theta = math::acos(absD), sinTheta = math::sin(theta);
        scale0 = math::sin((Real(1) - t) * theta) / sinTheta;
        scale1 = math::sin(t * theta) / sinTheta;
    }
    if (d < 0) scale1 = -scale1;
    return Quat(scale0 * a.coeffs() + scale1 * b.coeffs());
}

}  // namespace stepwise
