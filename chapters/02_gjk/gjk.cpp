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

}  // namespace

GjkResult gjkIntersect(const ConvexProxy& a, const ConvexProxy& b, int maxIterations, FacePoint facePoint) {
    GjkResult result;
    if (!isValidProxy(a) || !isValidProxy(b)) {
        result.exit = GjkExit::Degenerate;
        return result;
    }
    const RelativePair pair = seenFromA(a, b);
    const GjkTolerances tolerances = gjkTolerances(a, b);
    const Real touchingSquared = tolerances.touching * tolerances.touching;

    Walk walk = startWalk(pair, tolerances);
    result.iterations = 1;
    GjkExit exit = GjkExit::IterationCap;
    // [ch02-gjk-loop]
    if (walk.v.dot(walk.firstDirection) < 0) {
        exit = GjkExit::Separated;  // the very first support plane already separates
    } else if (walk.v.squaredNorm() <= touchingSquared) {
        exit = GjkExit::Intersect;  // that point is the origin: touching at a vertex
    }
    while (exit == GjkExit::IterationCap && result.iterations < maxIterations) {
        // Search towards the origin from the closest point v found so far.
        const Vec3 direction = -walk.v;
        const SupportPoint point = minkowskiSupport(pair.a, pair.b, direction);
        ++result.iterations;

        // The support plane {x : x.d = w.d} bounds A - B. If the origin (x.d = 0) lies beyond
        // it, that plane separates the origin from A - B: no overlap, done.
        if (point.w.dot(direction) < 0) {
            exit = GjkExit::Separated;
            break;
        }
        // A support point the simplex already holds cannot bring it closer. In exact
        // arithmetic that only happens when v is already the origin.
        if (alreadyInSimplex(walk.simplex, point.w, tolerances.touching)) {
            exit = GjkExit::RepeatedSupport;
            break;
        }
        const Real previousSquared = walk.v.squaredNorm();
        addAndReduce(walk, point, tolerances.scale, facePoint);
        const Real distanceSquared = walk.v.squaredNorm();
        if (!std::isfinite(distanceSquared)) {
            exit = GjkExit::Degenerate;
            break;
        }
        // The simplex holds the origin (a tetrahedron around it, or a face through it).
        if (walk.inside || distanceSquared <= touchingSquared) {
            exit = GjkExit::Intersect;
            break;
        }
        // Exact GJK shrinks |v| strictly every step; when rounding stops that, stop too.
        if (distanceSquared >= previousSquared) {
            exit = walk.degenerate ? GjkExit::Degenerate : GjkExit::NoProgress;
            break;
        }
    }
    // [ch02-gjk-loop]

    // [ch02-gjk-verdict]
    // A clean exit answers directly. The others (rounding floors, the cap) prove nothing by
    // themselves: "separated" needs a plane. At the closest point the support plane towards the
    // origin passes through it, so a pair that is apart shows its gap there; a walk that stalled
    // short of the closest point (a sliver of A - B, a needle against a small box) finds no such
    // plane, and the origin may well be inside. Without a plane leaving the origin outside by
    // more than the touching tolerance the pair counts as touching, and EPA, which grows the
    // simplex into a tetrahedron around the origin, says how deep.
    if (exit == GjkExit::Intersect || exit == GjkExit::Separated) {
        result.intersect = exit == GjkExit::Intersect;
    } else if (walk.v.squaredNorm() <= touchingSquared) {
        result.intersect = true;
    } else {
        const Vec3 towardsOrigin = -walk.v.normalized();
        const SupportPoint point = minkowskiSupport(pair.a, pair.b, towardsOrigin);
        ++result.iterations;
        result.intersect = !(point.w.dot(towardsOrigin) < -tolerances.touching);
        // A float walk stalled on a sliver of A - B (a 1.2 mm box at a 56 m hull's face) points
        // its one plane centimetres off the gap; the distance walk, which walks again with the
        // sums that cancel in double where it stalls too, finds the gap if there is one.
        if (result.intersect) {
            const GjkDistanceResult distance = gjkDistance(a, b, maxIterations);
            result.iterations += distance.iterations;
            result.intersect = !distance.separated;
        }
    }
    // [ch02-gjk-verdict]
    result.exit = exit;
    result.newestDropped = walk.newestDropped;
    if (result.intersect) growToTetrahedron(pair, walk.simplex, tolerances.scale);
    result.simplex = walk.simplex;
    toWorld(result.simplex, pair.offset);
    return result;
}

}  // namespace stepwise
