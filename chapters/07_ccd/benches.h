#pragma once
// Chapter 7's `stepwise bench` suite.

#include "app/registry.h"

namespace stepwise {

/// `stepwise bench ccd`: the tunnel rate and the step's cost against the speed of small
/// spheres, boxes and hulls shot at a 5 cm wall, with CCD off, with CCD on, and with CCD off
/// but 2, 4, 8 and 16 substeps (what stopping the tunnels without CCD would cost).
BenchEntry ccdBench();

}  // namespace stepwise
