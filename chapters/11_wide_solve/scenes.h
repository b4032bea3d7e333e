#pragma once
// Chapter 11's demo scenes: a pyramid big enough to fill the wide blocks, and a field of ragdolls
// whose joints are solved in the same substeps as their contacts.

#include "app/registry.h"
#include "world/world.h"

namespace stepwise {

/// `ragdolls` ragdolls (chapter 8's, joint friction `frictionTorque` N m; 0 for a peer that has no
/// cone-twist friction) dropped in columns of four on a square grid 2 m apart, lying down and
/// turned every way (seeded), onto a static ground: 11 bodies and 10 joints each.
World buildRagdollField(int ragdolls, Real frictionTorque = Real(0.5), unsigned seed = 11);

void addChapter11Scenes(Registry& registry);

}  // namespace stepwise
