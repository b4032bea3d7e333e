#pragma once
// Chapter 6's pipeline: chapter 5's broadphase, then manifolds of up to four points kept from
// step to step (manifold.h) as the narrowphase, then the solve with warm starting and the
// stabilisation Settings::stabilisation names (stabilisation.h), with its relax pass after the
// positions moved when it has one. Chapter 4's "drop unloaded points" upkeep is gone: what a
// pair remembers is now its manifold's life cycle (persistence within the speculative margin).

#include "05_sap/chapter.h"
#include "06_manifolds/manifold.h"
#include "06_manifolds/stabilisation.h"
#include "world/pipeline.h"

namespace stepwise {

/// How contacts are searched in chapter 6: once per frame. A manifold holds every touching corner,
/// and its points ride on their bodies (anchors) through the substeps.
ContactSearch chooseContactSearch(const World& world);

/// What the solve stage runs each step: the substepped solve of Settings::stabilisation when it
/// is one and the step order is split, else one solve of Settings::solverIterations iterations
/// (after moving the contact points with their bodies when the contacts were found in an
/// earlier substep). `extra`: a later chapter's constraints solved with the contacts, or null.
void runStabilisedSolve(World& world, Real dt, bool splitOrder, ExtraConstraints* extra);

/// The pipeline with the default manifold options (multi-point).
Pipeline makeChapter06Pipeline(const World& world);
Pipeline makeChapter06Pipeline(const World& world, const ManifoldOptions& options);
Pipeline makeChapter06Pipeline(const World& world, const ManifoldOptions& options, StepOrder order,
                               ContactSearch search);

}  // namespace stepwise
