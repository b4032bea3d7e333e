#pragma once
// Chapter 8's scenes: the sandbox (stacked boxes, a chain, a moving platform, a rotator and a
// ragdoll), the joint gallery, a pile of ragdolls, and the platform and rotator alone. One builder
// each, shared by the demo, the tests and the bench.

#include "world/world.h"

namespace stepwise {

class Registry;

/// A static ground box 40 m x 40 m, top face at y = 0.
void addGround(World& world);

/// A kinematic platform that follows a KinematicPath back and forth along x, with a dynamic box
/// resting on it: friction alone carries the box. The platform starts at the path's end, where
/// its speed is zero, so the box is not jerked off at the first step.
struct PlatformSpec {
    Vec3 center = Vec3(0, Real(0.5), 0);   // the middle of the platform's path
    Real amplitude = 2;                     // m along the platform's length
    Real heading = 0;                       // rad about +y: the length runs along x turned by this
    Real period = 4;                        // s: the largest acceleration, A (2 pi / T)^2 = 4.9 m/s^2,
                                            // stays below friction's 0.6 g = 5.9 m/s^2
    std::string prefix = "platform";        // the box is "<prefix>-rider"
};
int addMovingPlatform(World& world, const PlatformSpec& spec);  // returns the platform's index

/// A kinematic paddle spinning about the vertical at `spin` rad/s, sweeping the ground around
/// `center`, with small boxes and spheres in its way to be thrown out.
struct RotatorSpec {
    Vec3 center = Vec3::Zero();             // on the ground
    Real spin = 3;                          // rad/s about +y
    Real paddleHalfLength = Real(1.2);      // m: the tip moves at 3.6 m/s
    std::string prefix = "rotator";
};
int addRotator(World& world, const RotatorSpec& spec);          // returns the paddle's index

/// The chapter's first scene: a five-box stack, a ten-link chain of distance joints swinging from
/// a static anchor, a moving platform carrying a box, a rotator and a ragdoll dropped from 2 m.
World buildJointsSandbox();

/// One body per joint type, each on its own static post, in a row along x: a distance spring, a
/// ball socket, a hinge with limits, a hinge with a motor, a cone-twist, a slider and a weld.
World buildJointGallery();

/// The platform and its rider alone (the tests measure how well friction carries the box).
World buildPlatformScene();

/// The rotator and its targets alone.
World buildRotatorScene();

/// Ground and ten ragdolls dropped in a pile from 1 to 10 m, turned every way (seeded).
World buildRagdollPile(int ragdolls = 10, unsigned seed = 8);

/// Registers the chapter's scenes under "Joints", each drawn with JointView.
void addChapter08Scenes(Registry& registry);

}  // namespace stepwise
