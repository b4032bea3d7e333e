#pragma once
// `stepwise bench integrators`: error at a fixed time against the closed form, and run time,
// for each integrator over a range of step sizes (a work-precision diagram).

#include "app/registry.h"

namespace stepwise {

/// The registry entry: name, description and the files the bench writes.
BenchEntry integratorsBench();

/// Runs the bench; writes the table (--csv), the work-precision plot (--plot) and the error
/// against step size next to it (<plot>-dt.svg). Returns 0, or 2 when an output cannot be written.
int runIntegratorsBench(const BenchOptions& options);

}  // namespace stepwise
