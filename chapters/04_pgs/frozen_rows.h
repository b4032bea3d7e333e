#pragma once
// One contact set, frozen: the rows and velocities the solver would get at some frame of a scene.
// Solving copies of it with different methods and iteration counts compares the methods on
// exactly the same problem (the convergence test and `stepwise bench solver` both use it).

#include "04_pgs/constraint_row.h"

#include <vector>

namespace stepwise {

struct FrozenRows {
    std::vector<ConstraintRow> rows;
    std::vector<SolverBody> bodies;
};

/// The sphere pit of `sphereCount` balls after `frames` frames of the chapter 4 pipeline, frozen
/// at the next frame's first solve: its stages up to the solve have run, the solve has not.
FrozenRows freezeSpherePitRows(int sphereCount, int frames);

}  // namespace stepwise
