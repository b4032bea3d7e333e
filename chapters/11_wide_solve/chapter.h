#pragma once
// Chapter 11's pipeline: chapter 10's, with the contacts solved wide. The contacts are built into
// blocks once per frame (solver_data.h), coloured so that no two contacts of a colour share a
// moving body (colouring.h), and solved kWideLanes at a time by one kernel written for any lane
// count (lanes.h, contact_kernels.h): the manifold's normal rows as one block, friction at its
// centre, rolling resistance. A plan stage before the solve sets the frame's substeps (here the
// scene's count; chapter 12 plans them).

#include "10_skip_work/chapter.h"
#include "11_wide_solve/contact_solver.h"

#include <memory>

namespace stepwise {

/// What chapter 11 adds, switchable for the A/B of the demo and the benches.
struct WideSolveOptions {
    bool fastSolve = true;  // false: chapter 10's solve (chapter 8's rows) for every scene
    SolverPath solverPath = defaultSolverPath();  // Wide unless STEPWISE_SOLVER_PATH=scalar
    std::shared_ptr<FastSolveStats> profile;     // when set, every solve adds its phase times here
    std::shared_ptr<SolveExtension> extension;   // a later chapter's pass (chapter 12's shock sweep)
};

Pipeline makeChapter11Pipeline(const World& world);
Pipeline makeChapter11Pipeline(const World& world, const SkipWorkOptions& skip, const WideSolveOptions& wide);

}  // namespace stepwise
