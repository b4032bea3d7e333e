#pragma once
// Chapter 12's pipeline: chapter 11's, with the frame's substeps planned from what touches what
// (iteration_plan.h) in the plan stage before the solve, and deep stacks of slow bodies ended with
// a shock sweep (shock_sweep.h). The solve reads the plan from World::step.iterationPlan and never
// plans; the run report says what the planner saw and chose.

#include "11_wide_solve/chapter.h"
#include "12_planner/iteration_plan.h"
#include "12_planner/shock_sweep.h"

#include <memory>

namespace stepwise {

/// The fast step's switches, chapters 10 to 12, each on by default: the bench's "one optimisation
/// off at a time" and the demos' A/B.
struct SpeedOptions {
    bool fastSolve = true;             // false: chapter 10's solve (chapter 8's rows)
    SolverPath solverPath = defaultSolverPath();  // Wide unless STEPWISE_SOLVER_PATH=scalar
    ContactCacheRule contactCache;     // enabled = false: every pair is queried every frame
    bool sleeping = true;              // with Settings::sleeping; false: never (the bench's A/B)
    bool enlargedBounds = true;        // sweep only when a body leaves its grown box; false: every step
    bool boxBoxQuery = true;           // two boxes by separating axes (box_box.h); false: GJK and EPA
    bool shockPropagation = true;      // the planner's shock sweep; false: never
    std::shared_ptr<FastSolveStats> profile;  // when set, every fast solve adds its phase times here
    PairManifoldFunction pairManifold = nullptr;  // a later chapter's shapes (ManifoldOptions::pairManifold)
};

Pipeline makeChapter12Pipeline(const World& world);
Pipeline makeChapter12Pipeline(const World& world, const SpeedOptions& options);

}  // namespace stepwise
