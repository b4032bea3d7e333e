#include "10_speed/chapter.h"

#include "04_pgs/chapter.h"
#include "10_speed/box_box.h"
#include "10_speed/iteration_plan.h"

#include <algorithm>
#include <memory>

namespace stepwise {

Pipeline makeChapter10Pipeline(const World& world) { return makeChapter10Pipeline(world, SpeedOptions{}); }

// [ch10-pipeline]
Pipeline makeChapter10Pipeline(const World& world, const SpeedOptions& options) {
    // Chapter 8's solve, for the scenes with joints the fast solve does not take: its relax pass
    // keeps the biased pass's joint rows (half the joint work of a substep).
    JointOptions joints;
    joints.relaxOnBiasedRows = true;
    Pipeline pipeline = makeChapter08Pipeline(world, joints);
    if (Stage* broadphase = pipeline.find(stage_group::kBroadphase); broadphase && options.enlargedBounds) {
        // Same pairs as chapter 5's sweep, which runs only when a body has left its grown box.
        broadphase->run = [sweep = broadphase->run](World& stepWorld, Real dt) {
            if (chooseBroadphase(stepWorld) == BroadphaseMode::Sap)
                sweepAndPruneEnlarged(stepWorld);
            else
                sweep(stepWorld, dt);
        };
    }
    std::string why;
    // Sleepers are skipped by the fast solve only: chapter 8's would still integrate them.
    const char* noSleep = "off: sleepers are skipped by the fast solve only, and chapter 8's solves this scene";
    if (!options.fastSolve) {
        pipeline.setPlanNote(stage_group::kSolve, "chapter 8's solve: the fast solve is switched off");
        pipeline.setPlanNote(stage_group::kSleep, noSleep);
    } else if (!fastSolveApplies(world, &why)) {
        pipeline.setPlanNote(stage_group::kSolve, "chapter 8's solve: " + why);
        pipeline.setPlanNote(stage_group::kSleep, noSleep);
        Stage* solve = pipeline.find(stage_group::kSolve);
        if (solve && !world.joints.empty() && chooseStepOrder(world) == StepOrder::SplitIntegration) {
            // Chapter 8's solve takes the scene's count as its substeps; the planner hands it
            // fewer for a frame where every body hangs or rests on the world alone.
            struct JointPlanScratch {
                std::vector<int> contacts;
                StackSearch search;
            };
            solve->run = [run = solve->run, scratch = std::make_shared<JointPlanScratch>()](World& stepWorld, Real dt) {
                const int scene = stepWorld.settings.solverIterations;
                stepWorld.settings.solverIterations = plannedJointSolveIterations(
                    stepWorld, dt, scratch->contacts, stepWorld.step.iterationPlan, scratch->search);
                run(stepWorld, dt);
                stepWorld.settings.solverIterations = scene;
            };
        }
    } else if (Stage* solve = pipeline.find(stage_group::kSolve)) {
        solve->name = stageName(stage_group::kSolve, std::string(toString(options.solverPath)) + "_" +
                                                         toString(world.settings.stabilisation));
        // Scratch buffers only: rebuilt from the World every frame, they carry nothing between
        // frames (a copied World steps the same), and spare the allocation per step.
        auto scratch = std::make_shared<ContactSolverScratch>();
        scratch->timePhases = options.profile != nullptr;
        scratch->shockAllowed = options.shockPropagation;
        solve->run = [scratch, path = options.solverPath, profile = options.profile](World& stepWorld, Real dt) {
            solveFast(stepWorld, dt, path, *scratch);
            if (profile) addPhaseTimes(*profile, scratch->stats);
        };
        pipeline.setPlanNote(stage_group::kSolve, std::string(toString(options.solverPath)) +
                                                      ": no joints, springs, dampings or kinematic bodies");
        if (Stage* narrowphase = pipeline.find(stage_group::kNarrowphase); narrowphase && options.contactCache.enabled) {
            // The fast solve is a substepped one (relax or soft step), which moves the bodies
            // through the whole frame on the contacts found here: chapter 6's look-ahead for it.
            auto cache = std::make_shared<ContactCacheScratch>();
            narrowphase->name = stageName(stage_group::kNarrowphase, "cached_manifold");
            narrowphase->run = [cache, rule = options.contactCache, boxBox = options.boxBoxQuery](World& stepWorld, Real) {
                ManifoldOptions manifold;
                manifold.multiPoint = stepWorld.settings.manifoldContacts;
                if (boxBox) manifold.query = fastContactQuery;
                const Real lookAhead = static_cast<Real>(std::max(1, stepWorld.settings.substeps));
                updateManifoldsCached(stepWorld, lookAhead, manifold, rule, *cache);
            };
        }
        if (options.sleeping) {
            addSleepStages(pipeline, world);
            // A world asleep throughout has the pairs and contacts it had: nothing moved.
            for (const char* group : {stage_group::kBroadphase, stage_group::kNarrowphase}) {
                Stage* stage = pipeline.find(group);
                if (!stage) continue;
                stage->run = [run = stage->run](World& stepWorld, Real dt) {
                    if (!everyBodyAsleep(stepWorld)) run(stepWorld, dt);
                };
            }
        }
        else
            pipeline.setPlanNote(stage_group::kSleep, "off: switched off for comparison");
    }
    return pipeline;
}
// [ch10-pipeline]

}  // namespace stepwise
