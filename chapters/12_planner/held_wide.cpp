#include "12_planner/held_wide.h"

#include "12_planner/held_kernels.h"

#include <algorithm>

namespace stepwise {

void prepareHeldWide(std::vector<ManifoldBlock<kWideLanes>>& blocks) {
    for (ManifoldBlock<kWideLanes>& block : blocks)
        if (std::any_of(block.shockGroup, block.shockGroup + kWideLanes, [](int group) { return group > 0; }))
            prepareHeld(block);
}

void solveHeldWide(const ManifoldBlock<kWideLanes>& block, SolverBodyState* states, const ContactSolveParams& params,
                   int group) {
    solveHeldBlock(block, states, params, group);
}

}  // namespace stepwise
