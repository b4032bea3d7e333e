#pragma once
// `stepwise bench gjk` (see bench_gjk.cpp).

#include "app/registry.h"

namespace stepwise {

/// The registry entry: name, description, what it measures and the files it writes.
BenchEntry gjkBench();

}  // namespace stepwise
