#pragma once
// The sub-algorithm at the heart of GJK: the point of a simplex (point, segment, triangle or
// tetrahedron) closest to the origin, found by testing which Voronoi region of the simplex holds
// the origin, and that point's barycentric coordinates. Every region is tested: nothing is
// assumed about where the origin cannot be (see docs/ch02_gjk.md, "Every region, every time").
// Follows Ericson, Real-Time Collision Detection (2005), 5.1.2, 5.1.5 and 5.1.6.

#include "math/math.h"

namespace stepwise {

/// How the closest point on a triangle's face is formed. Projection (the default) is accurate;
/// BarycentricSum is the textbook a + v ab + w ac, kept so the bench can show what it costs.
enum class FacePoint { Projection, BarycentricSum };

/// The answer in the scalar S it was found in (Real; double for SimplexPrecision::Double).
template <typename S>
struct SimplexClosestOf {
    Eigen::Matrix<S, 3, 1> point = Eigen::Matrix<S, 3, 1>::Zero();  // closest point of the simplex to the origin
    S weights[4] = {0, 0, 0, 0};         // barycentric weights of the input points, summing to 1
    int kept[4] = {0, 0, 0, 0};          // input indices of the smallest feature holding point
    int keptCount = 0;
    bool inside = false;                 // tetrahedron only: the origin is inside or on it
    bool degenerate = false;             // a zero-length, -area or -volume simplex was met
};
using SimplexClosest = SimplexClosestOf<Real>;

/// The arithmetic the closest point is found in. Working: Real's. Double: double whatever Real
/// is, for the walks float cannot finish: on a feature whose points lie tens of metres from the
/// origin while the origin is millimetres from it, a float sum of them carries eps |p| and turns
/// the closest point's direction by eps |p| / |v| (gjkDistance's second walk).
enum class SimplexPrecision { Working, Double };

/// Closest point to the origin of the simplex spanned by points[0..count-1] (1 <= count <= 4).
/// `scale` (m) is the size of the shapes: lengths, areas and volumes below a few rounding
/// errors of it count as zero, so the answer does not depend on units.
SimplexClosest closestPointToOrigin(const Vec3* points, int count, Real scale,
                                    FacePoint facePoint = FacePoint::Projection,
                                    SimplexPrecision precision = SimplexPrecision::Working);

}  // namespace stepwise
