// GJK, boolean and distance. Both loops share the same four moves: ask A - B for its support
// point towards the origin, stop if that proves an answer, add the point to the simplex, and
// shrink the simplex to the feature closest to the origin (closest_point.cpp).

#include "02_gjk/gjk.h"

#include "02_gjk/closest_point.h"

#include <cmath>

namespace stepwise {

const char* toString(GjkExit exit) {
    switch (exit) {
        case GjkExit::Intersect: return "intersect";
        case GjkExit::Separated: return "separated";
        case GjkExit::NoProgress: return "no-progress";
        case GjkExit::RepeatedSupport: return "repeated-support";
        case GjkExit::Degenerate: return "degenerate";
        case GjkExit::IterationCap: return "iteration-cap";
    }
    return "?";
}

// [ch02-tolerances]
GjkTolerances gjkTolerances(const ConvexProxy& a, const ConvexProxy& b) {
    GjkTolerances tolerances;
    // Support points of A - B have coordinates of the order of the two shapes' sizes once the
    // pair is seen from A (below), so rounding errors are a few epsilons of that size. Every
    // tolerance is such a multiple: a 1 mm and a 1 km box get the same relative treatment.
    tolerances.scale = shapeScale(*a.shape) + shapeScale(*b.shape);
    tolerances.touching = Real(100) * kEpsilon * tolerances.scale;
    tolerances.relative = Real(100) * kEpsilon;
    return tolerances;
}
// [ch02-tolerances]

namespace {

// [ch02-relative]
// The pair seen from A: same shapes and rotations, A's origin moved to the world origin. The
// Minkowski difference only moves with the positions' difference, so the answer is the same,
// but 10 km from the origin a float position has a resolution of about 1 mm while the offset
// pB - pA of two nearby bodies is exact (Sterbenz), and every product GJK forms is then of the
// size of the shapes, not of their distance to the world origin.
struct RelativePair {
    ConvexProxy a;
    ConvexProxy b;
    Vec3 offset = Vec3::Zero();   // add back to shape points to return to the world
};

RelativePair seenFromA(const ConvexProxy& a, const ConvexProxy& b) {
    RelativePair pair{a, b, a.transform.position};
    pair.a.transform.position = Vec3::Zero();
    pair.b.transform.position = b.transform.position - a.transform.position;
    return pair;
}
// [ch02-relative]

bool isFiniteShape(const Shape& shape) {
    if (shape.type == ShapeType::Convex) {
        if (!shape.hull) return false;
        for (const Vec3& vertex : shape.hull->vertices)
            if (!vertex.allFinite()) return false;
        return true;
    }
    return shape.halfExtents.allFinite() && std::isfinite(shape.radius) && std::isfinite(shape.halfHeight);
}

// Bad input gets a defined answer (not intersecting, exit Degenerate) rather than NaN.
bool isValidProxy(const ConvexProxy& proxy) {
    return proxy.shape && isFiniteShape(*proxy.shape) && proxy.transform.position.allFinite() &&
           proxy.transform.rotation.coeffs().allFinite();
}

// The loop state both queries share: the simplex (seen from A), the weights of its vertices
// that make the closest point v, and how often the newest vertex was not kept.
struct Walk {
    Simplex simplex;
    Real weights[4] = {1, 0, 0, 0};
    Vec3 v = Vec3::Zero();
    Vec3 firstDirection = Vec3::UnitX();
    int newestDropped = 0;
    bool degenerate = false;
    bool inside = false;
};

bool alreadyInSimplex(const Simplex& simplex, const Vec3& w, Real tolerance) {
    for (int i = 0; i < simplex.count; ++i)
        if ((simplex.vertices[i].w - w).squaredNorm() <= tolerance * tolerance) return true;
    return false;
}

// [ch02-reduce]
// Adds a support point, finds the closest point of the grown simplex to the origin, and keeps
// only the vertices of the feature that holds it (at most 4 survive; usually fewer).
void addAndReduce(Walk& walk, const SupportPoint& point, Real scale, FacePoint facePoint = FacePoint::Projection) {
    Simplex& simplex = walk.simplex;
    simplex.vertices[simplex.count++] = point;
    Vec3 points[4];
    for (int i = 0; i < simplex.count; ++i) points[i] = simplex.vertices[i].w;
    const SimplexClosest closest = closestPointToOrigin(points, simplex.count, scale, facePoint);

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

// Grows an intersecting simplex into a tetrahedron around the origin for EPA: the origin is
// within rounding of the simplex, so adding points of A - B off its span (in the directions
// it lacks) gives a tetrahedron containing it. Stops early when A - B is itself flat.
void growToTetrahedron(const RelativePair& pair, Simplex& simplex, Real scale) {
    const Real minimumReach = Real(256) * kEpsilon * scale;
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

void toWorld(Simplex& simplex, const Vec3& offset) {
    for (int i = 0; i < simplex.count; ++i) {
        simplex.vertices[i].onA += offset;
        simplex.vertices[i].onB += offset;
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
    // A clean exit answers directly. The others (rounding floors, the cap) happen when the
    // origin is within rounding of the boundary of A - B, i.e. the shapes touch: then "touching
    // counts as intersecting" exactly when the closest point found is within tolerance.
    if (exit == GjkExit::Intersect || exit == GjkExit::Separated)
        result.intersect = exit == GjkExit::Intersect;
    else
        result.intersect = walk.v.squaredNorm() <= touchingSquared;
    // [ch02-gjk-verdict]
    result.exit = exit;
    result.newestDropped = walk.newestDropped;
    if (result.intersect) growToTetrahedron(pair, walk.simplex, tolerances.scale);
    result.simplex = walk.simplex;
    toWorld(result.simplex, pair.offset);
    return result;
}

GjkDistanceResult gjkDistance(const ConvexProxy& a, const ConvexProxy& b, int maxIterations) {
    GjkDistanceResult result;
    if (!isValidProxy(a) || !isValidProxy(b)) {
        result.exit = GjkExit::Degenerate;
        return result;
    }
    const RelativePair pair = seenFromA(a, b);
    const GjkTolerances tolerances = gjkTolerances(a, b);
    const Real touchingSquared = tolerances.touching * tolerances.touching;

    Walk walk = startWalk(pair, tolerances);
    result.iterations = 1;
    GjkExit exit = walk.v.squaredNorm() <= touchingSquared ? GjkExit::Intersect : GjkExit::IterationCap;
    // [ch02-distance-loop]
    while (exit == GjkExit::IterationCap && result.iterations < maxIterations) {
        const Vec3 direction = -walk.v;
        const SupportPoint point = minkowskiSupport(pair.a, pair.b, direction);
        ++result.iterations;

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
        addAndReduce(walk, point, tolerances.scale);
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

    // [ch02-closest-points]
    // v = sum_i weight_i (a_i - b_i), so the same weights applied to the shape points give the
    // closest point on each shape (van den Bergen 1999, section 3).
    result.separated = exit != GjkExit::Intersect && walk.v.squaredNorm() > touchingSquared;
    result.distance = result.separated ? walk.v.norm() : Real(0);
    for (int i = 0; i < walk.simplex.count; ++i) {
        result.pointA += walk.weights[i] * walk.simplex.vertices[i].onA;
        result.pointB += walk.weights[i] * walk.simplex.vertices[i].onB;
    }
    // [ch02-closest-points]
    result.pointA += pair.offset;
    result.pointB += pair.offset;
    result.exit = exit;
    result.newestDropped = walk.newestDropped;
    result.simplex = walk.simplex;
    toWorld(result.simplex, pair.offset);
    return result;
}

}  // namespace stepwise
