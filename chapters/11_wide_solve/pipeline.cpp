#include "11_wide_solve/chapter.h"

#include "04_pgs/chapter.h"

#include <memory>
#include <string>

namespace stepwise {

Pipeline makeChapter11Pipeline(const World& world) {
    return makeChapter11Pipeline(world, SkipWorkOptions{}, WideSolveOptions{});
}

// [ch11-pipeline]
Pipeline makeChapter11Pipeline(const World& world, const SkipWorkOptions& skip, const WideSolveOptions& wide) {
    Pipeline pipeline = makeChapter10Pipeline(world, skip);
    std::string why;
    if (!wide.fastSolve) {
        pipeline.setPlanNote(stage_group::kSolve, "chapter 10's solve: the wide solve is switched off");
        return pipeline;
    }
    if (!fastSolveApplies(world, &why)) {
        pipeline.setPlanNote(stage_group::kSolve, "chapter 10's solve (chapter 8's rows): " + why);
        return pipeline;
    }
    Stage* solve = pipeline.find(stage_group::kSolve);
    if (!solve) return pipeline;
    solve->name = stageName(stage_group::kSolve,
                            std::string(toString(wide.solverPath)) + "_" + toString(world.settings.stabilisation));
    // Scratch buffers only: rebuilt from the World every frame, they carry nothing between frames
    // (a copied World steps the same), and spare the allocation per step.
    auto scratch = std::make_shared<ContactSolverScratch>();
    scratch->timePhases = wide.profile != nullptr;
    scratch->extension = wide.extension;
    solve->run = [scratch, path = wide.solverPath, profile = wide.profile](World& stepWorld, Real dt) {
        solveFast(stepWorld, dt, path, *scratch);
        if (profile) addPhaseTimes(*profile, scratch->stats);
    };
    std::string rows = std::string(toString(wide.solverPath)) + ": contacts coloured, " +
                       (wide.solverPath == SolverPath::Wide ? std::to_string(kWideLanes) + " at a time" : std::string("one at a time"));
    if (!world.joints.empty())
        rows += "; " + std::to_string(world.joints.size()) + " joint(s) one at a time in the same substeps (chapter 8's rows)";
    if (!world.springs.empty() || !world.dampings.empty()) rows += "; springs and drag as forces every substep";
    pipeline.setPlanNote(stage_group::kSolve, rows);
    // The solve skips sleepers itself (they take slot 0, with everything that does not move).
    pipeline.remove(stageName(stage_group::kSleep, "hold"));
    pipeline.remove(stageName(stage_group::kSleep, "release"));
    Stage plan;
    plan.name = stageName(stage_group::kPlan, "scene_count");
    plan.run = [](World& stepWorld, Real dt) {
        if (fastSolvePlans(stepWorld, dt)) planSceneCount(stepWorld);
    };
    pipeline.insertBefore(stage_group::kSolve, std::move(plan));
    pipeline.setPlanNote(stage_group::kPlan, "the scene's count of substeps every frame");
    return pipeline;
}
// [ch11-pipeline]

}  // namespace stepwise
