#pragma once
// `stepwise bench epa`: depth error against run time as EPA's tolerance and iteration cap vary
// (a work-precision diagram), box support by extents against by vertices, ns per query.

#include "app/registry.h"

namespace stepwise {

/// The registry entry: name, description and the files the bench writes.
BenchEntry epaBench();

/// Runs the bench; writes options.csvPath and options.plotPath when given. Returns 0, or 2 when
/// an output file cannot be written.
int runEpaBench(const BenchOptions& options);

}  // namespace stepwise
