#pragma once
// `stepwise bench integrators`: error at a fixed time against the closed form, and run time,
// for each integrator over a range of step sizes (a work-precision diagram).

#include "app/registry.h"

namespace stepwise {

/// The registry entry: name, description, what it measures and the files it writes: the table
/// (--csv), the work-precision plot (--plot) and the error against step size next to it
/// (<plot>-dt.svg). runBench(integratorsBench(), options) runs it.
BenchEntry integratorsBench();

}  // namespace stepwise
