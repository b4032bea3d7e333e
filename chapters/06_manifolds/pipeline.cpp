#include "06_manifolds/chapter.h"

#include <algorithm>

namespace stepwise {

ContactSearch chooseContactSearch(const World& /*world*/) { return ContactSearch::OncePerFrame; }

Pipeline makeChapter06Pipeline(const World& world) { return makeChapter06Pipeline(world, ManifoldOptions{}); }

Pipeline makeChapter06Pipeline(const World& world, const ManifoldOptions& options) {
    return makeChapter06Pipeline(world, options, chooseStepOrder(world), chooseContactSearch(world));
}

void runStabilisedSolve(World& world, Real dt, bool splitOrder, ExtraConstraints* extra) {
    if (splitOrder && isSubstepped(world.settings.stabilisation)) {
        substeppedSolve(world, dt, extra);
        return;
    }
    if (world.step.substep > 0 && world.step.contactsFoundAtSubstep < world.step.substep) followContactAnchors(world);
    solveStabilised(world, dt, std::max(0, world.settings.solverIterations), extra);
    world.step.velocitiesBeforeForces.clear();
}

// [ch06-pipeline]
Pipeline makeChapter06Pipeline(const World& world, const ManifoldOptions& options, StepOrder order,
                               ContactSearch search) {
    Pipeline pipeline = makeChapter05Pipeline(world, order, search);
    const bool split = order == StepOrder::SplitIntegration;

    // The narrowphase keeps its place and frequency; it now builds and keeps manifolds.
    if (Stage* narrowphase = pipeline.find(stage_group::kNarrowphase)) {
        const bool planned = options.multiPoint && world.settings.manifoldContacts;
        narrowphase->name = stageName(stage_group::kNarrowphase, planned ? "manifold" : "one_point");
        narrowphase->run = [search, options, split](World& stepWorld, Real) {
            // Relax and soft_step move the bodies through the whole frame in their own substeps
            // on the contacts found here, so the speculative margin must cover the frame, not only
            // the substeps after the first: at substeps = 1 those are none, and a ball falling at
            // 6 m/s would go 10 cm into a box before its contact exists.
            const bool wholeFrame = split && isSubstepped(stepWorld.settings.stabilisation);
            const int ahead = wholeFrame ? std::max(1, stepWorld.settings.substeps) : substepsAhead(stepWorld, search);
            ManifoldOptions now = options;  // Settings::manifoldContacts is read every step (the demo's toggle)
            now.multiPoint = options.multiPoint && stepWorld.settings.manifoldContacts;
            updateManifolds(stepWorld, static_cast<Real>(ahead), now);
        };
    }

    // The solve reads Settings::stabilisation every step, so the demo's toggle acts at once. The
    // substepped ones (relax, soft_step) integrate the bodies themselves, so with them the
    // integration stages stand aside; they need the split step order (RK4 and Verlet bodies get
    // a single warm-started solve instead).
    if (Stage* solve = pipeline.find(stage_group::kSolve)) {
        solve->name = stabilisedSolveStageName(world.settings.stabilisation);
        solve->run = [split](World& stepWorld, Real dt) { runStabilisedSolve(stepWorld, dt, split, nullptr); };
    }
    if (split) {
        for (const char* variant : {"velocities", "positions"}) {
            Stage* stage = pipeline.find(stageName(stage_group::kIntegrate, variant));
            if (!stage) continue;
            stage->run = [integrate = stage->run](World& stepWorld, Real dt) {
                if (!isSubstepped(stepWorld.settings.stabilisation)) integrate(stepWorld, dt);
            };
        }
    }

    // What a pair remembers is its manifold's life cycle now, not chapter 4's load test.
    pipeline.remove(stageName(stage_group::kContacts, "drop_unloaded"));
    return pipeline;
}
// [ch06-pipeline]

}  // namespace stepwise
