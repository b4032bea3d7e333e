#pragma once
// The shapes and rays the ray-cast tests and `stepwise bench debug` share: one of each shape
// type at a tilted pose near y = 1, and random rays from 3 m away aimed into their bounds (most
// hit, the bounds' corners make some graze or miss).

#include "09_debug/ray_cast.h"
#include "math/random.h"

#include <vector>

namespace stepwise {

struct RayTarget {
    const char* name;
    Shape shape;
    Transform pose;
};

/// A sphere, a box, a capsule and a ten-point hull (a gem: an octagon and two apexes).
std::vector<RayTarget> rayTargets();

/// A ray from 3 m away aimed at a random point of the target's bounds.
Ray aimedRay(const RayTarget& target, Random& random);

}  // namespace stepwise
