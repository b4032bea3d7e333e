#pragma once
// Chapter 6's `stepwise bench` suite.

#include "app/registry.h"

namespace stepwise {

/// `stepwise bench stacking`: horizontal drift, sag and deepest overlap of pyramids against the
/// step's run time, as the iterations go from 1 to 50 and the substeps from 1 to 8, for each
/// stabilisation, warm starting on and off, manifolds against one point per pair; pyramids of
/// 10, 20 and 40 rows; and the chapter's targets measured on their scenes.
BenchEntry stackingBench();

}  // namespace stepwise
