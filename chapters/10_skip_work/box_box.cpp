// Box against box by separating axes (box_box.h).
#include "10_skip_work/box_box.h"

#include "02_gjk/segments.h"

#include <cmath>

namespace stepwise {

namespace {

/// Edge pairs closer to parallel than this (the sine of their angle) give no axis of their own:
/// a face axis of one of the boxes already covers them, and their cross product is round-off.
constexpr Real kParallelSine = Real(1e-4);

bool isUsableBox(const Shape& shape) {
    return shape.type == ShapeType::Box && shape.halfExtents.allFinite() && (shape.halfExtents.array() > 0).all();
}

bool isUsablePose(const Transform& transform) {
    return transform.position.allFinite() && transform.rotation.coeffs().allFinite() &&
           transform.rotation.norm() > Real(0.5);
}

/// The vertex of a box (centre, axes as columns, half extents) furthest along `direction`.
Vec3 boxSupport(const Vec3& centre, const Mat3& axes, const Vec3& half, const Vec3& direction) {
    Vec3 point = centre;
    for (int k = 0; k < 3; ++k) point += (axes.col(k).dot(direction) >= 0 ? half[k] : -half[k]) * axes.col(k);
    return point;
}

/// The edge of a box along its axis `along` that supports it in `direction`: the segment's ends.
void supportingEdge(const Vec3& centre, const Mat3& axes, const Vec3& half, int along, const Vec3& direction,
                    Vec3& start, Vec3& end) {
    Vec3 middle = centre;
    for (int k = 0; k < 3; ++k)
        if (k != along) middle += (axes.col(k).dot(direction) >= 0 ? half[k] : -half[k]) * axes.col(k);
    start = middle - half[along] * axes.col(along);
    end = middle + half[along] * axes.col(along);
}

}  // namespace

// [ch10-box-box]
ContactQuery boxBoxQuery(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb) {
    if (!isUsableBox(a) || !isUsableBox(b) || !isUsablePose(ta) || !isUsablePose(tb)) return collideShapes(a, ta, b, tb);
    // In A's frame, centred on A: B's axes as the columns of `turn`, B's centre at `offset`.
    const Mat3 axesA = ta.rotation.normalized().toRotationMatrix();
    const Mat3 axesB = tb.rotation.normalized().toRotationMatrix();
    const Mat3 turn = axesA.transpose() * axesB;
    const Vec3 offset = axesA.transpose() * (tb.position - ta.position);
    const Vec3& halfA = a.halfExtents;
    const Vec3& halfB = b.halfExtents;

    // Each axis's separation: the gap between the two boxes' shadows on it (< 0: they overlap).
    Real bestSeparation = -kRealMax;
    Vec3 bestNormal = Vec3::UnitY();  // A's frame, from A towards B
    int bestKind = -1;                // 0-2 a face of A, 3-5 a face of B, 6-14 an edge of A and one of B
    const auto tryAxis = [&](const Vec3& axis, int kind) {
        const Vec3 unit = axis / axis.norm();
        const Real reachA = halfA.dot(unit.cwiseAbs());
        const Real reachB = halfB.dot((turn.transpose() * unit).cwiseAbs());
        const Real along = offset.dot(unit);
        const Real separation = std::abs(along) - reachA - reachB;
        // Ties go to the earlier axis (faces before edges), so a pose always picks the same one.
        if (separation > bestSeparation) {
            bestSeparation = separation;
            bestNormal = along >= 0 ? unit : Vec3(-unit);
            bestKind = kind;
        }
    };
    for (int i = 0; i < 3; ++i) tryAxis(Vec3::Unit(i), i);
    for (int j = 0; j < 3; ++j) tryAxis(turn.col(j), 3 + j);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const Vec3 axis = Vec3::Unit(i).cross(turn.col(j));
            if (axis.norm() > kParallelSine) tryAxis(axis, 6 + 3 * i + j);
        }

    ContactQuery query;
    query.routine = "box_box_sat";
    query.depth = -bestSeparation;
    query.intersect = bestSeparation < 0;
    const Vec3 normal = axesA * bestNormal;
    query.normal = normal;
    // Witness points, relative to A's centre until the end.
    const Vec3 centreB = tb.position - ta.position;
    Vec3 pointA, pointB;
    if (bestKind < 3) {
        pointB = boxSupport(centreB, axesB, halfB, -normal);  // B's deepest corner towards A
        pointA = pointB + query.depth * normal;
    } else if (bestKind < 6) {
        pointA = boxSupport(Vec3::Zero(), axesA, halfA, normal);
        pointB = pointA - query.depth * normal;
    } else {
        Vec3 startA, endA, startB, endB;
        supportingEdge(Vec3::Zero(), axesA, halfA, (bestKind - 6) / 3, normal, startA, endA);
        supportingEdge(centreB, axesB, halfB, (bestKind - 6) % 3, -normal, startB, endB);
        closestPointsOfSegments<Real>(startA, endA, startB, endB, pointA, pointB);
    }
    query.pointA = pointA + ta.position;
    query.pointB = pointB + ta.position;
    return query;
}
// [ch10-box-box]

ContactQuery fastContactQuery(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                              const CollideOptions& options) {
    if (a.type == ShapeType::Box && b.type == ShapeType::Box) return boxBoxQuery(a, ta, b, tb);
    return collideShapes(a, ta, b, tb, options);
}

}  // namespace stepwise
