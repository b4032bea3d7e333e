// The Expanding Polytope Algorithm (see epa.h for sources). The file reads top to bottom as the
// algorithm runs: a starting tetrahedron around the origin, then repeatedly pick the closest face and ask for a
// support point beyond it (polytope.cpp cuts the faces that point sees and stitches new ones
// across the horizon), and finally map the origin's projection on the closest face back to a
// point on each shape. When the polytope cannot give the answer, epa_fallback.cpp does.
#include "03_epa/epa.h"

#include "03_epa/epa_fallback.h"
#include "03_epa/polytope.h"
#include "world/enum_names.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

const char* toString(EpaExit exit) {
    static const Names<EpaExit> names = {{"converged", EpaExit::Converged},
                                         {"iteration_cap", EpaExit::IterationCap},
                                         {"step_limit", EpaExit::StepLimit},
                                         {"no_progress", EpaExit::NoProgress},
                                         {"degenerate", EpaExit::Degenerate}};
    return nameOf(names, exit, "unknown");
}

namespace {

using namespace epa_polytope;
using epa_fallback::answerWithBound;
using epa_fallback::fallbackContact;
using epa_fallback::UpperBound;

using tolerance::kCoplanar;
constexpr Real kTouching = tolerance::kSeedContainment;

// Support points the search for a starting tetrahedron may spend before it gives up: the search
// recurses over subsets of GJK's points and over directions, and a pathological input must not
// turn it into thousands of queries (GJK's own points usually need none, a shallow contact a few).
constexpr int kSeedBudget = 64;

/// A stop by round-off counts as converged within this many tolerances of the boundary.
constexpr Real kUnconverged = 16;

struct EpaContext {
    const ConvexProxy& a;
    const ConvexProxy& b;
    Real scale = 1;
    int seedSupports = 0;
};

bool containsOrigin(const SupportPoint points[4], Real slack);

// [ch03-start-polytope]
/// The polytope's first faces need a tetrahedron around the origin. GJK often stops earlier:
/// with a triangle or an edge through the origin (touching or shallow contact) or a single
/// point. Following Bullet's EncloseOrigin, add support points in directions the current points
/// do not span until four points bound a volume that holds the origin.
bool growToTetrahedron(EpaContext& context, SupportPoint points[4], int count) {
    const Vec3 axes[3] = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
    const auto tryDirection = [&](const Vec3& direction) {
        if (++context.seedSupports > kSeedBudget) return false;
        points[count] = minkowskiSupport(context.a, context.b, direction);
        return growToTetrahedron(context, points, count + 1);
    };
    switch (count) {
        case 1:  // a single point: try the six axis directions for a second one
            for (const Vec3& axis : axes) {
                if (tryDirection(axis) || tryDirection(-axis)) return true;
            }
            return false;
        case 2: {  // an edge: try directions perpendicular to it
            const Vec3 edge = points[1].w - points[0].w;
            for (const Vec3& axis : axes) {
                const Vec3 side = edge.cross(axis);
                if (side.squaredNorm() <= Real(0)) continue;
                if (tryDirection(side) || tryDirection(-side)) return true;
            }
            return false;
        }
        case 3: {  // a triangle: try both sides of its plane
            const Vec3 normal = (points[1].w - points[0].w).cross(points[2].w - points[0].w);
            if (normal.squaredNorm() <= Real(0)) return false;
            return tryDirection(normal) || tryDirection(-normal);
        }
        default: {
            const Vec3 e1 = points[1].w - points[0].w, e2 = points[2].w - points[0].w,
                       e3 = points[3].w - points[0].w;
            // The sign of the volume orients every face, so it must be clear of its round-off
            // (a few ulps of the product of the edge lengths); a thin tetrahedron is fine.
            const Real volume = std::abs(e1.cross(e2).dot(e3));
            const bool solid = volume > kRoundOff * e1.norm() * e2.norm() * e3.norm();
            // GJK calls shapes within its touching tolerance (about 100 ulps of the size) of each
            // other intersecting, so the origin may lie that far outside their simplex.
            return solid && containsOrigin(points, kTouching * context.scale);
        }
    }
}
// [ch03-start-polytope]

/// GJK's points are normally the starting tetrahedron itself. When they cannot be (four points on
/// one plane, three on one line), fewer of them can: try again with each point left out in turn.
bool seedTetrahedron(EpaContext& context, SupportPoint points[4], int count) {
    SupportPoint trial[4];
    std::copy(points, points + count, trial);
    if (growToTetrahedron(context, trial, count)) {
        std::copy(trial, trial + 4, points);
        return true;
    }
    for (int skip = 0; skip < count && count > 1; ++skip) {
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            if (i != skip) trial[kept++] = points[i];
        }
        if (seedTetrahedron(context, trial, kept)) {
            std::copy(trial, trial + 4, points);
            return true;
        }
    }
    return false;
}

/// True when the origin is inside the tetrahedron or within `slack` of it.
bool containsOrigin(const SupportPoint points[4], Real slack) {
    static const int kFaces[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
    for (const auto& face : kFaces) {
        const Vec3& p0 = points[face[0]].w;
        Vec3 normal = (points[face[1]].w - p0).cross(points[face[2]].w - p0);
        const Real length = normal.norm();
        if (!(length > Real(0))) return false;
        normal /= length;
        // Orient the plane away from the fourth vertex, then the origin must not be beyond it.
        if (normal.dot(points[face[3]].w - p0) > 0) normal = -normal;
        if (normal.dot(-p0) > slack) return false;
    }
    return true;
}

/// The face the contact comes from. A face of A - B that EPA has split into several coplanar
/// triangles gives them all the same distance up to round-off, and the smallest of those may
/// well be a triangle the origin does not project into. Among the faces within `tolerance` of
/// the closest and in its plane (only that plane is known to bound A - B), take the one whose
/// projection lies deepest inside its triangle.
int contactFace(const EpaPolytope& polytope, int closest, Real tolerance) {
    const EpaFace& closestFace = polytope.faces[closest];
    const Real limit = closestFace.distance + tolerance;
    int best = closest;
    Real bestInside = projectionWeights(polytope, closestFace).minCoeff();
    for (int f = 0; f < static_cast<int>(polytope.faces.size()) && bestInside < 0; ++f) {
        const EpaFace& face = polytope.faces[f];
        if (face.removed || face.distance > limit || face.normal.dot(closestFace.normal) < kCoplanar) continue;
        const Real inside = projectionWeights(polytope, face).minCoeff();
        if (inside > bestInside) {
            best = f;
            bestInside = inside;
        }
    }
    return best;
}

// [ch03-contact]
/// The origin projects onto the closest face at depth * normal. Its barycentric coordinates in
/// that face weight the shapes' own support points, giving a point on A and a point on B with
/// pointA - pointB = depth * normal.
void contactFromFace(const EpaPolytope& polytope, const EpaFace& face, EpaResult& result) {
    const SupportPoint& s0 = polytope.vertices[face.vertices[0]];
    const SupportPoint& s1 = polytope.vertices[face.vertices[1]];
    const SupportPoint& s2 = polytope.vertices[face.vertices[2]];
    Vec3 weights = projectionWeights(polytope, face);
    // Round-off (or a polytope stopped early) can put the projection a hair outside the face:
    // clamp to the triangle so the points stay on the shapes.
    weights = weights.cwiseMax(Real(0));
    const Real sum = weights.sum();
    weights = sum > 0 && isFinite(sum) ? Vec3(weights / sum) : Vec3(Real(1) / 3, Real(1) / 3, Real(1) / 3);

    result.depth = std::max(face.distance, Real(0));
    result.normal = face.normal;
    result.pointA = weights[0] * s0.onA + weights[1] * s1.onA + weights[2] * s2.onA;
    result.pointB = weights[0] * s0.onB + weights[1] * s1.onB + weights[2] * s2.onB;
    result.barycentric = weights;
    result.closestFace[0] = s0;
    result.closestFace[1] = s1;
    result.closestFace[2] = s2;
}
// [ch03-contact]

}  // namespace

// [ch03-loop]
EpaResult epaPenetration(const ConvexProxy& a, const ConvexProxy& b, const Simplex& simplex,
                         const EpaSettings& settings) {
    if (simplex.count < 1 || simplex.count > 4) return fallbackContact(a, b, simplex);

    // The tolerance is relative to the pair's size (GJK's scale: the sum of the bounding radii);
    // below a few ulps of that size a float cannot tell a gap from round-off, so it never asks
    // for less.
    EpaContext context{a, b, gjkTolerances(a, b).scale, 0};
    if (!(context.scale > 0) || !isFinite(context.scale)) return fallbackContact(a, b, simplex);
    const Real tolerance = std::max(settings.relativeTolerance, kRoundOff) * context.scale;

    SupportPoint points[4];
    std::copy(simplex.vertices, simplex.vertices + simplex.count, points);
    EpaPolytope polytope;
    // Room for every vertex and face the iteration cap allows (each expansion adds one vertex
    // and at most two faces net), so the loop never reallocates.
    const int expansionLimit = std::max(0, settings.maxIterations);
    polytope.vertices.reserve(4 + expansionLimit);
    polytope.faces.reserve(4 + 2 * expansionLimit);
    if (!seedTetrahedron(context, points, simplex.count) || !initPolytope(polytope, points, context.scale)) {
        return fallbackContact(a, b, simplex);
    }

    ExpansionScratch scratch;

    EpaResult result;
    // The closest face's distance bounds the depth from below, the reach of A - B along any
    // normal (its support) from above: moving B that far along it separates the shapes. The
    // tightest upper bound seen is kept for a polytope that stops growing far from converged.
    UpperBound best;
    Real lastGap = 0;
    int closest = closestFace(polytope);
    for (;;) {
        // Ask A - B for its furthest point along the closest face's normal. If it is no further
        // out than the face (within the tolerance), that face lies on the boundary: done.
        const EpaFace& face = polytope.faces[closest];
        const SupportPoint support = minkowskiSupport(a, b, face.normal);
        if (!isFinite(support.w)) {
            result.exit = EpaExit::NoProgress;
            break;
        }
        const Real reach = face.normal.dot(support.w);
        if (reach < best.reach) best = {reach, face.normal, support};
        lastGap = reach - face.distance;
        if (lastGap <= tolerance) {
            result.exit = EpaExit::Converged;
            break;
        }
        if (result.iterations >= settings.maxIterations) {
            result.exit = EpaExit::IterationCap;
            break;
        }
        if (settings.maxExpansions >= 0 && result.iterations >= settings.maxExpansions) {
            result.exit = EpaExit::StepLimit;
            break;
        }
        // A point already in the polytope, or a horizon broken by round-off, means the polytope
        // has stopped growing: the current face is as good as this precision allows.
        if (isDuplicate(polytope, support.w, context.scale) ||
            !expandPolytope(polytope, closest, support, context.scale, scratch)) {
            result.exit = EpaExit::NoProgress;
            break;
        }
        ++result.iterations;
        closest = closestFace(polytope);
    }

    if (result.exit == EpaExit::NoProgress && lastGap > kUnconverged * tolerance) {
        // Stopped by round-off far from the boundary (a plate 1/1600 of its width thick around
        // a small box: the closest face passed through the origin, 3.8 mm inside the boundary):
        // the face's points would lie that far inside the shapes. Any direction's reach is a
        // true way out instead, so the answer is the shortest found among the normals EPA tried,
        // every face of its polytope and the candidates of fallbackContact (a separating-axis
        // search over the directions at hand).
        for (const EpaFace& face : polytope.faces) {
            if (face.removed) continue;
            const SupportPoint support = minkowskiSupport(a, b, face.normal);
            const Real reach = face.normal.dot(support.w);
            if (isFinite(reach) && reach < best.reach) best = {reach, face.normal, support};
        }
        const EpaResult candidates = fallbackContact(a, b, simplex);
        if (candidates.depth < best.reach) best = {candidates.depth, candidates.normal, candidates.closestFace[0]};
        answerWithBound(a, b, best, kUnconverged * tolerance, result);
    } else {
        contactFromFace(polytope, polytope.faces[contactFace(polytope, closest, tolerance)], result);
    }
    if (settings.keepPolytope) result.polytope = std::move(polytope);
    return result;
}
// [ch03-loop]

}  // namespace stepwise
