#pragma once
// Support maps: the only thing GJK (and EPA, chapter 3) asks of a shape. The support point of a
// convex set C in direction d is a point of C farthest along d, s_C(d) = argmax_{x in C} d.x.
// GJK never needs the shape's faces or edges, so one algorithm serves boxes, spheres, capsules
// and hulls (Gilbert, Johnson, Keerthi 1988; van den Bergen, "Collision Detection in
// Interactive 3D Environments", 2004, ch. 4.3).

#include "math/math.h"
#include "world/shape.h"

namespace stepwise {

/// How a box answers a support query: from the signs of the direction (3 comparisons), or by
/// looping over its 8 corners like a generic hull (the naive way, kept to compare).
enum class SupportMode { Extents, Vertices };

/// A farthest point of the shape along a direction, both in the shape's own frame. Any
/// direction is accepted: for the zero direction every point ties and a defined surface point
/// comes back (never NaN).
Vec3 localSupport(const Shape& shape, const Vec3& localDirection, SupportMode mode = SupportMode::Extents);

/// The support of a cylinder of axis +Y (the shape chapter 13 adds; every convex kind's support
/// map lives here, where GJK asks for it).
Vec3 cylinderSupport(Real radius, Real halfHeight, const Vec3& localDirection);

/// A shape placed in the world.
struct ConvexProxy {
    const Shape* shape = nullptr;
    Transform transform;
    SupportMode mode = SupportMode::Extents;

    /// Farthest world point along a world direction.
    Vec3 support(const Vec3& worldDirection) const;
    /// A world point inside the shape (the centre; a hull's vertex average).
    Vec3 center() const;
};

/// A point of the Minkowski difference A - B with the two shape points that made it.
struct SupportPoint {
    Vec3 onA = Vec3::Zero();
    Vec3 onB = Vec3::Zero();
    Vec3 w = Vec3::Zero();   // onA - onB
};

/// s_{A-B}(d) = s_A(d) - s_B(-d): the support of the Minkowski difference is the difference of
/// two supports, so A - B never has to be built. w is computed as (pA - pB) + (RA a - RB b),
/// which equals onA - onB but keeps its precision when both shapes are far from the origin.
SupportPoint minkowskiSupport(const ConvexProxy& a, const ConvexProxy& b, const Vec3& direction);

/// Size of the shape (radius of a sphere about its origin that holds it), for tolerances
/// relative to scale. Never below the smallest normal Real, so it can divide.
Real shapeScale(const Shape& shape);

}  // namespace stepwise
