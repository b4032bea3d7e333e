#pragma once
// `stepwise bench gjk` (see bench_gjk.cpp).

#include "app/registry.h"

namespace stepwise {

/// The registry entry: name, description and the files the bench writes.
BenchEntry gjkBench();

/// Runs the GJK bench; returns the process exit code.
int runGjkBench(const BenchOptions& options);

}  // namespace stepwise
