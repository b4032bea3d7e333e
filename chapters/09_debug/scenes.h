#pragma once
// Chapter 9's demo scenes: small cases to take apart with the tools, one per worked example of
// the page (a first contact, a hull's EPA face, a box that tunnels, a stack that jitters).

#include "world/world.h"

#include <vector>

namespace stepwise {

class Registry;

/// "debug-drop": a tilted box and, later, a ball fall onto the ground: hold Space and the run
/// stops on the frame each first touches.
World buildDebugDrop();

/// A gem of ten points: an octagon ring of radius 0.3 m and two apexes, 0.6 m tall (the hull of
/// debug-hull-on-box and of the ray-cast tests).
std::vector<Vec3> gemPoints();

/// "debug-hull-on-box": a convex hull dropped onto a crate on the ground: the EPA face and A - B.
World buildDebugHullOnBox();

/// "debug-tunnel": a bullet fired at a thin wall with continuous collision off: it passes
/// through between two frames, which the rewind shows (and `ccd` on cures).
World buildDebugTunnel();

/// "debug-jitter": a five-box stack with warm starting off: the impulses in the hit tree
/// flicker from frame to frame instead of settling.
World buildDebugJitter();

void addChapter09Scenes(Registry& registry);

}  // namespace stepwise
