#pragma once
// Chapter 5's pipeline: chapter 4's, with a broadphase stage before the narrowphase. The stage
// (`broadphase:sap` or `broadphase:brute`) fills World::candidatePairs in canonical order, and
// the narrowphase tests only those pairs instead of all n^2.

#include "04_pgs/chapter.h"
#include "05_sap/sweep_and_prune.h"
#include "world/pipeline.h"

#include <string>

namespace stepwise {

// [ch05-crossover]
/// `auto` runs sweep and prune from this many bodies on, and tests all pairs below it. The body
/// count where sweep and prune's broadphase becomes faster than brute force's, measured by
/// `stepwise bench broadphase` (its "crossover" line) on sparse and dense stress scenes: below
/// it, sorting and sweeping cost more than the few pairs they save.
constexpr int kAutoSapMinBodies = 128;
// [ch05-crossover]

/// How the sweep sorts the interval ends: from last step's order by insertion sort when the axis
/// is the same (falling back to a full sort when too much moved), or from scratch every step.
enum class SortMode { Incremental, Full };

/// Settings::broadphase with `auto` resolved by the body count: Sap or Brute.
BroadphaseMode chooseBroadphase(const World& world);

/// Why chooseBroadphase chose what it did, in words (the run report's "broadphase.reason").
std::string broadphaseReason(const World& world);

/// Sets world.broadphase.reason, when the setting or the body count changed since it was set.
void noteBroadphaseReason(World& world);

/// Sweep and prune: fills world.broadphase (bounds, axis, sorted ends, statistics) and
/// world.candidatePairs (canonical order).
void sweepAndPrune(World& world, SortMode sortMode = SortMode::Incremental);

/// The sweep alone, on the boxes already in world.broadphase.bounds and .dynamic (chapter 10 sweeps
/// boxes it has grown).
void sweepBounds(World& world, SortMode sortMode = SortMode::Incremental);

/// All pairs, against the same bounds: the same candidate pairs, at O(n^2).
void bruteForceBroadphase(World& world);

/// The stage: the broadphase chooseBroadphase picks, recorded in world.broadphase.
void findCandidatePairs(World& world);

/// Chapter 4's pipeline with `broadphase:<choice>` inserted before the narrowphase, at the
/// narrowphase's frequency, and the narrowphase reading World::candidatePairs.
Pipeline makeChapter05Pipeline(const World& world);
Pipeline makeChapter05Pipeline(const World& world, StepOrder order, ContactSearch search = ContactSearch::EverySubstep);

}  // namespace stepwise
