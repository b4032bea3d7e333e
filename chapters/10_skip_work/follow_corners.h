#pragma once
// A carried record's points followed on their bodies, the four points at once. Chapter 3's
// followContact moves each material point (a box's or hull's corner or face point) with its body
// and reads its depth along the normal, a point at a time; the cache does that for every carried
// record every frame (the touching 100-row pyramid's 15,000 records, 60,000 points), and the
// compiler makes four lanes of the same arithmetic four points at a time.

#include "world/world.h"

namespace stepwise {

/// Chapter 3's followContact for a pair of shapes that are not round (their points are material
/// points): each point's world positions from its anchors and its depth along the normal, with
/// the same operations in the same order, so the same bits. A pair with a round shape goes to
/// followContact itself.
void followCorners(const Body& bodyA, const Body& bodyB, Contact& contact);

}  // namespace stepwise
