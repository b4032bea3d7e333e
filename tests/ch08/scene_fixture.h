#pragma once
// What chapter 8's scene tests share: whether a world's state is finite, frames stepped, a joint
// found by its body B's name, and where a hinge or a slider stands.

#include "08_joints/joint_frame.h"
#include "world/pipeline.h"
#include "world/world.h"

#include <catch2/catch.hpp>

#include <string>

namespace stepwise::test {

inline bool finiteState(const World& world) {
    for (const Body& body : world.bodies)
        if (!body.transform.position.allFinite() || !body.transform.rotation.coeffs().allFinite()) return false;
    for (const Motion& motion : world.motions)
        if (!motion.linearVelocity.allFinite() || !motion.angularVelocity.allFinite()) return false;
    return true;
}

inline void stepFrames(World& world, Pipeline& pipeline, int frames) {
    for (int frame = 0; frame < frames; ++frame) pipeline.step(world);
}

/// The joint whose body B has this name.
inline const JointDesc& jointTo(const World& world, const std::string& bodyB) {
    const int index = world.findBody(bodyB);
    for (const JointDesc& joint : world.joints)
        if (joint.bodyB == index) return joint;
    FAIL("no joint to " << bodyB);
    return world.joints.front();
}

inline Real angleAbout(const World& world, const JointDesc& joint) {
    return twistAngle(jointFrame(world, joint).deviation, joint.axis);
}

inline Real slide(const World& world, const JointDesc& joint) {
    const JointFrame frame = jointFrame(world, joint);
    return frame.axisA.dot(frame.anchorB - frame.anchorA);
}

}  // namespace stepwise::test
