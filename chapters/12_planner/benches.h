#pragma once
// Chapter 10's `stepwise bench` suite.

#include "app/registry.h"

namespace stepwise {

/// `stepwise bench speed`: ms per step and per stage on the big scenes (a 100-row pyramid, ten
/// 20-row pyramids, a 2,000-body mixed pile), with each optimisation switched off in turn, Bullet
/// beside it when the program has the peer; the pile settled with and without sleeping; ms per
/// step against body count for growing pyramids.
BenchEntry speedBench();

}  // namespace stepwise
