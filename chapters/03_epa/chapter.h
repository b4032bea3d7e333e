#pragma once
// Chapter 3's pipeline: chapter 2's, with its yes/no stage `narrowphase:gjk` replaced by a
// stage that also measures each overlap and fills World::contacts (one point per pair).
// The stage is called `narrowphase:closed_form` when every pair of the scene has a closed form
// (no GJK or EPA will run), else `narrowphase:gjk_epa`.

#include "03_epa/narrowphase.h"
#include "world/pipeline.h"

namespace stepwise {

/// Fills world.pairs and world.contacts with every overlapping pair (bodyA < bodyB, static
/// pairs skipped), one contact point each. Returns the number of shape queries made.
int findContacts(World& world, const CollideOptions& options = CollideOptions{});

/// True when every pair of bodies that could collide has a closed-form routine.
bool allPairsClosedForm(const World& world);

/// The deepest overlap between any two bodies (static pairs skipped), m; 0 when none overlap.
/// The penetration probe of run reports (max_penetration).
Real measureDeepestPenetration(const World& world);

/// Chapter 2's pipeline with its narrowphase stage replaced by chapter 3's.
Pipeline makeChapter03Pipeline(const World& world);

}  // namespace stepwise
