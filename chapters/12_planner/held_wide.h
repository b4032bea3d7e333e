#pragma once
// The shock sweep's wide kernels, in the one file of chapter 12 built for the wide instruction set
// (as chapter 11's wide_solver.h, and for the same reason).

#include "11_wide_solve/solver_data.h"

#include <vector>

namespace stepwise {

/// The held masses of every block that holds lanes of the sweep (prepareHeld).
void prepareHeldWide(std::vector<ManifoldBlock<kWideLanes>>& blocks);
/// The sweep's solve of one block's lanes in `group` (solveHeldBlock).
void solveHeldWide(const ManifoldBlock<kWideLanes>& block, SolverBodyState* states, const ContactSolveParams& params,
                   int group);

}  // namespace stepwise
