#include "10_skip_work/enlarged_bounds.h"

#include "05_sap/chapter.h"
#include "05_sap/sweep_and_prune.h"

namespace stepwise {

namespace {

bool inside(const Aabb& box, const Aabb& enlarged) {
    return (enlarged.min.array() <= box.min.array()).all() && (box.max.array() <= enlarged.max.array()).all();
}

/// Whether the pairs of the last sweep still cover every pair this step's boxes can make.
bool enlargedPairsHold(const BroadphaseState& state) {
    if (state.enlargedBounds.size() != state.bounds.size() || state.enlargedDynamic != state.dynamic) return false;
    for (std::size_t i = 0; i < state.bounds.size(); ++i)
        if (!inside(state.bounds[i], state.enlargedBounds[i])) return false;  // also false for NaN
    return true;
}

}  // namespace

// [ch10-enlarged-bounds]
void sweepAndPruneEnlarged(World& world) {
    const Real margin = world.settings.boundsMargin;
    BroadphaseState& state = world.broadphase;
    computeBroadphaseBounds(world, state.bounds, state.dynamic);
    state.sweepSkipped = enlargedPairsHold(state);
    if (!state.sweepSkipped) {
        // Sweep the grown boxes (chapter 5's sweep, axis choice and incremental sort included), then
        // put this step's own boxes back for whoever reads them (the demo, the report).
        state.enlargedBounds = state.bounds;
        for (Aabb& box : state.bounds) {
            box.min.array() -= margin;
            box.max.array() += margin;
        }
        sweepBounds(world);
        state.enlargedPairs = world.candidatePairs;
        state.enlargedDynamic = state.dynamic;
        state.bounds.swap(state.enlargedBounds);
    }
    world.candidatePairs.clear();
    for (const BodyPair& pair : state.enlargedPairs)
        if (state.bounds[static_cast<std::size_t>(pair.bodyA)].overlaps(state.bounds[static_cast<std::size_t>(pair.bodyB)]))
            world.candidatePairs.push_back(pair);
    state.used = BroadphaseMode::Sap;
    noteBroadphaseReason(world);
}
// [ch10-enlarged-bounds]

}  // namespace stepwise
