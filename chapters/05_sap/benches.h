#pragma once
// Chapter 5's `stepwise bench` suite.

#include "app/registry.h"

namespace stepwise {

/// `stepwise bench broadphase`: broadphase and whole-step time against body count, sparse and
/// dense, brute force against sweep and prune (full sort and incremental); the crossover count
/// `auto` uses; incremental against full sort on a settled scene; the chapter's targets.
BenchEntry broadphaseBench();

}  // namespace stepwise
