#pragma once
// Chapter 1's pipeline: a single stage, `integrate:<method>`, that advances every moving body
// with its integrator. Later chapters start from this pipeline and add their stages around it.

#include "world/pipeline.h"

namespace stepwise {

/// The chapter 1 pipeline for a world: one stage named "integrate:" plus the method the
/// dynamic bodies use ("integrate:semi_implicit_euler", "integrate:rk4", "integrate:verlet"),
/// or "integrate:mixed" when bodies override the world's integrator with different methods.
Pipeline makeChapter01Pipeline(const World& world);

}  // namespace stepwise
