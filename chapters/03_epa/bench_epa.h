#pragma once
// `stepwise bench epa`: depth error against run time as EPA's tolerance and iteration cap vary
// (a work-precision diagram), box support by extents against by vertices, ns per query.

#include "app/registry.h"

namespace stepwise {

/// The registry entry: name, description, what it measures and the files it writes
/// (options.csvPath and options.plotPath, when given).
BenchEntry epaBench();

}  // namespace stepwise
