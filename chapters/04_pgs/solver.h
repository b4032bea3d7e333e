#pragma once
// Projected Gauss-Seidel and (for comparison) projected Jacobi over generic constraint rows.
// Both iterate on the rows' accumulated impulses and clamp them to their bounds; they differ
// only in when a row sees the velocity changes of the others.

#include "04_pgs/constraint_row.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

/// One SolverBody per World body, read from the bodies' Motions (statics get zero velocity and
/// zero inverse mass).
std::vector<SolverBody> gatherSolverBodies(const World& world);

/// Writes the solved velocities back into the Motions of the dynamic bodies.
void scatterSolverBodies(World& world, const std::vector<SolverBody>& bodies);

/// One row's 1 / (J M^-1 J^T), 0 when no body can move along it.
Real effectiveMass(const ConstraintRow& row, const std::vector<SolverBody>& bodies);

/// Fills each row's effectiveMass = 1 / (J M^-1 J^T) from the bodies' inverse masses.
void computeEffectiveMasses(std::vector<ConstraintRow>& rows, const std::vector<SolverBody>& bodies);

/// Relative velocity along a row, J v.
Real rowVelocity(const ConstraintRow& row, const std::vector<SolverBody>& bodies);

/// Applies `impulse` along one row to its two bodies: v += M^-1 J^T impulse.
void applyRowImpulse(const ConstraintRow& row, Real impulse, std::vector<SolverBody>& bodies);

/// Applies every row's current accumulated impulse to the bodies (the warm start of chapter 6: rows
/// that begin with last frame's impulse must first push the bodies by it).
void applyRowImpulses(const std::vector<ConstraintRow>& rows, std::vector<SolverBody>& bodies);

/// Projected Gauss-Seidel: rows are solved one after the other, each against the velocities the
/// rows before it already changed.
void solveGaussSeidel(std::vector<ConstraintRow>& rows, std::vector<SolverBody>& bodies, int iterations);

/// Projected Jacobi: every row computes its impulse from the velocities at the start of the
/// iteration, then all are applied together, each scaled down by the number of rows that share
/// its busiest body.
void solveJacobi(std::vector<ConstraintRow>& rows, std::vector<SolverBody>& bodies, int iterations);

/// Dispatches on Settings::solver.
void solveRows(std::vector<ConstraintRow>& rows, std::vector<SolverBody>& bodies, SolverKind kind, int iterations);

/// How far the rows are from solved, in m/s: for each row the natural residual of its
/// complementarity problem, lambda - clamp(lambda - m (J v - bias), lower, upper), divided by
/// its effective mass m. It is J v - bias for a row inside its bounds and 0 for a row resting on
/// a bound that it pushes against, so it is zero exactly at a solution.
struct Residual {
    Real rms = 0;   // root mean square over the rows
    Real max = 0;   // largest magnitude
};
Residual measureResidual(const std::vector<ConstraintRow>& rows, const std::vector<SolverBody>& bodies);

}  // namespace stepwise
