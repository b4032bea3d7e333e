#pragma once
// A body's motion through one step, as continuous collision sees it: its centre of mass moves on
// a straight line and its orientation turns at a constant rate between the pose the step started
// from and the pose it ended at (Box2D's b2Sweep does the same; Catto, "Continuous Collision",
// GDC 2013). Time is the fraction t of the step, 0 at its start and 1 at its end.

#include "world/world.h"

namespace stepwise {

struct Sweep {
    Vec3 localCenter = Vec3::Zero();        // centre of mass in the body frame
    Vec3 center0 = Vec3::Zero();            // centre of mass at time alpha0, world
    Vec3 center1 = Vec3::Zero();            // centre of mass at the end of the step
    Quat rotation0 = Quat::Identity();      // orientation at time alpha0
    Quat rotation1 = Quat::Identity();      // at the end of the step
    Real alpha0 = 0;                        // fraction of the step where the sweep starts
};

/// A body that does not move over the step: a static body, or one stopped where it is.
Sweep stillSweep(const Transform& pose, const Vec3& localCenter);

/// The sweep between two poses of a body's origin.
Sweep sweepBetween(const Transform& start, const Transform& end, const Vec3& localCenter, Real alpha0 = 0);

/// Pose of the body origin at time t in [alpha0, 1]: centre by linear interpolation, rotation by
/// slerp, so the body turns at a constant angular speed.
Transform poseAt(const Sweep& sweep, Real t);

/// Angle the body turns through from alpha0 to 1, in [0, pi].
Real sweepAngle(const Sweep& sweep);

/// The farthest any point of the body travels over the sweep, m: |centre travel| plus the angle
/// times the lever arm about the centre of mass (maxLeverArm, world/shape.h, the rule chapter
/// 5's bounds use too; an arc is no longer than angle times radius).
Real sweepTravel(const Sweep& sweep, const Shape& shape);

/// The world box that holds the body at every time of the sweep (start and end boxes, grown by
/// the arc's bulge, angle times lever arm).
Aabb sweptBounds(const Sweep& sweep, const Shape& shape);

}  // namespace stepwise
