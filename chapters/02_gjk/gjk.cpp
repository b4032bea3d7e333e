// GJK, the boolean query. Both queries (this one and gjk_distance.cpp) make the same four moves:
// ask A - B for its support point towards the origin, stop if that proves an answer, add the
// point to the simplex, and shrink the simplex to the feature closest to the origin
// (gjk_walk.cpp, closest_point.cpp).

#include "02_gjk/gjk.h"

#include "02_gjk/gjk_walk.h"
#include "02_gjk/tolerances.h"
#include "world/enum_names.h"

#include <cmath>

namespace stepwise {

using namespace gjk_detail;

const char* toString(GjkExit exit) {
    static const Names<GjkExit> names = {{"intersect", GjkExit::Intersect},
                                         {"separated", GjkExit::Separated},
                                         {"no-progress", GjkExit::NoProgress},
                                         {"repeated-support", GjkExit::RepeatedSupport},
                                         {"degenerate", GjkExit::Degenerate},
                                         {"iteration-cap", GjkExit::IterationCap}};
    return nameOf(names, exit);
}

// [ch02-tolerances]
GjkTolerances gjkTolerances(const ConvexProxy& a, const ConvexProxy& b) {
    GjkTolerances tolerances;
    // Support points of A - B have coordinates of the order of the two shapes' sizes once the
    // pair is seen from A (below), so rounding errors are a few epsilons of that size. Every
    // tolerance is such a multiple: a 1 mm and a 1 km box get the same relative treatment.
    tolerances.scale = shapeScale(*a.shape) + shapeScale(*b.shape);
    tolerances.touching = tolerance::kTouching * tolerances.scale;
    tolerances.relative = tolerance::kTouching;
    return tolerances;
}
// [ch02-tolerances]

namespace {

// Grows an intersecting simplex into a tetrahedron around the origin for EPA: the origin is
// within rounding of the simplex, so adding points of A - B off its span (in the directions
// it lacks) gives a tetrahedron containing it. Stops early when A - B is itself flat.
void growToTetrahedron(const RelativePair& pair, Simplex& simplex, Real scale) {
    const Real minimumReach = tolerance::kDegenerateFraction * scale;
    while (simplex.count > 0 && simplex.count < 4) {
        const Vec3& first = simplex.vertices[0].w;
        Vec3 candidates[6];
        int candidateCount = 0;
        if (simplex.count == 1) {
            for (int axis = 0; axis < 3; ++axis) {
                candidates[candidateCount++] = Vec3::Unit(axis);
                candidates[candidateCount++] = -Vec3::Unit(axis);
            }
        } else if (simplex.count == 2) {
            const Vec3 along = simplex.vertices[1].w - first;
            const Vec3 side = anyPerpendicular(along.normalized());
            const Vec3 up = along.cross(side).normalized();
            for (const Vec3& d : {side, Vec3(-side), up, Vec3(-up)}) candidates[candidateCount++] = d;
        } else {
            const Vec3 normal = (simplex.vertices[1].w - first).cross(simplex.vertices[2].w - first);
            candidates[candidateCount++] = normal;
            candidates[candidateCount++] = -normal;
        }
        SupportPoint best;
        Real bestReach = 0;
        for (int c = 0; c < candidateCount; ++c) {
            const SupportPoint point = minkowskiSupport(pair.a, pair.b, candidates[c]);
            // How far the point lies off the current simplex's span, along the direction asked.
            const Real reach = simplex.count == 1 ? (point.w - first).norm()
                                                  : (point.w - first).dot(candidates[c].normalized());
            if (reach > bestReach) {
                bestReach = reach;
                best = point;
            }
        }
        if (!(bestReach > minimumReach)) return;
        simplex.vertices[simplex.count++] = best;
    }
}

/// The walk towards the origin, from startWalk's first point until one of the exits; the
/// iterations it takes are added to `iterations`.
GjkExit walkTowardsOrigin(const RelativePair& pair, const GjkTolerances& tolerances, int maxIterations,
                          FacePoint facePoint, Walk& walk, int& iterations) {
    const Real touchingSquared = tolerances.touching * tolerances.touching;
    // [ch02-gjk-loop]
    if (walk.v.dot(walk.firstDirection) < 0) return GjkExit::Separated;  // the first support plane separates
    if (walk.v.squaredNorm() <= touchingSquared) return GjkExit::Intersect;  // that point is the origin
    while (iterations < maxIterations) {
        // Search towards the origin from the closest point v found so far.
        const Vec3 direction = -walk.v;
        const SupportPoint point = minkowskiSupport(pair.a, pair.b, direction);
        ++iterations;

        // The support plane {x : x.d = w.d} bounds A - B. If the origin (x.d = 0) lies beyond
        // it, that plane separates the origin from A - B: no overlap, done.
        if (point.w.dot(direction) < 0) return GjkExit::Separated;
        // A support point the simplex already holds cannot bring it closer. In exact
        // arithmetic that only happens when v is already the origin.
        if (alreadyInSimplex(walk.simplex, point.w, tolerances.touching)) return GjkExit::RepeatedSupport;
        const Real previousSquared = walk.v.squaredNorm();
        addAndReduce(walk, point, tolerances.scale, facePoint);
        const Real distanceSquared = walk.v.squaredNorm();
        if (!std::isfinite(distanceSquared)) return GjkExit::Degenerate;
        // The simplex holds the origin (a tetrahedron around it, or a face through it).
        if (walk.inside || distanceSquared <= touchingSquared) return GjkExit::Intersect;
        // Exact GJK shrinks |v| strictly every step; when rounding stops that, stop too.
        if (distanceSquared >= previousSquared) return walk.degenerate ? GjkExit::Degenerate : GjkExit::NoProgress;
    }
    return GjkExit::IterationCap;
    // [ch02-gjk-loop]
}

/// Whether the pair overlaps, given how the walk ended.
bool overlapsAfterWalk(const ConvexProxy& a, const ConvexProxy& b, const RelativePair& pair,
                       const GjkTolerances& tolerances, int maxIterations, GjkExit exit, const Walk& walk,
                       int& iterations) {
    // [ch02-gjk-verdict]
    // A clean exit answers directly. The others (rounding floors, the cap) prove nothing by
    // themselves: "separated" needs a plane. At the closest point the support plane towards the
    // origin passes through it, so a pair that is apart shows its gap there; a walk that stalled
    // short of the closest point (a sliver of A - B, a needle against a small box) finds no such
    // plane, and the origin may well be inside. Without a plane leaving the origin outside by
    // more than the touching tolerance the pair counts as touching, and EPA, which grows the
    // simplex into a tetrahedron around the origin, says how deep.
    if (exit == GjkExit::Intersect || exit == GjkExit::Separated) return exit == GjkExit::Intersect;
    if (walk.v.squaredNorm() <= tolerances.touching * tolerances.touching) return true;
    const Vec3 towardsOrigin = -walk.v.normalized();
    const SupportPoint point = minkowskiSupport(pair.a, pair.b, towardsOrigin);
    ++iterations;
    if (point.w.dot(towardsOrigin) < -tolerances.touching) return false;
    // A float walk stalled on a sliver of A - B (a 1.2 mm box at a 56 m hull's face) points its
    // one plane centimetres off the gap; the distance walk, which walks again with the sums that
    // cancel in double where it stalls too, finds the gap if there is one.
    const GjkDistanceResult distance = gjkDistance(a, b, maxIterations);
    iterations += distance.iterations;
    return !distance.separated;
    // [ch02-gjk-verdict]
}

}  // namespace

GjkResult gjkIntersect(const ConvexProxy& a, const ConvexProxy& b, int maxIterations, FacePoint facePoint) {
    GjkResult result;
    if (!isValidProxy(a) || !isValidProxy(b)) {
        result.exit = GjkExit::Degenerate;
        return result;
    }
    const RelativePair pair = seenFromA(a, b);
    const GjkTolerances tolerances = gjkTolerances(a, b);
    Walk walk = startWalk(pair, tolerances);
    result.iterations = 1;
    result.exit = walkTowardsOrigin(pair, tolerances, maxIterations, facePoint, walk, result.iterations);
    result.intersect = overlapsAfterWalk(a, b, pair, tolerances, maxIterations, result.exit, walk, result.iterations);
    result.newestDropped = walk.newestDropped;
    if (result.intersect) growToTetrahedron(pair, walk.simplex, tolerances.scale);
    result.simplex = walk.simplex;
    toWorld(result.simplex, pair.offset);
    return result;
}

}  // namespace stepwise
