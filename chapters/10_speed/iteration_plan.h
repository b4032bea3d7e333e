#pragma once
// solver_iterations "auto" (docs/scene-format.md): how many substeps the fast solve spends on a
// frame, from what touches what. Sequential impulses carry a heavy body's weight through light
// ones slowly: each sweep passes on only part of an impulse where the body above is much
// heavier (Erleben, "Velocity-based shock propagation for multibody dynamics animation", 2007;
// Tonge, Benevolenski and Voroshilov, "Mass splitting for jitter-free parallel rigid body
// simulation", 2012). More substeps are the engine's cure for that, and a scene only pays for
// them when its touching masses differ widely. A deep stack has the same trouble: when it is
// loaded (or hit), the load must cross every contact layer before the bottom pushes back
// enough, and while it crosses, the top rows sway.

#include "world/world.h"

#include <vector>

namespace stepwise {

/// Touching mass ratios up to this solve at the scene's count: a 100 kg box on 1 kg boxes
/// stands at ten substeps.
constexpr Real kPlainMassRatio = 100;
/// The most the planner multiplies the scene's count by.
constexpr int kMostIterationFactor = 4;

/// Stacks up to this many bodies deep stand at the scene's count: a 20-row pyramid takes its
/// load at ten substeps with its boxes 1.5 mm from where they started.
constexpr int kPlainStackDepth = 20;

/// Working memory of supportDepth, kept from frame to frame so that the search allocates nothing
/// once it has run: the contact graph in compressed rows, and the breadth-first search.
struct StackSearch {
    std::vector<int> start, fill, neighbours, depth, queue;
};

/// How many dynamic bodies the deepest stack has between its top and what holds it up (a static
/// or kinematic body): the longest of the shortest paths, in touching contacts, from a dynamic
/// body down to a support. 0 when no dynamic body touches a support.
int supportDepth(const World& world, const std::vector<int>& contactOrder, StackSearch& search);

/// The substep count for this frame's contacts (indices into World::contacts), and what the
/// planner saw, into `plan` (World::step.iterationPlan).
int plannedIterations(const World& world, const std::vector<int>& contactOrder, IterationPlan& plan,
                      StackSearch& search);

}  // namespace stepwise
