#pragma once
// solver_iterations "auto" (docs/scene-format.md): how many substeps the fast solve spends on a
// frame, from what touches what. Sequential impulses carry a heavy body's weight through light
// ones slowly: each sweep passes on only part of an impulse where the body above is much
// heavier (Erleben, "Velocity-based shock propagation for multibody dynamics animation", 2007;
// Tonge, Benevolenski and Voroshilov, "Mass splitting for jitter-free parallel rigid body
// simulation", 2012). More substeps are the engine's cure for that, and a scene only pays for
// them when its touching masses differ widely.

#include "world/world.h"

#include <vector>

namespace stepwise {

/// Touching mass ratios up to this solve at the scene's count: a 100 kg box on 1 kg boxes
/// stands at ten substeps.
constexpr Real kPlainMassRatio = 100;
/// The most the planner multiplies the scene's count by.
constexpr int kMostIterationFactor = 4;

/// The substep count for this frame's contacts (indices into World::contacts), and what the
/// planner saw, into `plan` (World::step.iterationPlan).
int plannedIterations(const World& world, const std::vector<int>& contactOrder, IterationPlan& plan);

}  // namespace stepwise
