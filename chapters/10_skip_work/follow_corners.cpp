// The four-lane point follow (follow_corners.h).
#include "10_skip_work/follow_corners.h"

#include "03_epa/chapter.h"

#include <algorithm>

namespace stepwise {

namespace {

constexpr int kLanes = 4;  // a manifold's most points

/// Four points, a coordinate at a time.
struct LanePoints {
    Real x[kLanes] = {}, y[kLanes] = {}, z[kLanes] = {};
};

// Transform::apply on four points: position + q v q*, written as turnVector writes it (Eigen's
// order: uv = 2 axis x v, then (v + w uv) + axis x uv, each cross product's terms as Eigen's).
// Whole arrays of locals in and out: the compiler takes the four lanes in one register each.
LanePoints applyToLanes(const Transform& transform, const LanePoints& v) {
    const Real qx = transform.rotation.x(), qy = transform.rotation.y(), qz = transform.rotation.z();
    const Real w = transform.rotation.w();
    const Real px = transform.position.x(), py = transform.position.y(), pz = transform.position.z();
    LanePoints out;
    for (int k = 0; k < kLanes; ++k) {
        Real ux = qy * v.z[k] - qz * v.y[k], uy = qz * v.x[k] - qx * v.z[k], uz = qx * v.y[k] - qy * v.x[k];
        ux += ux;
        uy += uy;
        uz += uz;
        const Real cx = qy * uz - qz * uy, cy = qz * ux - qx * uz, cz = qx * uy - qy * ux;
        out.x[k] = px + ((v.x[k] + w * ux) + cx);
        out.y[k] = py + ((v.y[k] + w * uy) + cy);
        out.z[k] = pz + ((v.z[k] + w * uz) + cz);
    }
    return out;
}

}  // namespace

void followCorners(const Body& bodyA, const Body& bodyB, Contact& contact) {
    if (isRound(bodyA.shape) || isRound(bodyB.shape)) return followContact(bodyA, bodyB, contact);
    const int count = std::min(std::max(contact.pointCount, 0), kLanes);
    LanePoints anchorA, anchorB;
    for (int i = 0; i < count; ++i) {
        const ContactPoint& point = contact.points[i];
        anchorA.x[i] = point.localAnchorA.x(), anchorA.y[i] = point.localAnchorA.y(), anchorA.z[i] = point.localAnchorA.z();
        anchorB.x[i] = point.localAnchorB.x(), anchorB.y[i] = point.localAnchorB.y(), anchorB.z[i] = point.localAnchorB.z();
    }
    const LanePoints a = applyToLanes(bodyA.transform, anchorA), b = applyToLanes(bodyB.transform, anchorB);
    for (int i = 0; i < count; ++i) {
        ContactPoint& point = contact.points[i];
        point.pointA = Vec3(a.x[i], a.y[i], a.z[i]);
        point.pointB = Vec3(b.x[i], b.y[i], b.z[i]);
        // Eigen's own dot product: it sums a 3-vector's products in one order for floats and in
        // another for doubles (two to a register), and the depth must be followContact's.
        point.depth = contact.normal.dot(point.pointA - point.pointB);
    }
}

}  // namespace stepwise
