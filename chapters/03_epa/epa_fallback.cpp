// The answers EPA gives when its polytope cannot (epa_fallback.h): the best of a handful of
// candidate axes, and the contact along the tightest upper bound EPA found.
#include "03_epa/epa_fallback.h"

#include <algorithm>
#include <cmath>

namespace stepwise::epa_fallback {

/// No tetrahedron around the origin could be built: GJK's simplex holds the origin but A - B
/// spans no volume around it within round-off, so the shapes touch (or the input is degenerate).
/// The depth is then tiny, and the direction matters more than its value: try the directions the
/// simplex and the centres suggest, and keep the one along which A - B reaches least far past
/// the origin (the same min-over-axes idea as SAT, over a handful of candidate axes).
EpaResult fallbackContact(const ConvexProxy& a, const ConvexProxy& b, const Simplex& simplex) {
    Vec3 candidates[20];
    // Where a candidate knows the touching points themselves (a round shape's core), they are kept.
    bool knownPoints[20] = {};
    Vec3 knownA[20], knownB[20];
    int count = 0;
    const auto add = [&](const Vec3& direction) {
        const Real length = direction.norm();
        if (count + 2 <= 20 && length > 0 && isFinite(length)) {
            candidates[count++] = direction / length;
            candidates[count++] = -direction / length;
        }
    };
    if (simplex.count >= 3 && simplex.count <= 4) {
        const Vec3& p0 = simplex.vertices[0].w;
        add((simplex.vertices[1].w - p0).cross(simplex.vertices[2].w - p0));
    }
    if (simplex.count >= 2 && simplex.count <= 4) {
        const Vec3 edge = simplex.vertices[1].w - simplex.vertices[0].w;
        add(edge.cross(Vec3::UnitX()));
        add(edge.cross(Vec3::UnitY()));
    }
    add(b.center() - a.center());
    // A round shape (sphere, capsule) touches along the line from the other shape to its core
    // (centre or segment), which lies a radius inside its surface: GJK's distance to the core names
    // the normal that none of the directions above may come near. Without it a sphere just touching
    // a hull read 7.8 cm deep (tests/ch03: a sphere grazing a hull).
    const auto addCoreDirection = [&](const ConvexProxy& round, const ConvexProxy& other, Real sign) {
        const Shape& shape = *round.shape;
        if (shape.type != ShapeType::Sphere && shape.type != ShapeType::Capsule) return;
        const Real coreRadius = shape.radius * Real(1e-3);
        const Shape core = shape.type == ShapeType::Sphere ? Shape::sphere(coreRadius)
                                                           : Shape::capsule(coreRadius, shape.halfHeight);
        const ConvexProxy coreProxy{&core, round.transform, round.mode};
        const GjkDistanceResult distance = gjkDistance(other, coreProxy);
        if (!distance.separated) return;
        const int first = count;
        add(sign * (distance.pointB - distance.pointA));
        if (count == first) return;
        // The other shape's closest point, and the round shape's surface point a radius from its core.
        const Vec3 towardCore = (distance.pointB - distance.pointA).normalized();
        const Vec3 onOther = distance.pointA;
        const Vec3 onRound = distance.pointB - (shape.radius - coreRadius) * towardCore;
        knownPoints[first] = true;
        knownA[first] = sign > 0 ? onOther : onRound;
        knownB[first] = sign > 0 ? onRound : onOther;
    };
    addCoreDirection(b, a, 1);
    addCoreDirection(a, b, -1);
    add(Vec3::UnitX());
    add(Vec3::UnitY());
    add(Vec3::UnitZ());

    EpaResult result;
    result.exit = EpaExit::Degenerate;
    Real best = kRealMax;
    for (int i = 0; i < count; ++i) {
        const SupportPoint support = minkowskiSupport(a, b, candidates[i]);
        const Real reach = candidates[i].dot(support.w);
        if (!(reach < best) || !isFinite(support.w)) continue;
        best = reach;
        result.normal = candidates[i];
        // Each shape's own extreme point: on its surface, apart only across the contact plane
        // and, where the touching features are wide, along it.
        result.pointA = knownPoints[i] ? knownA[i] : support.onA;
        result.pointB = knownPoints[i] ? knownB[i] : support.onB;
        for (SupportPoint& corner : result.closestFace) corner = support;
    }
    result.depth = best < kRealMax ? std::max(best, Real(0)) : Real(0);
    if (!isFinite(result.pointA) || !isFinite(result.pointB)) result.pointA = result.pointB = Vec3::Zero();
    return result;
}

namespace {

/// True when a world point lies inside the shape, or within `slack` of it.
bool holds(const ConvexProxy& proxy, const Vec3& worldPoint, Real slack) {
    const Shape& shape = *proxy.shape;
    const Vec3 local = proxy.transform.applyInverse(worldPoint);
    switch (shape.type) {
        case ShapeType::Box: return (local.cwiseAbs() - shape.halfExtents).maxCoeff() <= slack;
        case ShapeType::Sphere: return local.norm() <= shape.radius + slack;
        case ShapeType::Capsule: {
            const Real along = std::clamp(local.y(), -shape.halfHeight, shape.halfHeight);
            return (local - Vec3(0, along, 0)).norm() <= shape.radius + slack;
        }
        case ShapeType::Convex:
            for (const HullFace& face : shape.hull->faces)
                if (face.normal.dot(local) - face.offset > slack) return false;
            return true;
        case ShapeType::Cylinder:
            return std::abs(local.y()) <= shape.halfHeight + slack && math::hypot(local.x(), local.z()) <= shape.radius + slack;
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: return false;  // never a proxy's shape
    }
    return false;
}

}  // namespace

/// The contact along an upper bound's normal, `reach` deep. Each shape's own extreme point lies
/// on its surface, but where the touching features are wide the two can be far apart (a plate's
/// far corner 4 m from the box inside it). So one shape's extreme point is kept and the other
/// point put `reach` from it along the normal, on the other shape's support plane, when it lies
/// on that shape too: the smaller shape's first, which lies within its own size of the overlap.
void answerWithBound(const ConvexProxy& a, const ConvexProxy& b, const UpperBound& bound, Real slack,
                     EpaResult& result) {
    result.depth = std::max(bound.reach, Real(0));
    result.normal = bound.normal;
    const Vec3 fromA = bound.support.onA - result.depth * result.normal;
    const Vec3 fromB = bound.support.onB + result.depth * result.normal;
    const bool aFirst = shapeScale(*a.shape) <= shapeScale(*b.shape);
    const bool keepA = holds(b, fromA, slack), keepB = holds(a, fromB, slack);
    if (keepA && (aFirst || !keepB)) {
        result.pointA = bound.support.onA;
        result.pointB = fromA;
    } else if (keepB) {
        result.pointA = fromB;
        result.pointB = bound.support.onB;
    } else {
        result.pointA = bound.support.onA;
        result.pointB = bound.support.onB;
    }
    for (SupportPoint& corner : result.closestFace) corner = bound.support;
}

}  // namespace stepwise::epa_fallback
