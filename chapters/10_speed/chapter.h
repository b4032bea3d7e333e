#pragma once
// Chapter 10's pipeline: chapter 9's step (chapter 8's stages), made fast where the scene allows
// it. The solve runs on the data of solver_data.h, wide (SIMD, coloured) or scalar; the scene
// pipeline below decides per scene and the run report says why.

#include "09_debug/chapter.h"
#include "10_speed/contact_cache.h"
#include "10_speed/contact_solver.h"
#include "10_speed/enlarged_bounds.h"
#include "10_speed/sleep.h"
#include "world/pipeline.h"

#include <memory>

namespace stepwise {

/// What chapter 10 adds, each switchable for the bench's "one optimisation off at a time".
struct SpeedOptions {
    bool fastSolve = true;             // false: chapter 8's solve (the reference)
    SolverPath solverPath = SolverPath::Wide;
    ContactCacheRule contactCache;     // enabled = false: every pair is queried every frame
    bool sleeping = true;              // with Settings::sleeping; false: never (the bench's A/B)
    bool enlargedBounds = true;        // sweep only when a body leaves its grown box; false: every step
    bool boxBoxQuery = true;           // two boxes by separating axes (box_box.h); false: GJK and EPA
    bool shockPropagation = true;      // the planner's shock sweep (shock_propagation.h); false: never
    std::shared_ptr<FastSolveStats> profile;  // when set, every fast solve adds its phase times here
};

Pipeline makeChapter10Pipeline(const World& world);
Pipeline makeChapter10Pipeline(const World& world, const SpeedOptions& options);

}  // namespace stepwise
