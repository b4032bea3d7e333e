#pragma once
// Chapter 9's `stepwise bench` suite.

#include "app/registry.h"

namespace stepwise {

/// `stepwise bench debug`: what the 120-frame history costs per frame (time beside the step's,
/// memory) as scenes grow, what a rewind and a resume cost, and the GJK ray cast's error against
/// the closed forms as its iteration cap grows, with the time per cast.
BenchEntry debugBench();

}  // namespace stepwise
