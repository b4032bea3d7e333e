#pragma once
// The solve in pieces: its rows are built once a piece, where the bodies stand as it begins, and a
// piece ends where a body a contact touches has turned kMostTurnPerPiece (solve_steps.h) since.
#include "11_wide_solve/contact_solver.h"

#include <vector>

namespace stepwise {

/// The substeps a frame's solve needs so that no awake dynamic body a contact touches turns more
/// than kMostTurnPerPiece in one (at its spin as the frame begins, held to kMostTurnPerSolve per
/// frame; a ball's rows stand at any turn): the plan's `substeps`, or more.
int substepsForTurns(const World& world, Real dt, int substeps);

/// The dynamic slots the piece's contacts touch (scratch.slotA and slotB), each once, into
/// scratch.touched.
void findTouched(ContactSolverScratch& scratch);

/// Whether a touched body has turned since the piece began, or would after one more substep of h
/// at its spin now, further than kMostTurnPerPiece.
bool turnedFar(const SolverBodyState* states, const std::vector<int>& touched, Real h);

}  // namespace stepwise
