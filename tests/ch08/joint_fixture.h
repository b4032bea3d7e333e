#pragma once
// What the chapter 8 tests share: a static post to hang things from, and degrees.

#include "world/world.h"

namespace stepwise::test {


/// A static 10 cm cube at the origin.
inline int addPost(World& world) { return addStaticBox(world, "post", Vec3::Zero(), Vec3::Constant(Real(0.05))); }

/// A dynamic box body: its name, half extents, mass and position.
inline BodyDef boxBody(const char* name, const Vec3& halfExtents, Real mass, const Vec3& position = Vec3::Zero()) {
    BodyDef body;
    body.name = name;
    body.shape = Shape::box(halfExtents);
    body.mass = mass;
    body.transform.position = position;
    return body;
}

/// A joint of `type` between bodies a and b with B's anchor and the axis given (A's anchor at A's origin).
inline JointDesc jointBetween(JointType type, int bodyA, int bodyB, const Vec3& anchorB, const Vec3& axis) {
    JointDesc joint;
    joint.type = type;
    joint.bodyA = bodyA;
    joint.bodyB = bodyB;
    joint.localAnchorB = anchorB;
    joint.axis = axis;
    return joint;
}

}  // namespace stepwise::test
