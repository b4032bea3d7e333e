#pragma once
// Chapter 7's pipeline: chapter 6's, plus continuous collision when the scene needs it
// (fast_bodies.h): a recorder at the start of every substep keeps where each body was, and the
// time-of-impact loop at its end (toi_loop.h) stops the fast bodies at their first impact
// along the way from there. Without a fast body the pipeline is chapter 6's, stage for stage.

#include "06_manifolds/chapter.h"
#include "07_ccd/fast_bodies.h"
#include "07_ccd/toi_loop.h"
#include "world/pipeline.h"

namespace stepwise {

/// Chapter 6's pipeline plus the CCD stages when planContinuousCollision says so; the plan's
/// reason is the pipeline's "ccd" plan note either way (the run report prints it).
Pipeline makeChapter07Pipeline(const World& world);
/// The same on a chapter 6 pipeline made with other options.
Pipeline makeChapter07Pipeline(const World& world, Pipeline chapter6);

/// Adds the two CCD stages to any pipeline: "ccd:sweep_start" first, "ccd:toi" last.
void addContinuousCollision(Pipeline& pipeline);

}  // namespace stepwise
