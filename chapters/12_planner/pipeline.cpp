#include "12_planner/chapter.h"

#include "04_pgs/chapter.h"

#include <memory>
#include <vector>

namespace stepwise {

namespace {

/// The plan stages' working memory: the frame's contacts and the stack search. Rebuilt every frame
/// from the World; the shock sweep reads the depths the search left.
struct PlanScratch {
    std::vector<int> contacts;
    StackSearch search;
};

// [ch12-plan-stage]
/// The wide solve's plan stage: the substeps and the shock sweep for this frame, from the contacts
/// the solve will take.
void planWideSolve(Stage& plan, const std::shared_ptr<PlanScratch>& scratch, bool shockAllowed) {
    plan.name = stageName(stage_group::kPlan, "auto");
    plan.run = [scratch, shockAllowed](World& world, Real dt) {
        if (!fastSolvePlans(world, dt)) return;
        collectSolvableContacts(world, scratch->contacts);
        IterationPlan& frame = world.step.iterationPlan;
        frame.previousIterations = frame.iterations;
        if (world.joints.empty())
            plannedIterations(world, dt, scratch->contacts, frame, scratch->search, shockAllowed);
        else
            plannedLinkedIterations(world, dt, scratch->contacts, frame, scratch->search);
        tallyPlanReason(frame);
    };
}
// [ch12-plan-stage]

/// Chapter 10's solve (chapter 8's rows), which takes Settings::solverIterations as its substeps:
/// a plan stage before it, and the solve run with the planned count.
void planJointSolve(Pipeline& pipeline, const std::shared_ptr<PlanScratch>& scratch) {
    Stage* solve = pipeline.find(stage_group::kSolve);
    if (!solve) return;
    solve->run = [run = solve->run](World& world, Real dt) {
        const int scene = world.settings.solverIterations;
        world.settings.solverIterations = world.step.iterationPlan.iterations;
        run(world, dt);
        world.settings.solverIterations = scene;
    };
    Stage plan;
    plan.name = stageName(stage_group::kPlan, "joint_substeps");
    plan.run = [scratch](World& world, Real dt) {
        plannedJointSolveIterations(world, dt, scratch->contacts, world.step.iterationPlan, scratch->search);
        tallyPlanReason(world.step.iterationPlan);
    };
    pipeline.insertBefore(stage_group::kSolve, std::move(plan));
    pipeline.setPlanNote(stage_group::kPlan, "chapter 8's rows: substeps by what hangs and rests on the world alone");
}

}  // namespace

Pipeline makeChapter12Pipeline(const World& world) { return makeChapter12Pipeline(world, SpeedOptions{}); }

// [ch12-pipeline]
Pipeline makeChapter12Pipeline(const World& world, const SpeedOptions& options) {
    SkipWorkOptions skip;
    skip.contactCache = options.contactCache;
    skip.sleeping = options.sleeping;
    skip.enlargedBounds = options.enlargedBounds;
    skip.boxBoxQuery = options.boxBoxQuery;
    skip.pairManifold = options.pairManifold;
    WideSolveOptions wide;
    wide.fastSolve = options.fastSolve;
    wide.solverPath = options.solverPath;
    wide.profile = options.profile;
    auto scratch = std::make_shared<PlanScratch>();
    if (options.shockPropagation)
        wide.extension = std::make_shared<ShockSweep>(std::shared_ptr<const StackSearch>(scratch, &scratch->search));
    Pipeline pipeline = makeChapter11Pipeline(world, skip, wide);
    if (Stage* plan = pipeline.find(stage_group::kPlan)) {  // the wide solve runs
        planWideSolve(*plan, scratch, options.shockPropagation);
        pipeline.setPlanNote(stage_group::kPlan, "auto: substeps by mass ratio and stack depth, shock sweep "
                                                 "on deep stacks of like masses");
    } else if (options.fastSolve && !world.joints.empty() && chooseStepOrder(world) == StepOrder::SplitIntegration) {
        planJointSolve(pipeline, scratch);
    }
    return pipeline;
}
// [ch12-pipeline]

}  // namespace stepwise
