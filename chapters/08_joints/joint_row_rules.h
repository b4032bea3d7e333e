#pragma once
// The rules that turn each joint type into rows (joint_rows.h says which slot holds what), written
// once for whatever collects the rows: a Builder with
//   equality(row, error)           C = 0 wanted
//   limit(row, gap)                C >= 0 wanted (a limit), impulse >= 0
//   motor(row, speed, maxForce)    J v driven towards speed, impulse within maxForce h either way
//   spring(row, error, softness)   a distance spring of its own softness
//   unused(bodyA, bodyB)           a slot the joint does not use now
// and a flag blockWithoutJacobians (the point rows of a block its solve pushes by the arms: their
// linear part alone). Chapter 8 collects them into a JointRowBatch (joint_rows.cpp); chapter 11
// writes them straight into its lanes.

#include "04_pgs/contact_constraints.h"
#include "06_manifolds/stabilisation.h"
#include "08_joints/joint_frame.h"
#include "world/world.h"

#include <optional>
#include <utility>

namespace stepwise::joint_rules {

// [ch08-row-shapes]
// A row that measures how fast two points close along n: point B (arm armB from B's centre of
// mass) minus point A (arm armA from A's). d/dt (pB - pA) . n with n fixed: J = [-n, -rA x n, n, rB x n],
// chapter 4's contact row.
inline ConstraintRow linearRow(int bodyA, int bodyB, const Vec3& armA, const Vec3& armB, const Vec3& direction) {
    return pointVelocityRow(bodyA, bodyB, direction, armA, armB);
}

// A row that measures how fast B turns relative to A about a world axis: (wB - wA) . axis.
inline ConstraintRow angularRow(int bodyA, int bodyB, const Vec3& axis) {
    ConstraintRow row;
    row.bodyA = bodyA;
    row.bodyB = bodyB;
    row.angularA = -axis;
    row.angularB = axis;
    return row;
}
// [ch08-row-shapes]

inline ConstraintRow negated(ConstraintRow row) {
    row.linearA = -row.linearA;
    row.angularA = -row.angularA;
    row.linearB = -row.linearB;
    row.angularB = -row.angularB;
    return row;
}

// Two unit vectors perpendicular to `axis` and to each other.
inline void perpendiculars(const Vec3& axis, Vec3& first, Vec3& second) { tangentBasis(axis, first, second); }

// [ch08-point-rows]
// Slots 0-2 of the point joints: the anchors coincide, one row per world axis (solved as a block).
template <class Builder>
void addPointRows(Builder& builder, const JointDesc& joint, const JointFrame& frame) {
    const Vec3 gap = frame.anchorB - frame.anchorA;
    for (int axis = 0; axis < 3; ++axis) {
        if (!builder.blockWithoutJacobians) {
            builder.equality(linearRow(joint.bodyA, joint.bodyB, frame.armA, frame.armB, Vec3::Unit(axis)), gap[axis]);
            continue;
        }
        ConstraintRow row;
        row.linearA = -Vec3::Unit(axis);
        row.linearB = Vec3::Unit(axis);
        builder.equality(row, gap[axis]);
    }
}
// [ch08-point-rows]

// B turns with A: one row per world axis, the error the deviation's small-angle vector.
template <class Builder>
void addWeldRows(Builder& builder, const JointDesc& joint, const JointFrame& frame) {
    const Vec3 error = rotationError(frame);
    for (int axis = 0; axis < 3; ++axis)
        builder.equality(angularRow(joint.bodyA, joint.bodyB, Vec3::Unit(axis)), error[axis]);
}

// [ch08-limit-rows]
// The two limit slots of a coordinate x (an angle or a travel) that `along` measures the rate of:
// lower wants x - lo >= 0, upper wants hi - x >= 0.
template <class Builder>
void addLimitRows(Builder& builder, const JointDesc& joint, const ConstraintRow& along, Real coordinate,
                  const std::optional<std::pair<Real, Real>>& limits) {
    if (!limits) {
        builder.unused(joint.bodyA, joint.bodyB);
        builder.unused(joint.bodyA, joint.bodyB);
        return;
    }
    builder.limit(along, coordinate - limits->first);
    builder.limit(negated(along), limits->second - coordinate);
}

template <class Builder>
void addLimitAndMotorRows(Builder& builder, const JointDesc& joint, const ConstraintRow& along, Real coordinate,
                          const std::optional<std::pair<Real, Real>>& limits) {
    addLimitRows(builder, joint, along, coordinate, limits);
    if (joint.motor)
        builder.motor(along, joint.motor->speed, joint.motor->maxForce);
    else if (joint.frictionTorque > 0)  // a hinge's joint friction: the motor slot at speed zero
        builder.motor(along, 0, joint.frictionTorque);
    else
        builder.unused(joint.bodyA, joint.bodyB);
}
// [ch08-limit-rows]

// [ch08-hinge-rows]
template <class Builder>
void addHingeRows(Builder& builder, const JointDesc& joint, const JointFrame& frame) {
    addPointRows(builder, joint, frame);
    // B's axis stays on A's: its components along two directions b, c across A's axis are zero.
    // d/dt (axisB . b) = (wB x axisB) . b + axisB . (wA x b) = (axisB x b) . (wB - wA).
    Vec3 across[2];
    perpendiculars(frame.axisA, across[0], across[1]);
    for (const Vec3& direction : across)
        builder.equality(angularRow(joint.bodyA, joint.bodyB, frame.axisB.cross(direction)), frame.axisB.dot(direction));
    // The angle turns at (wB - wA) . axis; the lower limit wants angle - lo >= 0, the upper hi - angle >= 0.
    const Real angle = twistAngle(frame.deviation, joint.axis);
    const ConstraintRow turn = angularRow(joint.bodyA, joint.bodyB, frame.axisA);
    addLimitAndMotorRows(builder, joint, turn, angle, joint.limits);
}
// [ch08-hinge-rows]

// [ch08-cone-twist-rows]
template <class Builder>
void addConeTwistRows(Builder& builder, const JointDesc& joint, const JointFrame& frame) {
    addPointRows(builder, joint, frame);
    // Swing: the angle between the axes grows at (wB - wA) . s with s = axisA x axisB normalised;
    // the cone wants coneAngle - swing >= 0. Aligned axes: no direction, and far from any cone.
    const Vec3 swingDirection = frame.axisA.cross(frame.axisB);
    const Real swing = swingAngle(frame);
    const Real swingLength = swingDirection.norm();
    if (swingLength > Real(1e-6))
        builder.limit(negated(angularRow(joint.bodyA, joint.bodyB, swingDirection / swingLength)), joint.coneAngle - swing);
    else
        builder.unused(joint.bodyA, joint.bodyB);
    // Twist about the mean of the two axes (the twist axis of A and B differ by the swing).
    const Vec3 mean = frame.axisA + frame.axisB;
    const Vec3 twistAxis = mean.norm() > Real(1e-6) ? Vec3(mean.normalized()) : frame.axisA;
    const Real twist = twistAngle(frame.deviation, joint.axis);
    addLimitRows(builder, joint, angularRow(joint.bodyA, joint.bodyB, twistAxis), twist, joint.twistLimits);
    // Joint friction (Box2D's ragdoll): zero-speed motors about the world axes.
    for (int axis = 0; axis < 3; ++axis) {
        if (joint.frictionTorque > 0)
            builder.motor(angularRow(joint.bodyA, joint.bodyB, Vec3::Unit(axis)), 0, joint.frictionTorque);
        else
            builder.unused(joint.bodyA, joint.bodyB);
    }
}
// [ch08-cone-twist-rows]

// [ch08-slider-rows]
template <class Builder>
void addSliderRows(Builder& builder, const JointDesc& joint, const JointFrame& frame) {
    // B's anchor stays on the line through A's anchor along A's axis. The offset d = pB - pA is
    // measured along directions n that turn with A, so d/dt (d . n) also has d . (wA x n): A's arm
    // reaches B's anchor, rA + d.
    const Vec3 gap = frame.anchorB - frame.anchorA;
    const Vec3 armToB = frame.armA + gap;
    Vec3 across[2];
    perpendiculars(frame.axisA, across[0], across[1]);
    for (const Vec3& direction : across)
        builder.equality(linearRow(joint.bodyA, joint.bodyB, armToB, frame.armB, direction), gap.dot(direction));
    addWeldRows(builder, joint, frame);
    const Real travel = gap.dot(frame.axisA);
    addLimitAndMotorRows(builder, joint, linearRow(joint.bodyA, joint.bodyB, armToB, frame.armB, frame.axisA), travel,
                         joint.limits);
}
// [ch08-slider-rows]

/// A distance joint's row before its feedback: a spring of its own, or an equality.
struct DistanceRow {
    ConstraintRow row;
    Real error = 0;
    bool spring = false;
    Softness springSoftness;
};
DistanceRow distanceRow(const JointDesc& joint, const JointFrame& frame, Real h);

template <class Builder>
void addDistanceRow(Builder& builder, const JointDesc& joint, const JointFrame& frame, Real h) {
    const DistanceRow distance = distanceRow(joint, frame, h);
    if (distance.spring)
        builder.spring(distance.row, distance.error, distance.springSoftness);
    else
        builder.equality(distance.row, distance.error);
}

/// Every slot of `joint` at `frame`, in slot order.
template <class Builder>
void addRowsOf(Builder& builder, const JointDesc& joint, const JointFrame& frame, Real h) {
    switch (joint.type) {
        case JointType::Distance: addDistanceRow(builder, joint, frame, h); break;
        case JointType::BallSocket: addPointRows(builder, joint, frame); break;
        case JointType::Hinge: addHingeRows(builder, joint, frame); break;
        case JointType::ConeTwist: addConeTwistRows(builder, joint, frame); break;
        case JointType::Slider: addSliderRows(builder, joint, frame); break;
        case JointType::Fixed:
            addPointRows(builder, joint, frame);
            addWeldRows(builder, joint, frame);
            break;
    }
}

}  // namespace stepwise::joint_rules
