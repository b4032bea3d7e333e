#pragma once
// Chapter 4's pipeline: chapter 3's (integrate, narrowphase) plus the sequential-impulse solver.

#include "world/pipeline.h"

namespace stepwise {

struct SolveStats;

/// Where the solve sits in a step.
enum class StepOrder {
    /// The first seed's order: integrate (velocities and positions), collide, solve. The solved
    /// velocities only move the bodies in the next step, after gravity has been added again.
    IntegrateFirst,
    /// Semi-implicit Euler split around the solve: integrate:velocities (gravity and forces),
    /// collide, solve, integrate:positions. The positions move with the solved velocities.
    SplitIntegration,
};

const char* toString(StepOrder order);

/// SplitIntegration when every dynamic body uses semi-implicit Euler (the split is that method's
/// two halves); IntegrateFirst for RK4 and Verlet, which need their whole step in one piece.
StepOrder chooseStepOrder(const World& world);

/// "solve:pgs" or "solve:jacobi", after Settings::solver.
const char* solveStageName(SolverKind kind);

/// Chapter 3's pipeline plus the solve stage, in the order chooseStepOrder picks.
Pipeline makeChapter04Pipeline(const World& world);
Pipeline makeChapter04Pipeline(const World& world, StepOrder order);

/// What the pipeline's solve stage measured in its last run (the last substep of the last
/// frame): rows, removed points, residual. nullptr for a pipeline without chapter 4's stage.
/// Copies of a pipeline share this record (and the velocity copy restitution uses): make one
/// pipeline per world.
const SolveStats* lastSolveStats(const Pipeline& pipeline);

}  // namespace stepwise
