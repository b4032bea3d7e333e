#pragma once
// `stepwise bench integrators`: error at a fixed time against the closed form, and run time,
// for each integrator over a range of step sizes (a work-precision diagram).

#include "app/registry.h"

namespace stepwise {

/// Runs the bench; writes options.csvPath and options.plotPath (plus "<plot>-dt.svg", error
/// against step size) when given. Returns 0, or 2 when an output file cannot be written.
int runIntegratorsBench(const BenchOptions& options);

}  // namespace stepwise
