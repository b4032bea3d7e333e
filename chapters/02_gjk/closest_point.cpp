// Closest point of a simplex to the origin by Voronoi regions (Ericson, Real-Time Collision
// Detection, 2005: 5.1.2 segment, 5.1.5 triangle, 5.1.6 tetrahedron), with the query point
// fixed at the origin so p - x becomes -x.

#include "02_gjk/closest_point.h"

#include "02_gjk/tolerances.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stepwise {
namespace {

using tolerance::kDegenerateFraction;
using tolerance::kRoundOff;

// The routines below run in the scalar S of their points: Real, or double for a walk that
// Real = float cannot finish (SimplexPrecision::Double). Their tolerances stay the working
// type's: the points themselves carry its rounding.
template <typename S>
SimplexClosestOf<S> vertexResult(const Eigen::Matrix<S, 3, 1>* points, int i) {
    SimplexClosestOf<S> result;
    result.point = points[i];
    result.weights[i] = 1;
    result.kept[0] = i;
    result.keptCount = 1;
    return result;
}

// Point a + t (b - a) of edge ij.
template <typename S>
SimplexClosestOf<S> edgeResult(const Eigen::Matrix<S, 3, 1>* points, int i, int j, S t) {
    SimplexClosestOf<S> result;
    result.point = points[i] + t * (points[j] - points[i]);
    result.weights[i] = 1 - t;
    result.weights[j] = t;
    result.kept[0] = i;
    result.kept[1] = j;
    result.keptCount = 2;
    return result;
}

template <typename S>
SimplexClosestOf<S> closestOnSegment(const Eigen::Matrix<S, 3, 1>* points, int i, int j, S scale) {
    using V = Eigen::Matrix<S, 3, 1>;
    const S fraction = S(kDegenerateFraction);
    const V& a = points[i];
    const V ab = points[j] - a;
    const S lengthSquared = ab.squaredNorm();
    if (lengthSquared <= fraction * fraction * scale * scale) {
        // Both points coincide: the segment is a point; keep the nearer one.
        SimplexClosestOf<S> result = vertexResult(points, points[j].squaredNorm() < a.squaredNorm() ? j : i);
        result.degenerate = true;
        return result;
    }
    const S t = -a.dot(ab);                    // projection of the origin, times |ab|^2
    if (t <= 0) return vertexResult(points, i);                 // region of A
    if (t >= lengthSquared) return vertexResult(points, j);     // region of B
    return edgeResult(points, i, j, t / lengthSquared);         // region of the edge
}

// [ch02-triangle]
// Ericson 5.1.5 with p = 0. Each test is one Voronoi region: the three vertex regions, the
// three edge regions, and the face. d1..d6 are the projections of the origin onto the two edges
// from each vertex; va, vb, vc are (twice) the signed areas that give the barycentric
// coordinates of the origin's projection onto the plane.
template <typename S>
SimplexClosestOf<S> closestOnTriangle(const Eigen::Matrix<S, 3, 1>* points, int ia, int ib, int ic, S scale,
                               FacePoint facePoint) {
    using V = Eigen::Matrix<S, 3, 1>;
    const S fraction = S(kDegenerateFraction);
    const V& a = points[ia];
    const V& b = points[ib];
    const V& c = points[ic];
    const V ab = b - a;
    const V ac = c - a;

    const S d1 = -ab.dot(a);
    const S d2 = -ac.dot(a);
    if (d1 <= 0 && d2 <= 0) return vertexResult(points, ia);             // vertex A

    const S d3 = -ab.dot(b);
    const S d4 = -ac.dot(b);
    if (d3 >= 0 && d4 <= d3) return vertexResult(points, ib);            // vertex B

    const S vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return edgeResult(points, ia, ib, d1 / (d1 - d3));  // edge AB

    const S d5 = -ab.dot(c);
    const S d6 = -ac.dot(c);
    if (d6 >= 0 && d5 <= d6) return vertexResult(points, ic);            // vertex C

    const S vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return edgeResult(points, ia, ic, d2 / (d2 - d6));  // edge AC

    const S va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)                     // edge BC
        return edgeResult(points, ib, ic, (d4 - d3) / ((d4 - d3) + (d5 - d6)));

    // Face region. va + vb + vc = |ab x ac|^2; when that is ~0 the triangle is a sliver whose
    // "face" has no well-defined plane: fall back to the best of its three edges. The test is
    // sin^2 of the angle at a against the square of the fraction (as for the segment's length
    // above): a sliver is a triangle thinner than 256 rounding errors, not thinner than 0.3
    // degrees, which the Minkowski difference of a 100:1 needle and a small box routinely is.
    const auto nearestEdge = [&](bool degenerate) {
        SimplexClosestOf<S> best = closestOnSegment(points, ia, ib, scale);
        for (const SimplexClosestOf<S>& edge : {closestOnSegment(points, ia, ic, scale), closestOnSegment(points, ib, ic, scale)})
            if (edge.point.squaredNorm() < best.point.squaredNorm()) best = edge;
        best.degenerate = best.degenerate || degenerate;
        return best;
    };
    const S denominator = va + vb + vc;
    if (!(denominator > fraction * fraction * ab.squaredNorm() * ac.squaredNorm())) {
        return nearestEdge(true);
    }
    // The weights from cross products, not from va, vb, vc: those are differences of products
    // of dot products, which cancel on a long thin triangle (a 9 m plate against a 5 mm box)
    // and leave weights that no longer rebuild the point, so the closest points GJK reports
    // from them disagree with its distance. The cross products keep their relative precision.
    const V normal = ab.cross(ac);
    const S normalSquared = normal.squaredNorm();
    const S v = normal.dot(ac.cross(a)) / normalSquared;      // n . ((o - a) x ac) / |n|^2
    const S w = normal.dot(a.cross(ab)) / normalSquared;      // n . (ab x (o - a)) / |n|^2
    // The same cancellation can put a 28 m by 14 cm triangle's origin in the face region when
    // it projects well beyond an edge: weights of -0.5 gave a closest point on a box 6 cm
    // outside the box (found by fuzz_narrowphase). The accurate weights decide: clearly outside
    // the triangle, the nearest edge holds the closest point.
    if (std::min({v, w, 1 - v - w}) < -fraction) return nearestEdge(false);
    SimplexClosestOf<S> result;
    // The point itself as the projection onto the plane, not as a + v ab + w ac: that sum
    // carries an absolute rounding error of eps |a|, which near contact (|point| << |a|) turns
    // its direction by up to eps |a| / |point|. The normal comes from the edges alone, so this
    // form keeps the direction exact to rounding; the search direction GJK takes from it then
    // still finds the separating plane at distances of 1e-4 of the shapes' size in float.
    result.point = facePoint == FacePoint::Projection ? V(normal * (normal.dot(a) / normalSquared))
                                                      : V(a + v * ab + w * ac);
    result.weights[ia] = 1 - v - w;
    result.weights[ib] = v;
    result.weights[ic] = w;
    result.kept[0] = ia;
    result.kept[1] = ib;
    result.kept[2] = ic;
    result.keptCount = 3;
    return result;
}
// [ch02-triangle]

// [ch02-tetrahedron]
// Ericson 5.1.6: the origin is outside the tetrahedron exactly when it lies on the far side of
// some face plane (opposite the fourth vertex). The closest point is then on one of those faces,
// and the nearest face answer wins. Inside every face plane means inside the tetrahedron.
template <typename S>
SimplexClosestOf<S> closestOnTetrahedron(const Eigen::Matrix<S, 3, 1>* points, S scale, FacePoint facePoint) {
    using V = Eigen::Matrix<S, 3, 1>;
    // Each face, listed with the vertex opposite it.
    static const int kFaces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    SimplexClosestOf<S> best;
    S bestDistanceSquared = std::numeric_limits<S>::max();
    bool anyOutside = false;
    bool degenerate = false;
    bool solid = true;
    S originSide[4] = {0, 0, 0, 0};
    S oppositeSide[4] = {0, 0, 0, 0};
    for (int f = 0; f < 4; ++f) {
        const V& a = points[kFaces[f][0]];
        const V ab = points[kFaces[f][1]] - a;
        const V ac = points[kFaces[f][2]] - a;
        const V ad = points[kFaces[f][3]] - a;
        const V normal = ab.cross(ac);
        originSide[f] = -a.dot(normal);
        oppositeSide[f] = ad.dot(normal);
        // Flat: a volume within a few hundred rounding errors of the product of the edges. Solid:
        // clear of the triple product's own rounding (a few ulps of that product), the bar EPA's
        // starting tetrahedron must clear too.
        const S edges = ab.norm() * ac.norm() * ad.norm();
        degenerate = degenerate || std::abs(oppositeSide[f]) <= S(kDegenerateFraction) * edges;
        solid = solid && std::abs(oppositeSide[f]) > S(kRoundOff) * edges;
    }
    // A thin tetrahedron whose every sign is clear holds the origin when it lies on the inner
    // side of all four faces. Of a 27 m needle hull and a 6 cm box GJK meets tetrahedra 21 ulps
    // thick that hold the origin so; taken for flat, GJK would return one of their faces, 1 mm
    // from the origin, again and again, and the pair would read as only touching.
    bool holdsOrigin = solid;
    for (int f = 0; f < 4; ++f)
        holdsOrigin = holdsOrigin && ((originSide[f] > 0 && oppositeSide[f] > 0) || (originSide[f] < 0 && oppositeSide[f] < 0));
    if (holdsOrigin) degenerate = false;
    for (int f = 0; f < 4; ++f) {
        // A flat tetrahedron has no inside; test every face instead of trusting the signs. All
        // four, not only the face whose test said flat: the test scales with each face's own
        // edges, so of a 40 m by 2 mm sliver (a box resting on a large ground box) one face reads
        // flat and the others do not, and the face nearest the origin would go untested.
        const bool outside =
            degenerate || (originSide[f] > 0 && oppositeSide[f] < 0) || (originSide[f] < 0 && oppositeSide[f] > 0);
        if (!outside) continue;
        anyOutside = true;
        SimplexClosestOf<S> onFace = closestOnTriangle(points, kFaces[f][0], kFaces[f][1], kFaces[f][2], scale, facePoint);
        const S distanceSquared = onFace.point.squaredNorm();
        if (distanceSquared < bestDistanceSquared) {
            bestDistanceSquared = distanceSquared;
            best = onFace;
        }
    }
    if (anyOutside) {
        best.degenerate = best.degenerate || degenerate;
        return best;
    }
    // Inside (or on the boundary): the origin is its own closest point. Its barycentric weight
    // for each vertex is the volume of the tetrahedron with that vertex replaced by the origin,
    // over the whole volume: originSide / oppositeSide of the face opposite the vertex.
    SimplexClosestOf<S> inside;
    inside.inside = true;
    inside.keptCount = 4;
    for (int f = 0; f < 4; ++f) {
        inside.kept[f] = f;
        inside.weights[kFaces[f][3]] = originSide[f] / oppositeSide[f];
    }
    return inside;
}
// [ch02-tetrahedron]


template <typename S>
SimplexClosestOf<S> closestIn(const Eigen::Matrix<S, 3, 1>* points, int count, S scale, FacePoint facePoint) {
    switch (count) {
        case 1: return vertexResult(points, 0);
        case 2: return closestOnSegment(points, 0, 1, scale);
        case 3: return closestOnTriangle(points, 0, 1, 2, scale, facePoint);
        default: return closestOnTetrahedron(points, scale, facePoint);
    }
}

SimplexClosest toWorking(const SimplexClosestOf<double>& in) {
    SimplexClosest out;
    out.point = in.point.cast<Real>();
    for (int i = 0; i < 4; ++i) {
        out.weights[i] = static_cast<Real>(in.weights[i]);
        out.kept[i] = in.kept[i];
    }
    out.keptCount = in.keptCount;
    out.inside = in.inside;
    out.degenerate = in.degenerate;
    return out;
}

}  // namespace

SimplexClosest closestPointToOrigin(const Vec3* points, int count, Real scale, FacePoint facePoint,
                                    SimplexPrecision precision) {
    if (precision == SimplexPrecision::Working) return closestIn(points, count, scale, facePoint);
    Eigen::Vector3d wide[4];
    for (int i = 0; i < count; ++i) wide[i] = points[i].cast<double>();
    return toWorking(closestIn(wide, count, static_cast<double>(scale), facePoint));
}

}  // namespace stepwise
