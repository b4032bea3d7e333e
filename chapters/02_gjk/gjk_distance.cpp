// GJK, the distance query: the closest points of two separated shapes (chapter 7, to come, builds
// continuous collision on it).

#include "02_gjk/gjk_walk.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace stepwise {

using namespace gjk_detail;

namespace {

// [ch02-cores]
// A sphere is a point grown by its radius, a capsule a segment grown by its radius. On the grown
// shape every support point is new, so GJK only converges in the limit and its simplex fills
// with slivers; on the cores (a point, a segment: polytopes) it ends after a few steps with an
// exact feature, and the radii come off at the end (van den Bergen, "Collision Detection in
// Interactive 3D Environments", 2004, 4.3.5; Box2D's b2ShapeDistance does the same). A zero-size
// box is a point and a box of half extents (0, h, 0) the segment, so the box support serves.
ConvexProxy coreOf(const ConvexProxy& proxy, Shape& storage, Real& radius) {
    ConvexProxy core = proxy;
    radius = 0;
    if (isRound(*proxy.shape)) {
        const Real halfHeight = proxy.shape->type == ShapeType::Capsule ? proxy.shape->halfHeight : Real(0);
        storage = Shape::box(Vec3(0, halfHeight, 0));
        radius = proxy.shape->radius;
        core.shape = &storage;
    }
    return core;
}
// [ch02-cores]

// One walk of the distance query, its simplex's closest points found in `precision`.
struct DistanceWalk {
    Walk walk;
    GjkExit exit = GjkExit::IterationCap;
    Real lowerBound = -kRealMax;  // the best support plane's distance from the origin (cores)
    int iterations = 1;
};

DistanceWalk walkToDistance(const RelativePair& pair, const GjkTolerances& tolerances, int maxIterations,
                            SimplexPrecision precision) {
    const Real touchingSquared = tolerances.touching * tolerances.touching;
    DistanceWalk run{startWalk(pair, tolerances)};
    Walk& walk = run.walk;
    GjkExit& exit = run.exit;
    Real& lowerBound = run.lowerBound;
    exit = walk.v.squaredNorm() <= touchingSquared ? GjkExit::Intersect : GjkExit::IterationCap;
    // [ch02-distance-loop]
    while (exit == GjkExit::IterationCap && run.iterations < maxIterations) {
        const Vec3 direction = -walk.v;
        const SupportPoint point = minkowskiSupport(pair.a, pair.b, direction);
        ++run.iterations;
        lowerBound = std::max(lowerBound, walk.v.dot(point.w) / walk.v.norm());

        // Bounds on the distance: |v| from above (v is a point of A - B), v.w / |v| from below
        // (the support plane through w). Stop when they agree to a relative tolerance
        // (van den Bergen 1999, eq. 4): |v|^2 - v.w <= eps |v|^2.
        const Real distanceSquared = walk.v.squaredNorm();
        if (distanceSquared - walk.v.dot(point.w) <= tolerances.relative * distanceSquared) {
            exit = GjkExit::Separated;
            break;
        }
        if (alreadyInSimplex(walk.simplex, point.w, tolerances.touching)) {
            exit = GjkExit::RepeatedSupport;
            break;
        }
        addAndReduce(walk, point, tolerances.scale, FacePoint::Projection, precision);
        const Real newDistanceSquared = walk.v.squaredNorm();
        if (!std::isfinite(newDistanceSquared)) {
            exit = GjkExit::Degenerate;
            break;
        }
        if (walk.inside || newDistanceSquared <= touchingSquared) {
            exit = GjkExit::Intersect;
            break;
        }
        if (newDistanceSquared >= distanceSquared) {
            exit = walk.degenerate ? GjkExit::Degenerate : GjkExit::NoProgress;
            break;
        }
    }
    // [ch02-distance-loop]
    return run;
}

// Whether the walk proved a gap: it converged, or a support plane it met leaves the origin
// outside by more than the touching tolerance.
bool provesGap(const DistanceWalk& run, const GjkTolerances& tolerances) {
    return run.exit == GjkExit::Separated || run.lowerBound > tolerances.touching;
}

}  // namespace

GjkDistanceResult gjkDistance(const ConvexProxy& a, const ConvexProxy& b, int maxIterations) {
    GjkDistanceResult result;
    if (!isValidProxy(a) || !isValidProxy(b)) {
        result.exit = GjkExit::Degenerate;
        return result;
    }
    // Tolerances from the whole shapes, the walk on their cores.
    const GjkTolerances tolerances = gjkTolerances(a, b);
    Shape coreStorageA, coreStorageB;
    Real radiusA = 0, radiusB = 0;
    const RelativePair pair = seenFromA(coreOf(a, coreStorageA, radiusA), coreOf(b, coreStorageB, radiusB));
    DistanceWalk run = walkToDistance(pair, tolerances, maxIterations, SimplexPrecision::Working);
    // [ch02-second-walk]
    // A float walk that stops on a rounding floor without a proof walks again with its simplex's
    // closest point found in double. Where the nearest feature's points lie tens of metres from the
    // origin and the origin millimetres from the feature (a 1.2 mm box beside a 56 m slab), a
    // float closest point carries eps |p| and turns by eps |p| / |v|, and the support plane it
    // points at misses the gap by centimetres. The support points stay float: only the sums
    // that cancel are made wider. In a double build, and for every walk that ends cleanly, the
    // first walk stands.
    if (std::is_same<Real, float>::value && run.exit != GjkExit::Intersect && !provesGap(run, tolerances)) {
        DistanceWalk precise = walkToDistance(pair, tolerances, maxIterations, SimplexPrecision::Double);
        precise.iterations += run.iterations;
        run = precise;
    }
    // [ch02-second-walk]
    const Walk& walk = run.walk;
    const GjkExit exit = run.exit;
    result.iterations = run.iterations;

    // [ch02-closest-points]
    // v = sum_i weight_i (a_i - b_i), so the same weights applied to the shape points give the
    // closest points of the cores (van den Bergen 1999, section 3); the radii then move them
    // towards each other along the axis between the cores.
    Vec3 coreA = Vec3::Zero(), coreB = Vec3::Zero();
    for (int i = 0; i < walk.simplex.count; ++i) {
        coreA += walk.weights[i] * walk.simplex.vertices[i].onA;
        coreB += walk.weights[i] * walk.simplex.vertices[i].onB;
    }
    // A walk that stopped on a rounding floor (a sliver simplex: a small box on a 40 m ground box
    // makes A - B a slab, and its tetrahedra near the origin are millimetres thick) has found an
    // upper bound of the distance, not the distance. It proves a gap only with a support plane that
    // leaves the origin outside; without one the cores count as touching, as gjkIntersect's verdict
    // counts them.
    const bool proven = provesGap(run, tolerances);
    const Real coreDistance = exit == GjkExit::Intersect || !proven ? Real(0) : walk.v.norm();
    const Vec3 axisAToB = coreDistance > 0 ? Vec3(-walk.v / coreDistance) : Vec3::Zero();
    result.pointA = coreA + radiusA * axisAToB + pair.offset;
    result.pointB = coreB - radiusB * axisAToB + pair.offset;
    result.axis = axisAToB;
    const Real gap = coreDistance - radiusA - radiusB;
    result.separated = gap > tolerances.touching;
    result.distance = result.separated ? gap : Real(0);
    result.radiusOverlap = coreDistance > 0 && gap < 0 ? -gap : Real(0);
    // [ch02-closest-points]
    // Separated cores whose radii overlap are intersecting shapes: a clean answer too.
    result.exit = exit == GjkExit::Separated && !result.separated ? GjkExit::Intersect : exit;
    result.newestDropped = walk.newestDropped;
    result.simplex = walk.simplex;
    toWorld(result.simplex, pair.offset);
    return result;
}

}  // namespace stepwise
