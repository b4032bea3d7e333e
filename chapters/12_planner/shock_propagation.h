#pragma once
// Shock propagation (Guendelman, Bridson and Fedkiw, "Nonconvex rigid bodies with stacking",
// SIGGRAPH 2003; Erleben, "Velocity-based shock propagation for multibody dynamics animation",
// ACM TOG 2007). Sequential impulses pass a stack's weight down one contact layer a sweep, and
// push back up just as slowly: in a deep pyramid the boxes high up sway while the load crosses
// the rows below them, and walk sideways. One more relax sweep at the end of the frame, from the
// supports up, with each contact's lower body held still (infinitely heavy: its velocity read,
// never changed), settles every layer on the one below it in a single pass: the bottom row on the
// ground, the second row on the first as it now moves, and so on to the top.
//
// The layers are the planner's (supportDepth): a body's depth is its distance, in touching
// contacts, from a static body. A contact between depths d and d + 1 is in layer d; contacts
// between bodies of one depth (side by side) and contacts with a body that does not move are left
// to the ordinary sweeps. Within a layer no two contacts of a group share the upper body, so a
// group solves kWideLanes at a time: the lower bodies are only read.

#include <cstdint>
#include <vector>

namespace stepwise {

/// The planner's price of a sweep (iteration_plan.h) counts a group's contacts left over after its
/// full wide blocks as one more wide block when at least this many, else as one-lane blocks (the
/// blocks kShockBlockSubsteps and kShockLaneBlocks price, plan_constants.h).
constexpr int kShockWideLanesAtLeast = 2;

/// The order of a shock sweep: groups, layer by layer from the supports up.
struct ShockOrder {
    std::vector<int> entries;             // indices into the solve's contact order
    std::vector<std::uint8_t> lowerIsA;   // per entry: body A is the one held still (else B)
    std::vector<int> groupStart;          // group g is entries [groupStart[g], groupStart[g + 1])
    // Working memory, kept so that a steady scene allocates nothing.
    std::vector<int> layerStart, layered, colour, seen, groupCount;
};

/// The shock sweep's order for the contacts whose bodies sit in solver slots slotA[i] and
/// slotB[i] (0: does not move), a slot's depth being slotDepth[slot] (supportDepth's layers).
void orderShockSweep(const std::vector<int>& slotA, const std::vector<int>& slotB, const std::vector<int>& slotDepth,
                     ShockOrder& order);

}  // namespace stepwise
