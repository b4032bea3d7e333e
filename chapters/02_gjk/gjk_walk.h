#pragma once
// The machinery both GJK queries share (internal to chapter 2): the pair seen from A, the
// simplex walk, and the step that adds a support point and keeps the closest feature.

#include "02_gjk/gjk.h"

namespace stepwise {
namespace gjk_detail {

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
RelativePair seenFromA(const ConvexProxy& a, const ConvexProxy& b);
// [ch02-relative]

/// Bad input gets a defined answer (not intersecting, exit Degenerate) rather than NaN.
bool isValidProxy(const ConvexProxy& proxy);

/// The loop state both queries share: the simplex (seen from A), the weights of its vertices
/// that make the closest point v, and how often the newest vertex was not kept.
struct Walk {
    Simplex simplex;
    Real weights[4] = {1, 0, 0, 0};
    Vec3 v = Vec3::Zero();
    Vec3 firstDirection = Vec3::UnitX();
    int newestDropped = 0;
    bool degenerate = false;
    bool inside = false;
};

/// The first simplex: one support point towards B from inside A - B.
Walk startWalk(const RelativePair& pair, const GjkTolerances& tolerances);

/// True when w is within `tolerance` of a vertex of the simplex.
bool alreadyInSimplex(const Simplex& simplex, const Vec3& w, Real tolerance);

/// Adds a support point, finds the closest point of the grown simplex to the origin, and keeps
/// only the vertices of the feature that holds it.
void addAndReduce(Walk& walk, const SupportPoint& point, Real scale, FacePoint facePoint = FacePoint::Projection,
                  SimplexPrecision precision = SimplexPrecision::Working);

/// Moves the simplex's shape points back to world coordinates.
void toWorld(Simplex& simplex, const Vec3& offset);

}  // namespace gjk_detail
}  // namespace stepwise
