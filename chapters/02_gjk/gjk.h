#pragma once
// GJK (Gilbert, Johnson, Keerthi 1988): do two convex shapes intersect, and if not, how far
// apart are they? Both questions become questions about the origin and the Minkowski difference
// A - B = {a - b}: the shapes overlap exactly when A - B contains the origin, and their distance
// is the distance from the origin to A - B. GJK walks a simplex of support points of A - B
// towards the origin. Followed here: van den Bergen, "A Fast and Robust GJK Implementation for
// Collision Detection of Convex Objects" (JGT 1999) for the loop and its termination tests,
// Ericson, Real-Time Collision Detection (2005) 9.5 and 5.1 for the simplex sub-algorithm.

#include "02_gjk/closest_point.h"
#include "02_gjk/support.h"

namespace stepwise {

/// Up to four support points of A - B; the newest is last.
struct Simplex {
    SupportPoint vertices[4];
    int count = 0;
};

/// Why the loop stopped.
enum class GjkExit {
    Intersect,        // the simplex reached the origin: overlap (or touching within tolerance)
    Separated,        // found a plane separating the origin from A - B
    NoProgress,       // the simplex stopped getting closer to the origin (rounding floor)
    RepeatedSupport,  // the support point was already in the simplex
    Degenerate,       // the simplex collapsed (no area or volume), or the input was not finite
    IterationCap      // maxIterations support points without an answer
};

const char* toString(GjkExit exit);

struct GjkResult {
    bool intersect = false;
    /// The final simplex, support points in world space. When intersecting it is a tetrahedron
    /// holding the origin whenever A - B has volume (chapter 3's EPA starts from it).
    Simplex simplex;
    int iterations = 0;               // support points evaluated by the loop
    GjkExit exit = GjkExit::IterationCap;
    /// Times the closest feature of the simplex did not contain the newest support point: the
    /// regions a "skip the impossible regions" GJK never tests (docs/ch02_gjk.md).
    int newestDropped = 0;
};

/// Boolean GJK: stops as soon as a separating plane or the origin is found. `facePoint` is for
/// the bench's comparison only (FacePoint::BarycentricSum is the less accurate textbook form).
GjkResult gjkIntersect(const ConvexProxy& a, const ConvexProxy& b, int maxIterations = 75,
                       FacePoint facePoint = FacePoint::Projection);

struct GjkDistanceResult {
    bool separated = false;
    Real distance = 0;                // 0 when not separated
    Vec3 pointA = Vec3::Zero();       // closest point on A (world)
    Vec3 pointB = Vec3::Zero();       // closest point on B (world)
    /// Unit axis from A's core towards B's (the last search direction): the contact normal of
    /// shapes that touch within round-off, where pointB - pointA is too short to have one. Zero
    /// when the cores themselves overlap.
    Vec3 axis = Vec3::Zero();
    /// How far the shapes overlap when their cores are apart but their radii reach across (a
    /// sphere or a capsule sunk into another shape): the radii minus the cores' distance, exact,
    /// along `axis`. Zero otherwise (apart, or the cores themselves overlap).
    Real radiusOverlap = 0;
    /// The final simplex; for spheres and capsules it is that of their cores (a point, a
    /// segment), which the walk uses instead of the round shapes (gjk_distance.cpp).
    Simplex simplex;
    int iterations = 0;
    GjkExit exit = GjkExit::IterationCap;
    int newestDropped = 0;
};

/// Distance GJK: runs until the closest point of A - B to the origin is found to a relative
/// tolerance; pointA - pointB is the shortest vector between the shapes.
GjkDistanceResult gjkDistance(const ConvexProxy& a, const ConvexProxy& b, int maxIterations = 75);

/// The tolerances GJK uses for a pair, all relative to the pair's size so that millimetre and
/// kilometre shapes behave alike.
struct GjkTolerances {
    Real scale = 0;          // m: sum of the two shapes' bounding radii
    Real touching = 0;       // m: a closest point this near the origin counts as contact
    Real relative = 0;       // distance converged when the bound gap is this fraction of it
};
GjkTolerances gjkTolerances(const ConvexProxy& a, const ConvexProxy& b);

}  // namespace stepwise
