#include "12_planner/shock_sweep.h"

#include "10_skip_work/sleep.h"
#include "12_planner/held_kernels.h"
#include "12_planner/held_wide.h"

#include <algorithm>

namespace stepwise {

// [ch12-shock-groups]
/// The shock sweep's groups (orderShockSweep, in the sweep's order, numbered from 1) of the
/// contacts whose two bodies were slow when the frame began (isSlow, the sleep test), and which of
/// each contact's bodies is the lower one, held still. Set before the blocks are filled: each lane
/// carries its group (setLaneGroup), and the blocks are prepared for the sweep as well
/// (prepare), so that the sweep needs no blocks of its own.
void ShockSweep::groupLanes(const World& world, ContactSolverScratch& scratch) {
    const SolverBodies& bodies = scratch.bodies;
    const std::vector<int>& depth = search_->depth;  // this frame's (the plan stage's supportDepth)
    const std::size_t moving = bodies.states.size();
    std::vector<int>& slotDepth = slotDepth_;
    slotDepth.assign(moving, 0);
    for (std::size_t slot = 1; slot < moving; ++slot) {
        const auto body = static_cast<std::size_t>(bodies.info[slot].bodyIndex);
        slotDepth[slot] = body < depth.size() ? depth[body] : 0;
    }
    const ShockOrder& order = order_;
    orderShockSweep(scratch.slotA, scratch.slotB, slotDepth, order_);
    std::vector<std::uint8_t>& slow = slowSlot_;
    slow.assign(moving, 0);
    for (std::size_t slot = 1; slot < moving; ++slot) slow[slot] = isSlow(world, bodies.info[slot].bodyIndex) ? 1 : 0;
    scratch.laneGroupOf.assign(scratch.contactOrder.size(), 0);
    scratch.laneHeldIsA.assign(scratch.contactOrder.size(), 0);
    scratch.laneGroups = static_cast<int>(order.groupStart.size()) - 1;
    for (std::size_t group = 0; group + 1 < order.groupStart.size(); ++group) {
        for (int k = order.groupStart[group]; k < order.groupStart[group + 1]; ++k) {
            const auto i = static_cast<std::size_t>(order.entries[static_cast<std::size_t>(k)]);
            if (!slow[static_cast<std::size_t>(scratch.slotA[i])] || !slow[static_cast<std::size_t>(scratch.slotB[i])]) continue;
            scratch.laneGroupOf[i] = static_cast<int>(group) + 1;
            scratch.laneHeldIsA[i] = order.lowerIsA[static_cast<std::size_t>(k)];
        }
    }
}

/// The sweep's visits: every block holding lanes of a group, once per group it holds, in the
/// groups' order (a stable counting sort; a group's lanes are independent, so the blocks' order
/// within it changes no bit). A wide block holds one colour's lanes sorted by group (orderLanes).
void ShockSweep::orderVisits(const ContactSolverScratch& scratch) {
    std::vector<ShockVisit>& visits = visitScratch_;
    visits.clear();
    for (std::size_t b = 0; b < scratch.wideBlocks.size(); ++b) {
        int last = 0;
        for (const int group : scratch.wideBlocks[b].shockGroup)
            if (group > 0 && group != last) visits.push_back({true, b, last = group});
    }
    for (std::size_t b = 0; b < scratch.scalarBlocks.size(); ++b)
        if (const int group = scratch.scalarBlocks[b].shockGroup[0]; group > 0) visits.push_back({false, b, group});
    std::vector<int>& start = visitBuckets_;
    start.assign(static_cast<std::size_t>(scratch.laneGroups) + 2, 0);
    for (const ShockVisit& visit : visits) ++start[static_cast<std::size_t>(visit.group) + 1];
    for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
    visits_.resize(visits.size());
    for (const ShockVisit& visit : visits)
        visits_[static_cast<std::size_t>(start[static_cast<std::size_t>(visit.group)]++)] = visit;
}
// [ch12-shock-groups]

void ShockSweep::prepare(ContactSolverScratch& scratch) {
    prepareHeldWide(scratch.wideBlocks);
    for (ManifoldBlock<1>& block : scratch.scalarBlocks)
        if (block.shockGroup[0] > 0) prepareHeld(block);
}

// [ch12-shock-sweep]
void ShockSweep::finish(ContactSolverScratch& scratch, const ContactSolveParams& params) {
    orderVisits(scratch);
    SolverBodyState* states = scratch.bodies.states.data();
    for (const ShockVisit& visit : visits_) {
        if (visit.wide)
            solveHeldWide(scratch.wideBlocks[visit.block], states, params, visit.group);
        else
            solveHeldBlock(scratch.scalarBlocks[visit.block], states, params, visit.group);
    }
}
// [ch12-shock-sweep]

}  // namespace stepwise
