#pragma once
// Chapter 8's `stepwise bench` suite.

#include "app/registry.h"

namespace stepwise {

/// `stepwise bench joints`: a hanging chain's stretch, a swinging chain's, a heavy-ended chain's
/// and a ragdoll pile's joint error against the step's run time, as the solver iterations, the
/// substeps and the joint order vary.
BenchEntry jointsBench();

}  // namespace stepwise
