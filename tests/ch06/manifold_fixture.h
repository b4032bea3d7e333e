#pragma once
// The poses and shapes chapter 6's manifold and persistence tests place their pairs with.

#include "math/math.h"
#include "world/contact.h"
#include "world/shape.h"

#include <Eigen/Geometry>

namespace stepwise::test {

inline Quat axisAngle(const Vec3& axis, double degrees) {
    return Quat(Eigen::AngleAxis<Real>(static_cast<Real>(degrees * 3.14159265358979323846 / 180.0), axis.normalized()));
}

inline Transform pose(const Vec3& position, const Quat& rotation = Quat::Identity()) { return Transform{position, rotation}; }

/// A unit cube and a slab twice as wide as it, a quarter as thick: the pairs' usual partners.
inline const Shape kUnitBox = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
inline const Shape kSlab = Shape::box(Vec3(1, Real(0.25), Real(0.75)));

/// The depth of a contact's deepest point (-kRealMax when it has none).
inline Real deepestPoint(const Contact& contact) {
    Real depth = -kRealMax;
    for (int i = 0; i < contact.pointCount; ++i) depth = depth < contact.points[i].depth ? contact.points[i].depth : depth;
    return depth;
}

}  // namespace stepwise::test
