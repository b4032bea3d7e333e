#pragma once
// Where a joint is right now: its anchors and axes in world space, and how far body B has turned
// away from its rest orientation in A's frame, split the ways the joint types measure it (a
// hinge's angle, a cone-twist's swing and twist, a weld's small-angle error). Every row of
// joint_rows.h is built from one JointFrame.

#include "world/world.h"

namespace stepwise {

struct JointFrame {
    Vec3 anchorA = Vec3::Zero();     // world anchor points
    Vec3 anchorB = Vec3::Zero();
    Vec3 armA = Vec3::Zero();        // from each body's centre of mass to its anchor
    Vec3 armB = Vec3::Zero();
    Vec3 axisA = Vec3::UnitY();      // the joint axis as body A carries it, world frame
    Vec3 axisB = Vec3::UnitY();      // the same axis as body B carries it (equal at rest)
    /// B's turn away from rest, in A's frame: (qA^-1 qB) reference^-1, with w >= 0.
    Quat deviation = Quat::Identity();
    Quat rotationA = Quat::Identity();
};

/// The frame of joint `joint` with the bodies where they are now.
/// Whether the joint names two different bodies of the world (what every use of it checks first).
bool jointBodiesValid(const World& world, const JointDesc& joint);

JointFrame jointFrame(const World& world, const JointDesc& joint);
/// The same with the bodies' poses and centres of mass given (a solve that keeps its own).
JointFrame jointFrame(const JointDesc& joint, const Transform& poseA, const Vec3& centerA, const Transform& poseB,
                      const Vec3& centerB);

/// Whether a joint's rows leave the bodies' relative turn free (a distance joint, a ball socket):
/// its rows read only the anchors and arms of its frame.
constexpr bool turnsFreely(JointType type) { return type == JointType::Distance || type == JointType::BallSocket; }

/// What the joint's rows read of its frame: the anchors and arms, and the turn (axes, deviation)
/// only where the type locks or limits it. A solve that builds rows every substep calls this:
/// the turn is a third of the frame's arithmetic.
JointFrame jointRowFrame(const JointDesc& joint, const Transform& poseA, const Vec3& centerA, const Transform& poseB,
                         const Vec3& centerB);

/// The turn part of `frame`: A's rotation, B's deviation from rest in A's frame, the axes.
void addTurn(JointFrame& frame, const JointDesc& joint, const Transform& poseA, const Transform& poseB);

// [ch08-angles]
/// The angle B has turned about the joint axis (a hinge's angle; a cone-twist's twist): the twist
/// part of the deviation, 2 atan2(v . axis, w), in (-pi, pi].
Real twistAngle(const Quat& deviation, const Vec3& localAxis);

/// The angle between the axis as A and as B carry it (a cone-twist's swing), in [0, pi].
Real swingAngle(const JointFrame& frame);

/// The small-angle rotation error of a weld, world frame: 2 v of the deviation (w >= 0). Zero at
/// rest; for small turns its components are the turn's angles about the world axes.
Vec3 rotationError(const JointFrame& frame);
// [ch08-angles]

/// How far a joint is from what it asks, after a step: the anchors' gap (m; a distance joint's
/// length error) and the largest angle by which a locked axis or a limit is off (rad).
struct JointError {
    Real position = 0;
    Real angle = 0;
};
JointError measureJointError(const World& world, const JointDesc& joint);

}  // namespace stepwise
