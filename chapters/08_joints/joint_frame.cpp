#include "08_joints/joint_frame.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

bool jointBodiesValid(const World& world, const JointDesc& joint) {
    const int count = static_cast<int>(world.bodies.size());
    return joint.bodyA >= 0 && joint.bodyB >= 0 && joint.bodyA < count && joint.bodyB < count && joint.bodyA != joint.bodyB;
}

JointFrame jointFrame(const World& world, const JointDesc& joint) {
    return jointFrame(joint, world.bodies[static_cast<std::size_t>(joint.bodyA)].transform,
                      worldCenterOfMass(world, joint.bodyA), world.bodies[static_cast<std::size_t>(joint.bodyB)].transform,
                      worldCenterOfMass(world, joint.bodyB));
}

JointFrame jointFrame(const JointDesc& joint, const Transform& poseA, const Vec3& centerA, const Transform& poseB,
                      const Vec3& centerB) {
    JointFrame frame = jointRowFrame(joint, poseA, centerA, poseB, centerB);
    if (turnsFreely(joint.type)) addTurn(frame, joint, poseA, poseB);
    return frame;
}

JointFrame jointRowFrame(const JointDesc& joint, const Transform& poseA, const Vec3& centerA, const Transform& poseB,
                         const Vec3& centerB) {
    JointFrame frame;
    frame.anchorA = poseA.apply(joint.localAnchorA);
    frame.anchorB = poseB.apply(joint.localAnchorB);
    frame.armA = frame.anchorA - centerA;
    frame.armB = frame.anchorB - centerB;
    if (!turnsFreely(joint.type)) addTurn(frame, joint, poseA, poseB);
    return frame;
}

void addTurn(JointFrame& frame, const JointDesc& joint, const Transform& poseA, const Transform& poseB) {
    frame.rotationA = poseA.rotation;
    Quat deviation = (poseA.rotation.conjugate() * poseB.rotation) * joint.referenceRotation.conjugate();
    if (deviation.w() < 0) deviation.coeffs() = -deviation.coeffs();  // the shorter way round
    frame.deviation = deviation.normalized();
    frame.axisA = poseA.rotation * joint.axis;
    frame.axisB = poseA.rotation * (frame.deviation * joint.axis);
}

// [ch08-twist]
Real twistAngle(const Quat& deviation, const Vec3& localAxis) {
    // The deviation is swing * twist with the twist about localAxis; the twist quaternion is the
    // deviation's part along the axis (w, (v . a) a), normalised, so its angle is this.
    return 2 * math::atan2(deviation.vec().dot(localAxis), deviation.w());
}
// [ch08-twist]

// atan2 of the sine and cosine, not the arc cosine of the dot product: near 1 the cosine moves
// by angle^2 / 2, and the arc cosine of the float just below 1 is already 3.45e-4 rad, so no
// smaller swing can be read that way.
Real swingAngle(const JointFrame& frame) {
    return math::atan2(frame.axisA.cross(frame.axisB).norm(), frame.axisA.dot(frame.axisB));
}

Vec3 rotationError(const JointFrame& frame) { return frame.rotationA * (2 * frame.deviation.vec()); }

namespace {

// How far an angle is outside [lo, hi] (0 inside).
Real beyond(Real value, const std::pair<Real, Real>& limits) {
    return std::max({limits.first - value, value - limits.second, Real(0)});
}

// The whole angle B has turned away from rest.
Real turnAngle(const JointFrame& frame) { return 2 * math::atan2(frame.deviation.vec().norm(), frame.deviation.w()); }

}  // namespace

JointError measureJointError(const World& world, const JointDesc& joint) {
    const JointFrame frame = jointFrame(world, joint);
    const Vec3 gap = frame.anchorB - frame.anchorA;
    JointError error;
    switch (joint.type) {
        case JointType::Distance:
            error.position = std::abs(gap.norm() - joint.length.value_or(gap.norm()));  // as the solver reads it
            break;
        case JointType::BallSocket: error.position = gap.norm(); break;
        case JointType::Hinge:
            error.position = gap.norm();
            error.angle = swingAngle(frame);
            if (joint.limits) error.angle = std::max(error.angle, beyond(twistAngle(frame.deviation, joint.axis), *joint.limits));
            break;
        case JointType::ConeTwist:
            error.position = gap.norm();
            error.angle = std::max(swingAngle(frame) - joint.coneAngle, Real(0));
            if (joint.twistLimits)
                error.angle = std::max(error.angle, beyond(twistAngle(frame.deviation, joint.axis), *joint.twistLimits));
            break;
        case JointType::Slider: {
            const Vec3 along = frame.axisA * frame.axisA.dot(gap);
            error.position = (gap - along).norm();
            if (joint.limits) error.position = std::max(error.position, beyond(frame.axisA.dot(gap), *joint.limits));
            error.angle = turnAngle(frame);
            break;
        }
        case JointType::Fixed:
            error.position = gap.norm();
            error.angle = turnAngle(frame);
            break;
    }
    return error;
}

}  // namespace stepwise
