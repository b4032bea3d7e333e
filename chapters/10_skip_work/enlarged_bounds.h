#pragma once
// Chapter 10's broadphase: chapter 5's sweep, run only when a body has left the box it was swept
// in. The sweep runs on every box grown by a margin (Box3D's fat AABBs, 0.1 m) and keeps the pairs
// it found; while every body's box stays inside its grown one, any pair whose boxes overlap now had
// overlapping grown boxes then, so the kept pairs filtered by this step's boxes are exactly what a
// new sweep would return. A pyramid at rest pays one containment test per body and one overlap
// test per kept pair instead of a sweep.

#include "world/world.h"

namespace stepwise {

/// The broadphase stage for a scene that chapter 5 would sweep: world.candidatePairs in canonical
/// order, the same pairs as sweepAndPrune; world.broadphase.sweepSkipped says whether it swept.
/// Each box grows by Settings::boundsMargin on every side (m).
void sweepAndPruneEnlarged(World& world);

}  // namespace stepwise
