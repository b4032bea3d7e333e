// The simplex walk both GJK queries share (gjk_walk.h).

#include "02_gjk/gjk_walk.h"

#include "02_gjk/closest_point.h"

#include <cmath>

namespace stepwise {
namespace gjk_detail {

RelativePair seenFromA(const ConvexProxy& a, const ConvexProxy& b) {
    RelativePair pair{a, b, a.transform.position};
    pair.a.transform.position = Vec3::Zero();
    pair.b.transform.position = b.transform.position - a.transform.position;
    return pair;
}

namespace {

bool isFiniteShape(const Shape& shape) {
    if (shape.type == ShapeType::Convex) {
        if (!shape.hull) return false;
        for (const Vec3& vertex : shape.hull->vertices)
            if (!vertex.allFinite()) return false;
        return true;
    }
    return shape.halfExtents.allFinite() && std::isfinite(shape.radius) && std::isfinite(shape.halfHeight);
}

}  // namespace

bool isValidProxy(const ConvexProxy& proxy) {
    return proxy.shape && isFiniteShape(*proxy.shape) && proxy.transform.position.allFinite() &&
           proxy.transform.rotation.coeffs().allFinite();
}

bool alreadyInSimplex(const Simplex& simplex, const Vec3& w, Real tolerance) {
    for (int i = 0; i < simplex.count; ++i)
        if ((simplex.vertices[i].w - w).squaredNorm() <= tolerance * tolerance) return true;
    return false;
}

// [ch02-reduce]
// Adds a support point, finds the closest point of the grown simplex to the origin, and keeps
// only the vertices of the feature that holds it (at most 4 survive; usually fewer).
void addAndReduce(Walk& walk, const SupportPoint& point, Real scale, FacePoint facePoint, SimplexPrecision precision) {
    Simplex& simplex = walk.simplex;
    simplex.vertices[simplex.count++] = point;
    Vec3 points[4];
    for (int i = 0; i < simplex.count; ++i) points[i] = simplex.vertices[i].w;
    const SimplexClosest closest = closestPointToOrigin(points, simplex.count, scale, facePoint, precision);

    const int newest = simplex.count - 1;
    bool keptNewest = false;
    Simplex reduced;
    for (int k = 0; k < closest.keptCount; ++k) {
        const int index = closest.kept[k];
        keptNewest = keptNewest || index == newest;
        reduced.vertices[k] = simplex.vertices[index];
        walk.weights[k] = closest.weights[index];
    }
    reduced.count = closest.keptCount;
    simplex = reduced;
    if (!keptNewest) ++walk.newestDropped;
    walk.v = closest.point;
    walk.degenerate = closest.degenerate;
    walk.inside = closest.inside;
}
// [ch02-reduce]

// The first simplex: one support point towards B from inside A - B. cA - cB is a point of
// A - B we know without a query; when it is the origin (concentric shapes) any direction will do.
Walk startWalk(const RelativePair& pair, const GjkTolerances& tolerances) {
    Vec3 direction = pair.b.center() - pair.a.center();
    if (!(direction.squaredNorm() > tolerances.touching * tolerances.touching)) direction = Vec3::UnitX();
    Walk walk;
    walk.firstDirection = direction;
    walk.simplex.vertices[0] = minkowskiSupport(pair.a, pair.b, direction);
    walk.simplex.count = 1;
    walk.v = walk.simplex.vertices[0].w;
    return walk;
}

void toWorld(Simplex& simplex, const Vec3& offset) {
    for (int i = 0; i < simplex.count; ++i) {
        simplex.vertices[i].onA += offset;
        simplex.vertices[i].onB += offset;
    }
}

}  // namespace gjk_detail
}  // namespace stepwise
