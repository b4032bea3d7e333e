// Support maps of the four shape types, and of the Minkowski difference A - B.

#include "02_gjk/support.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stepwise {
namespace {

// A unit vector along d, or +X when d is zero. Dividing by the largest component first keeps
// tiny (even denormal) directions from underflowing to a zero length and then dividing by it.
Vec3 unitOrX(const Vec3& d) {
    const Real largest = d.cwiseAbs().maxCoeff();
    if (!(largest > 0)) return Vec3::UnitX();  // also catches NaN
    const Vec3 scaled = d / largest;
    return scaled / scaled.norm();
}

// [ch02-support-box]
// The farthest corner of a box along d: d.x = d_x x_x + d_y x_y + d_z x_z is maximised one term
// at a time, each by the half extent carrying d's sign. Three comparisons, no loop, no
// normalisation; a zero component ties both faces and picks the + side.
Vec3 boxSupportByExtents(const Vec3& halfExtents, const Vec3& d) {
    return Vec3(d.x() >= 0 ? halfExtents.x() : -halfExtents.x(),
                d.y() >= 0 ? halfExtents.y() : -halfExtents.y(),
                d.z() >= 0 ? halfExtents.z() : -halfExtents.z());
}

// The naive way: treat the box as a hull of its 8 corners and keep the best dot product.
Vec3 boxSupportByVertices(const Vec3& halfExtents, const Vec3& d) {
    Vec3 best = Vec3::Zero();
    Real bestDot = -kRealMax;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 vertex((corner & 1) ? halfExtents.x() : -halfExtents.x(),
                          (corner & 2) ? halfExtents.y() : -halfExtents.y(),
                          (corner & 4) ? halfExtents.z() : -halfExtents.z());
        const Real dot = vertex.dot(d);
        if (dot > bestDot) {
            bestDot = dot;
            best = vertex;
        }
    }
    return best;
}
// [ch02-support-box]

// [ch02-support-round]
// A sphere's support is its radius along the unit direction; a capsule's is the end of its
// inner segment (axis +Y) on d's side plus that sphere: the capsule is the segment swept by a
// sphere, and supports add under such sums (s_{X+Y}(d) = s_X(d) + s_Y(d)).
Vec3 sphereSupport(Real radius, const Vec3& d) { return radius * unitOrX(d); }

Vec3 capsuleSupport(Real radius, Real halfHeight, const Vec3& d) {
    return Vec3(0, d.y() >= 0 ? halfHeight : -halfHeight, 0) + sphereSupport(radius, d);
}
// [ch02-support-round]

}  // namespace

// [ch13-cylinder-support]
// A cylinder (axis +Y) is a disc swept along its axis, so its support is the end of the axis
// segment on d's side plus the disc's support: the rim point in the direction of d's part across
// the axis. With no such part (d along the axis) every rim point ties: the centre of the cap,
// which is on the surface, comes back.
Vec3 cylinderSupport(Real radius, Real halfHeight, const Vec3& d) {
    const Real across = math::hypot(d.x(), d.z());
    const Vec3 rim = across > 0 ? Vec3(radius * d.x() / across, 0, radius * d.z() / across) : Vec3::Zero();
    return rim + Vec3(0, d.y() >= 0 ? halfHeight : -halfHeight, 0);
}
// [ch13-cylinder-support]

namespace {

// A hull's support is its vertex of largest dot product: a linear function over a polytope is
// maximised at a vertex. O(n); hill climbing over vertex neighbours is the usual speed-up for
// large hulls, not needed for game-sized ones.
Vec3 hullSupport(const ConvexHull* hull, const Vec3& d) {
    if (!hull || hull->vertices.empty()) return Vec3::Zero();
    const Vec3* best = &hull->vertices.front();
    Real bestDot = best->dot(d);
    for (const Vec3& vertex : hull->vertices) {
        const Real dot = vertex.dot(d);
        if (dot > bestDot) {
            bestDot = dot;
            best = &vertex;
        }
    }
    return *best;
}

}  // namespace

Vec3 localSupport(const Shape& shape, const Vec3& localDirection, SupportMode mode) {
    switch (shape.type) {
        case ShapeType::Box:
            return mode == SupportMode::Extents ? boxSupportByExtents(shape.halfExtents, localDirection)
                                                : boxSupportByVertices(shape.halfExtents, localDirection);
        case ShapeType::Sphere: return sphereSupport(shape.radius, localDirection);
        case ShapeType::Capsule: return capsuleSupport(shape.radius, shape.halfHeight, localDirection);
        case ShapeType::Convex: return hullSupport(shape.hull.get(), localDirection);
        case ShapeType::Cylinder: return cylinderSupport(shape.radius, shape.halfHeight, localDirection);
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // not one convex set: chapter 13 collides their parts
    }
    return Vec3::Zero();
}

Vec3 ConvexProxy::support(const Vec3& worldDirection) const {
    return transform.apply(localSupport(*shape, transform.rotateInverse(worldDirection), mode));
}

Vec3 ConvexProxy::center() const {
    if (shape->type != ShapeType::Convex || !shape->hull || shape->hull->vertices.empty())
        return transform.position;
    // The vertex average lies inside the hull (a convex combination of its vertices).
    Vec3 sum = Vec3::Zero();
    for (const Vec3& vertex : shape->hull->vertices) sum += vertex;
    return transform.apply(sum / Real(shape->hull->vertices.size()));
}

// [ch02-minkowski]
SupportPoint minkowskiSupport(const ConvexProxy& a, const ConvexProxy& b, const Vec3& direction) {
    // s_{A-B}(d) = s_A(d) - s_B(-d): the farthest point of A along d minus the farthest point
    // of B against d.
    const Vec3 armA = a.transform.rotate(localSupport(*a.shape, a.transform.rotateInverse(direction), a.mode));
    const Vec3 armB = b.transform.rotate(localSupport(*b.shape, b.transform.rotateInverse(-direction), b.mode));
    SupportPoint point;
    point.onA = a.transform.position + armA;
    point.onB = b.transform.position + armB;
    // Subtract the positions first: far from the origin, onA - onB would cancel away the
    // digits the arms carry.
    point.w = (a.transform.position - b.transform.position) + (armA - armB);
    return point;
}
// [ch02-minkowski]

Real shapeScale(const Shape& shape) {
    if (shape.type == ShapeType::Convex && !shape.hull) return std::numeric_limits<Real>::min();
    return std::max(boundingRadius(shape), std::numeric_limits<Real>::min());
}

}  // namespace stepwise
