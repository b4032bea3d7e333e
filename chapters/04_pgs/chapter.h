#pragma once
// Chapter 4's pipeline: chapter 3's (integrate, narrowphase) plus the sequential-impulse solver.

#include "03_epa/chapter.h"
#include "world/pipeline.h"

#include <string>

namespace stepwise {

/// Where the solve sits in a step.
enum class StepOrder {
    /// Integrate (velocities and positions), collide, solve. The solved velocities only move the
    /// bodies in the next step, after gravity has been added again.
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
std::string solveStageName(SolverKind kind);

/// Chapter 3's pipeline plus the solve stage, in the order chooseStepOrder picks.
Pipeline makeChapter04Pipeline(const World& world);
Pipeline makeChapter04Pipeline(const World& world, StepOrder order,
                               ContactSearch search = ContactSearch::EverySubstep);

}  // namespace stepwise
