#include "06_manifolds/chapter.h"

#include "01_integrators/integrate.h"

namespace stepwise {

ContactSearch chooseContactSearch(const World& /*world*/) { return ContactSearch::OncePerFrame; }

Pipeline makeChapter06Pipeline(const World& world) { return makeChapter06Pipeline(world, ManifoldOptions{}); }

Pipeline makeChapter06Pipeline(const World& world, const ManifoldOptions& options) {
    return makeChapter06Pipeline(world, options, chooseStepOrder(world), chooseContactSearch(world));
}

// [ch06-pipeline]
Pipeline makeChapter06Pipeline(const World& world, const ManifoldOptions& options, StepOrder order,
                               ContactSearch search) {
    Pipeline pipeline = makeChapter05Pipeline(world, order, search);

    // The narrowphase keeps its place and frequency; it now builds and keeps manifolds.
    if (Stage* narrowphase = pipeline.find(stage_group::kNarrowphase)) {
        narrowphase->name = stageName(stage_group::kNarrowphase, options.multiPoint ? "manifold" : "one_point");
        narrowphase->run = [search, options](World& stepWorld, Real) {
            updateManifolds(stepWorld, static_cast<Real>(substepsAhead(stepWorld, search)), options);
        };
    }

    // The solve: warm started, stabilised as the settings say (read every step, so the demo's
    // toggles act at once). When the contacts were found earlier in the frame, their points first
    // move with their bodies. Without a relax pass, restitution's approach speeds are used here
    // once; with one, the relax pass needs them too and clears them.
    if (Stage* solve = pipeline.find(stage_group::kSolve)) {
        solve->name = stabilisedSolveStageName(world.settings.stabilisation);
        solve->run = [](World& stepWorld, Real dt) {
            if (stepWorld.step.substep > 0 && stepWorld.step.contactsFoundAtSubstep < stepWorld.step.substep)
                followContactAnchors(stepWorld);
            solveStabilised(stepWorld, dt);
            if (!hasRelaxPass(stepWorld.settings.stabilisation)) stepWorld.step.velocitiesBeforeForces.clear();
        };
    }

    // What a pair remembers is its manifold's life cycle now, not chapter 4's load test.
    pipeline.remove(stageName(stage_group::kContacts, "drop_unloaded"));

    // The relax pass runs after the positions moved, so it needs the split step.
    if (order == StepOrder::SplitIntegration) {
        Stage relax;
        relax.name = stageName(stage_group::kSolve, "relax");
        relax.run = [](World& stepWorld, Real dt) {
            if (hasRelaxPass(stepWorld.settings.stabilisation)) relaxContacts(stepWorld, dt);
            stepWorld.step.velocitiesBeforeForces.clear();
        };
        pipeline.add(std::move(relax));
    }
    return pipeline;
}
// [ch06-pipeline]

}  // namespace stepwise
