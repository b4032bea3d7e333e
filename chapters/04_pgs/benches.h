#pragma once
// Chapter 4's `stepwise bench` suites.

#include "app/registry.h"

namespace stepwise {

/// `stepwise bench solver`: error against solve time, iterations 1..50, Gauss-Seidel and Jacobi.
BenchEntry solverBench();

/// `stepwise bench resting`: penetration of a resting ball and box over time, for both step
/// orders (integrate first, and integration split around the solve), and the box's one-point
/// jitter.
BenchEntry restingBench();

}  // namespace stepwise
