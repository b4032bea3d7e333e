#pragma once
// An exact box-box oracle, computed in double whatever Real is, for the GJK (chapter 2) and
// EPA (chapter 3) suites and benches.
//
// Overlap: the separating-axis test over the 15 candidate axes (3 face normals of A, 3 of B,
// 9 edge-edge cross products). For two boxes these contain every face normal of the Minkowski
// difference A - B, and the penetration depth is the smallest support distance of A - B over
// its face normals, so the minimum overlap over the 15 axes IS the exact depth (Gottschalk,
// Lin, Manocha 1996, "OBBTree"; Ericson, Real-Time Collision Detection, 4.4.1).
//
// Separation: the closest pair of two convex polyhedra is realised by vertex-feature or
// edge-edge pairs (a face-face or edge-face closest set is a convex polygon whose corners are
// again such pairs), so the distance is the minimum over the 16 vertex-versus-box distances
// and the 144 edge-edge segment distances (Ericson 5.1.9 for segment-segment).

#include "02_gjk/segments.h"
#include "math/math.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace stepwise {
namespace oracle {

using Vec3d = Eigen::Vector3d;
using Mat3d = Eigen::Matrix3d;

/// A box in world space: centre, axes (columns are the box's local x, y, z) and half extents.
struct OracleBox {
    Vec3d center = Vec3d::Zero();
    Mat3d axes = Mat3d::Identity();
    Vec3d halfExtents = Vec3d::Ones();
};

/// The box an engine shape describes, lifted to double (the float pose is taken as exact).
inline OracleBox makeOracleBox(const Vec3& halfExtents, const Transform& pose) {
    OracleBox box;
    box.center = pose.position.cast<double>();
    box.axes = pose.rotation.cast<double>().normalized().toRotationMatrix();
    box.halfExtents = halfExtents.cast<double>();
    return box;
}

/// The 8 corners; bit k of the index picks the sign along axis k.
inline std::array<Vec3d, 8> boxVertices(const OracleBox& box) {
    std::array<Vec3d, 8> vertices;
    for (int i = 0; i < 8; ++i) {
        Vec3d local((i & 1) ? box.halfExtents.x() : -box.halfExtents.x(),
                    (i & 2) ? box.halfExtents.y() : -box.halfExtents.y(),
                    (i & 4) ? box.halfExtents.z() : -box.halfExtents.z());
        vertices[i] = box.center + box.axes * local;
    }
    return vertices;
}

/// The 12 edges as pairs of corner indices (corners differing in one bit).
inline std::array<std::array<int, 2>, 12> boxEdges() {
    std::array<std::array<int, 2>, 12> edges{};
    int count = 0;
    for (int i = 0; i < 8; ++i)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(i & bit)) edges[count++] = {i, i | bit};
    return edges;
}

struct SatResult {
    bool overlap = false;
    /// Overlapping: the exact penetration depth (> 0). Separated: the largest gap over the 15
    /// axes (a lower bound of the distance, exact when a face axis separates best).
    double depth = 0;
    /// Unit axis from A towards B: translating B by depth * axis separates an overlapping pair.
    Vec3d axis = Vec3d::UnitX();
    /// 0-2: A's face normals, 3-5: B's, 6-14: edge pair cross(A axis i, B axis j) at 6 + 3i + j.
    int axisIndex = -1;
};

/// Separating-axis test over the 15 axes of two boxes.
inline SatResult boxSat(const OracleBox& a, const OracleBox& b) {
    const Vec3d offset = b.center - a.center;
    SatResult result;
    double bestOverlap = std::numeric_limits<double>::infinity();
    double bestGap = -std::numeric_limits<double>::infinity();
    auto testAxis = [&](Vec3d axis, int index) {
        const double length = axis.norm();
        // Parallel edges give a zero cross product; the face axes already cover that case.
        if (length < 1e-9) return;
        axis /= length;
        const double radiusA = (a.axes.transpose() * axis).cwiseAbs().dot(a.halfExtents);
        const double radiusB = (b.axes.transpose() * axis).cwiseAbs().dot(b.halfExtents);
        double centerDistance = axis.dot(offset);
        if (centerDistance < 0) {
            axis = -axis;
            centerDistance = -centerDistance;
        }
        const double overlap = radiusA + radiusB - centerDistance;
        if (overlap < 0) {
            if (-overlap > bestGap) {
                bestGap = -overlap;
                result.axis = axis;
                result.axisIndex = index;
            }
        } else if (bestGap < 0 && overlap < bestOverlap) {
            bestOverlap = overlap;
            result.axis = axis;
            result.axisIndex = index;
        }
    };
    for (int i = 0; i < 3; ++i) testAxis(a.axes.col(i), i);
    for (int j = 0; j < 3; ++j) testAxis(b.axes.col(j), 3 + j);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) testAxis(a.axes.col(i).cross(b.axes.col(j)), 6 + 3 * i + j);
    result.overlap = bestGap < 0;
    result.depth = result.overlap ? bestOverlap : bestGap;
    return result;
}

/// Distance from a point to a solid box, and the closest point of the box.
inline double pointBoxDistance(const Vec3d& point, const OracleBox& box, Vec3d* closest = nullptr) {
    const Vec3d local = box.axes.transpose() * (point - box.center);
    const Vec3d clamped = local.cwiseMax(-box.halfExtents).cwiseMin(box.halfExtents);
    if (closest) *closest = box.center + box.axes * clamped;
    return (local - clamped).norm();
}

/// Distance of segments p1q1 and p2q2, and optionally their closest points, in double.
inline double segmentSegmentDistance(const Vec3d& p1, const Vec3d& q1, const Vec3d& p2, const Vec3d& q2,
                                     Vec3d* closest1 = nullptr, Vec3d* closest2 = nullptr) {
    Vec3d c1, c2;
    closestPointsOfSegments(p1, q1, p2, q2, c1, c2);
    if (closest1) *closest1 = c1;
    if (closest2) *closest2 = c2;
    return (c1 - c2).norm();
}

struct DistanceResult {
    double distance = 0;              // 0 when the boxes overlap
    Vec3d pointA = Vec3d::Zero();     // closest point on A (meaningful when separated)
    Vec3d pointB = Vec3d::Zero();     // closest point on B
};

/// Exact distance between two boxes: min over vertex-box (both ways) and the 144 edge pairs.
/// Returns 0 for overlapping boxes (test boxSat first when the depth matters).
inline DistanceResult boxDistance(const OracleBox& a, const OracleBox& b) {
    DistanceResult best;
    if (boxSat(a, b).overlap) return best;
    best.distance = std::numeric_limits<double>::infinity();
    const auto verticesA = boxVertices(a);
    const auto verticesB = boxVertices(b);
    Vec3d onOther;
    for (const Vec3d& vertex : verticesA) {
        const double distance = pointBoxDistance(vertex, b, &onOther);
        if (distance < best.distance) best = {distance, vertex, onOther};
    }
    for (const Vec3d& vertex : verticesB) {
        const double distance = pointBoxDistance(vertex, a, &onOther);
        if (distance < best.distance) best = {distance, onOther, vertex};
    }
    const auto edges = boxEdges();
    Vec3d onA, onB;
    for (const auto& edgeA : edges) {
        for (const auto& edgeB : edges) {
            const double distance = segmentSegmentDistance(verticesA[edgeA[0]], verticesA[edgeA[1]],
                                                           verticesB[edgeB[0]], verticesB[edgeB[1]], &onA, &onB);
            if (distance < best.distance) best = {distance, onA, onB};
        }
    }
    return best;
}

/// Positive distance when separated, minus the penetration depth when overlapping.
inline double boxSignedDistance(const OracleBox& a, const OracleBox& b) {
    const SatResult sat = boxSat(a, b);
    return sat.overlap ? -sat.depth : boxDistance(a, b).distance;
}

}  // namespace oracle
}  // namespace stepwise
