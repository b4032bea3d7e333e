// The broadphase stage of chapter 5 and the pipeline around it.
#include "05_sap/chapter.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

BroadphaseMode chooseBroadphase(const World& world) {
    if (world.settings.broadphase != BroadphaseMode::Auto) return world.settings.broadphase;
    return static_cast<int>(world.bodies.size()) >= kAutoSapMinBodies ? BroadphaseMode::Sap : BroadphaseMode::Brute;
}

std::string broadphaseReason(const World& world) {
    if (world.settings.broadphase != BroadphaseMode::Auto)
        return std::string("settings.broadphase is \"") + toString(world.settings.broadphase) + "\"";
    const std::string bodies = std::to_string(world.bodies.size()) + " bodies";
    const std::string crossover = std::to_string(kAutoSapMinBodies);
    return chooseBroadphase(world) == BroadphaseMode::Sap
               ? "auto: " + bodies + ", at least the " + crossover + " from which sweep and prune is faster"
               : "auto: " + bodies + ", fewer than the " + crossover + " from which sweep and prune is faster";
}

void noteBroadphaseReason(World& world) {
    BroadphaseState& state = world.broadphase;
    if (!state.reason.empty() && state.reasonSetting == world.settings.broadphase &&
        state.reasonBodyCount == world.bodies.size())
        return;
    state.reason = broadphaseReason(world);
    state.reasonSetting = world.settings.broadphase;
    state.reasonBodyCount = world.bodies.size();
}

// [ch05-sweep-and-prune]
void sweepAndPrune(World& world, SortMode sortMode) {
    computeBroadphaseBounds(world, world.broadphase.bounds, world.broadphase.dynamic);
    sweepBounds(world, sortMode);
}

void sweepBounds(World& world, SortMode sortMode) {
    BroadphaseState& state = world.broadphase;
    state.centreVariance = centreVariance(state.bounds);
    const int axis = chooseSweepAxis(state.centreVariance, state.axis);

    // Temporal coherence: on the same axis, last step's order is nearly right.
    const bool sameList = axis == state.axis && state.endpoints.size() == state.bounds.size();
    state.fullSort = !(sameList && sortMode == SortMode::Incremental);
    state.sortMoves = 0;
    if (!state.fullSort) {
        refreshEndpointValues(state.bounds, axis, state.endpoints);
        // Past n log2 n moves a full sort is cheaper: it finishes the job.
        const double n = static_cast<double>(state.endpoints.size());
        const long budget = static_cast<long>(n * std::max(1.0, math::log2(std::max(n, 2.0))));
        state.sortMoves = insertionSortEndpoints(state.endpoints, budget);
        state.fullSort = state.sortMoves < 0;
    } else {
        makeEndpoints(state.bounds, axis, state.endpoints);
    }
    if (state.fullSort) fullSortEndpoints(state.endpoints);
    state.axis = axis;

    world.candidatePairs.clear();
    state.axisOverlaps =
        sweepEndpoints(state.endpoints, state.bounds, state.dynamic, sweepAxes(state.centreVariance, axis),
                       world.candidatePairs, state.buffers.columns);
    sortPairsCanonical(world.candidatePairs, static_cast<int>(world.bodies.size()), state.buffers);
    state.used = BroadphaseMode::Sap;
}
// [ch05-sweep-and-prune]

void bruteForceBroadphase(World& world) {
    BroadphaseState& state = world.broadphase;
    computeBroadphaseBounds(world, state.bounds, state.dynamic);
    world.candidatePairs.clear();
    bruteForcePairs(state.bounds, state.dynamic, world.candidatePairs);
    state.axisOverlaps = 0;
    state.sortMoves = 0;
    state.fullSort = false;
    state.used = BroadphaseMode::Brute;
}

void findCandidatePairs(World& world) {
    if (chooseBroadphase(world) == BroadphaseMode::Sap)
        sweepAndPrune(world);
    else
        bruteForceBroadphase(world);
    noteBroadphaseReason(world);
}

Pipeline makeChapter05Pipeline(const World& world) { return makeChapter05Pipeline(world, chooseStepOrder(world)); }

// [ch05-pipeline]
Pipeline makeChapter05Pipeline(const World& world, StepOrder order, ContactSearch search) {
    Pipeline pipeline = makeChapter04Pipeline(world, order, search);
    Stage* narrowphase = pipeline.find(stage_group::kNarrowphase);
    if (!narrowphase) return pipeline;
    // The narrowphase keeps its name and frequency; it now tests the broadphase's pairs only.
    narrowphase->run = [search](World& stepWorld, Real) {
        updateContacts(stepWorld, stepWorld.candidatePairs, substepsAhead(stepWorld, search));
    };
    Stage broadphase;
    // The stage reads Settings::broadphase every step (the demo's toggle acts at once); its name
    // says what the scene asked for when the pipeline was planned.
    broadphase.name = stageName(stage_group::kBroadphase, toString(chooseBroadphase(world)));
    broadphase.frequency = narrowphase->frequency;
    broadphase.run = [](World& stepWorld, Real) { findCandidatePairs(stepWorld); };
    pipeline.insertBefore(stage_group::kNarrowphase, std::move(broadphase));
    return pipeline;
}
// [ch05-pipeline]

}  // namespace stepwise
