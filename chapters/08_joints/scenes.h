#pragma once
// Chapter 8's scenes: the sandbox (stacked boxes, a chain, a moving platform, a rotator and a
// ragdoll), the joint gallery, a pile of ragdolls. One builder each, shared by the demo, the tests
// and the bench.

#include "world/world.h"

namespace stepwise {

class Registry;

/// A static ground box 40 m x 40 m, top face at y = 0.
void addGround(World& world);

/// Ground and ten ragdolls dropped in a pile from 1 to 10 m, turned every way (seeded).
World buildRagdollPile(int ragdolls = 10, unsigned seed = 8);

/// Registers the chapter's scenes under "Joints".
void addChapter08Scenes(Registry& registry);

}  // namespace stepwise
