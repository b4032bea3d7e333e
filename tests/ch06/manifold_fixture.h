#pragma once
// The poses and shapes chapter 6's manifold and persistence tests place their pairs with.

#include "math/math.h"
#include "world/contact.h"
#include "world/shape.h"

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace stepwise::test {

inline Quat axisAngle(const Vec3& axis, double degrees) {
    return Quat(Eigen::AngleAxis<Real>(static_cast<Real>(degrees * 3.14159265358979323846 / 180.0), axis.normalized()));
}

inline Transform pose(const Vec3& position, const Quat& rotation = Quat::Identity()) { return Transform{position, rotation}; }

/// A unit cube and a slab twice as wide as it, a quarter as thick: the pairs' usual partners.
inline const Shape kUnitBox = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
inline const Shape kSlab = Shape::box(Vec3(1, Real(0.25), Real(0.75)));

inline Shape octahedronHull(Real size) {
    return Shape::convex({Vec3(size, 0, 0), Vec3(-size, 0, 0), Vec3(0, size, 0), Vec3(0, -size, 0), Vec3(0, 0, size),
                          Vec3(0, 0, -size)});
}

/// A hull with large faces of several shapes: a hexagonal prism with a slanted top.
inline Shape prismHull() {
    std::vector<Vec3> points;
    for (int k = 0; k < 6; ++k) {
        const Real angle = static_cast<Real>(k) * Real(3.14159265358979323846 / 3.0);
        const Real x = Real(0.6) * std::cos(angle), z = Real(0.6) * std::sin(angle);
        points.emplace_back(x, Real(-0.4), z);
        points.emplace_back(x, Real(0.4) + Real(0.1) * x, z);
    }
    return Shape::convex(points);
}

/// The depth of a contact's deepest point (-kRealMax when it has none).
inline Real deepestPoint(const Contact& contact) {
    Real depth = -kRealMax;
    for (int i = 0; i < contact.pointCount; ++i) depth = depth < contact.points[i].depth ? contact.points[i].depth : depth;
    return depth;
}

}  // namespace stepwise::test
