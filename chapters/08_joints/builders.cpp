#include "08_joints/builders.h"

#include "08_joints/joint_frame.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

Chain addChain(World& world, const ChainSpec& spec) {
    Chain chain;
    chain.anchorBody = addStaticBox(world, spec.prefix + "-anchor", spec.anchor, Vec3::Constant(Real(0.05)));
    const Vec3 direction = spec.direction.normalized();
    int previous = chain.anchorBody;
    for (int i = 0; i < spec.links; ++i) {
        BodyDef link;
        link.name = spec.prefix + std::to_string(i);
        link.shape = Shape::sphere(spec.linkRadius);
        link.mass = (i == spec.links - 1 && spec.endMass > 0) ? spec.endMass : spec.linkMass;
        link.transform.position = spec.anchor + direction * (spec.linkLength * Real(i + 1));
        const int body = addBody(world, link);
        JointDesc joint;
        joint.type = spec.joint;
        joint.bodyA = previous;
        joint.bodyB = body;
        // A's anchor is where B's centre is.
        joint.localAnchorA = direction * spec.linkLength;
        joint.localAnchorB = Vec3::Zero();
        if (spec.joint == JointType::Distance) {
            joint.localAnchorA = Vec3::Zero();
            joint.length = spec.linkLength;
        }
        chain.joints.push_back(static_cast<int>(world.joints.size()));
        world.joints.push_back(joint);
        chain.links.push_back(body);
        previous = body;
    }
    chain.restLength = spec.linkLength * Real(spec.links);
    return chain;
}

Real chainStretch(const World& world, const Chain& chain) {
    Real length = 0;
    for (int jointIndex : chain.joints) {
        const JointFrame frame = jointFrame(world, world.joints[static_cast<std::size_t>(jointIndex)]);
        const JointDesc& joint = world.joints[static_cast<std::size_t>(jointIndex)];
        // A distance joint's anchors are the link centres; a ball socket's meet at B's centre, so
        // the link's own length is the distance between the centres.
        length += joint.type == JointType::Distance
                      ? (frame.anchorB - frame.anchorA).norm()
                      : (worldCenterOfMass(world, joint.bodyB) - worldCenterOfMass(world, joint.bodyA)).norm();
    }
    return (length - chain.restLength) / chain.restLength;
}

namespace {

// [ch08-ragdoll-parts]
// Segment mass fractions after Winter, "Biomechanics and Motor Control of Human Movement" (Dempster's
// data): head and neck 8.1%, trunk 49.7% (here 30% chest, 19.7% pelvis), upper arm 2.8%, forearm and
// hand 2.2%, thigh 10%, leg and foot 6.1%.
struct Part {
    const char* name;
    Shape shape;
    Vec3 center;       // standing pose, relative to the pelvis
    Real massFraction;
};
// [ch08-ragdoll-parts]

}  // namespace

Ragdoll addRagdoll(World& world, const RagdollSpec& spec) {
    const Real armX = Real(0.23), hipX = Real(0.09);
    const Vec3 chest(0, Real(0.32), 0);
    const Vec3 shoulder[2] = {chest + Vec3(-armX, Real(0.17), 0), chest + Vec3(armX, Real(0.17), 0)};
    const Vec3 elbow[2] = {shoulder[0] - Vec3(0, Real(0.3), 0), shoulder[1] - Vec3(0, Real(0.3), 0)};
    const Vec3 hip[2] = {Vec3(-hipX, Real(-0.1), 0), Vec3(hipX, Real(-0.1), 0)};
    const Vec3 knee[2] = {hip[0] - Vec3(0, Real(0.44), 0), hip[1] - Vec3(0, Real(0.44), 0)};
    const Vec3 neck = chest + Vec3(0, Real(0.2), 0);
    const Vec3 spine(0, Real(0.11), 0);
    const std::vector<Part> parts = {
        {"pelvis", Shape::box(Vec3(Real(0.15), Real(0.1), Real(0.1))), Vec3::Zero(), Real(0.197)},
        {"chest", Shape::box(Vec3(Real(0.17), Real(0.2), Real(0.1))), chest, Real(0.30)},
        {"head", Shape::sphere(Real(0.1)), neck + Vec3(0, Real(0.12), 0), Real(0.081)},
        {"upper-arm-left", Shape::capsule(Real(0.05), Real(0.1)), shoulder[0] - Vec3(0, Real(0.15), 0), Real(0.028)},
        {"forearm-left", Shape::capsule(Real(0.045), Real(0.1)), elbow[0] - Vec3(0, Real(0.145), 0), Real(0.022)},
        {"upper-arm-right", Shape::capsule(Real(0.05), Real(0.1)), shoulder[1] - Vec3(0, Real(0.15), 0), Real(0.028)},
        {"forearm-right", Shape::capsule(Real(0.045), Real(0.1)), elbow[1] - Vec3(0, Real(0.145), 0), Real(0.022)},
        {"thigh-left", Shape::capsule(Real(0.07), Real(0.15)), hip[0] - Vec3(0, Real(0.22), 0), Real(0.10)},
        {"shin-left", Shape::capsule(Real(0.055), Real(0.15)), knee[0] - Vec3(0, Real(0.205), 0), Real(0.061)},
        {"thigh-right", Shape::capsule(Real(0.07), Real(0.15)), hip[1] - Vec3(0, Real(0.22), 0), Real(0.10)},
        {"shin-right", Shape::capsule(Real(0.055), Real(0.15)), knee[1] - Vec3(0, Real(0.205), 0), Real(0.061)},
    };
    Ragdoll ragdoll;
    for (const Part& part : parts) {
        BodyDef def;
        def.name = spec.prefix + "-" + part.name;
        def.shape = part.shape;
        def.mass = spec.mass * part.massFraction;
        def.transform.position = spec.pelvis + spec.orientation * part.center;
        def.transform.rotation = spec.orientation;
        ragdoll.bodies.push_back(addBody(world, def));
    }
    // [ch08-ragdoll-joints]
    // Joints at standing-pose points, axes in the (shared) body frame. Cone-twist axes run along
    // the child bone; hinges turn about the left-right axis: elbows bend forward, knees back.
    const auto join = [&](JointType type, int partA, int partB, const Vec3& at, const Vec3& axis) -> JointDesc& {
        JointDesc joint;
        joint.type = type;
        joint.bodyA = ragdoll.bodies[static_cast<std::size_t>(partA)];
        joint.bodyB = ragdoll.bodies[static_cast<std::size_t>(partB)];
        joint.localAnchorA = at - parts[static_cast<std::size_t>(partA)].center;
        joint.localAnchorB = at - parts[static_cast<std::size_t>(partB)].center;
        joint.axis = axis;
        joint.frictionTorque = spec.frictionTorque;
        ragdoll.joints.push_back(static_cast<int>(world.joints.size()));
        world.joints.push_back(joint);
        return world.joints.back();
    };
    const Real degree = kPi / 180;
    const Vec3 up = Vec3::UnitY(), down = -Vec3::UnitY(), across = Vec3::UnitX();
    JointDesc& spineJoint = join(JointType::ConeTwist, 0, 1, spine, up);
    spineJoint.coneAngle = 25 * degree;
    spineJoint.twistLimits = {-20 * degree, 20 * degree};
    JointDesc& neckJoint = join(JointType::ConeTwist, 1, 2, neck, up);
    neckJoint.coneAngle = 40 * degree;
    neckJoint.twistLimits = {-60 * degree, 60 * degree};
    for (int side = 0; side < 2; ++side) {
        const int upperArm = 3 + 2 * side, forearm = 4 + 2 * side, thigh = 7 + 2 * side, shin = 8 + 2 * side;
        JointDesc& shoulderJoint = join(JointType::ConeTwist, 1, upperArm, shoulder[side], down);
        shoulderJoint.coneAngle = 80 * degree;
        shoulderJoint.twistLimits = {-45 * degree, 45 * degree};
        JointDesc& elbowJoint = join(JointType::Hinge, upperArm, forearm, elbow[side], across);
        elbowJoint.limits = {-140 * degree, 0};
        JointDesc& hipJoint = join(JointType::ConeTwist, 0, thigh, hip[side], down);
        hipJoint.coneAngle = 60 * degree;
        hipJoint.twistLimits = {-30 * degree, 30 * degree};
        JointDesc& kneeJoint = join(JointType::Hinge, thigh, shin, knee[side], across);
        kneeJoint.limits = {0, 140 * degree};
    }
    // [ch08-ragdoll-joints]
    return ragdoll;
}

JointErrorSummary largestJointError(const World& world, const std::vector<int>& joints) {
    JointErrorSummary summary;
    for (int jointIndex : joints) {
        const JointError error = measureJointError(world, world.joints[static_cast<std::size_t>(jointIndex)]);
        summary.position = std::max(summary.position, error.position);
        summary.angle = std::max(summary.angle, error.angle);
    }
    return summary;
}

}  // namespace stepwise
