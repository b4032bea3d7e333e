#pragma once
// Chapter 2's pipeline: chapter 1's integration plus `narrowphase:gjk`, which asks GJK about
// every pair of bodies (no broadphase yet) and lists the pairs that intersect in World::pairs.

#include "02_gjk/gjk.h"
#include "world/pipeline.h"

namespace stepwise {

/// A body as GJK sees it (shape, pose, support mode).
ConvexProxy makeProxy(const Body& body, SupportMode mode = SupportMode::Extents);

/// Fills world.pairs with every intersecting pair (bodyA < bodyB), testing all pairs except
/// static-static ones. Returns the number of GJK queries made.
int findIntersectingPairs(World& world, SupportMode mode = SupportMode::Extents);

/// Chapter 1's pipeline + the stage "narrowphase:gjk" after integration.
Pipeline makeChapter02Pipeline(const World& world);

}  // namespace stepwise
