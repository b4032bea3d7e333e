#pragma once
// Chapter 4's `stepwise bench` suites.

#include "app/registry.h"

namespace stepwise {

/// Checks up front that the CSV and plot paths can be written (before minutes of measuring);
/// prints "error: bench <suite>: cannot write '<path>'" and returns false when one cannot.
bool benchOutputsWritable(const BenchOptions& options, const std::string& suite);

/// `stepwise bench solver`: error against solve time, iterations 1..50, Gauss-Seidel and Jacobi.
int runSolverBench(const BenchOptions& options);

/// `stepwise bench resting`: penetration of a resting ball and box over time, for both step
/// orders (the seed's integrate-first and the split around the solve), and the box's one-point
/// jitter.
int runRestingBench(const BenchOptions& options);

}  // namespace stepwise
