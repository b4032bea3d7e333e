#pragma once
// solver_iterations "auto" (docs/scene-format.md): how many substeps the fast solve spends on a
// frame, from what touches what. Sequential impulses carry a heavy body's weight through light
// ones slowly: each sweep passes on only part of an impulse where the body above is much
// heavier (Erleben, "Velocity-based shock propagation for multibody dynamics animation", 2007;
// Tonge, Benevolenski and Voroshilov, "Mass splitting for jitter-free parallel rigid body
// simulation", 2012). More substeps are the engine's cure for that, and a scene only pays for
// them where a heavy body rests on a much lighter one (load_paths.h). A deep stack has the same trouble: when it is
// loaded (or hit), the load must cross every contact layer before the bottom pushes back
// enough, and while it crosses, the top rows sway.

#include "12_planner/plan_constants.h"
#include "12_planner/load_paths.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

/// A law's real-valued count as a whole one: rounded up, but a hair over a whole number is that
/// number (float rounding makes 10.000001 of ten).
int countOf(Real substeps);

/// Substeps that keep each no longer than `longest` (at least one).
int substepsFor(Real dt, Real longest);

/// The most substeps the planner takes: kMostIterationFactor times the scene's count, at least
/// at the measured frame's substep length.
int mostSubsteps(int scene, Real perMeasuredFrame);

/// The square-root law (kPlainMassRatio): scene sqrt(ratio / kPlainMassRatio) substeps.
int squareRootLawCount(int scene, Real ratio, Real perMeasuredFrame);

/// The sag law (kPlainChainSag, kHeldChainSag): the count that holds a chain `depth` links deep
/// to kHeldChainSag.
int sagLawCount(int scene, int depth, Real perMeasuredFrame);

/// What the planner reads off a frame's touching contacts: whether any pair bounces, and the
/// touching dynamic bodies' mass ratio (heaviest over lightest; 1 when no two dynamic bodies touch).
struct TouchSummary {
    bool bouncy = false;   // a pair with restitution closes faster than the restitution threshold
    bool sliding = false;  // a touching body moves along the surface under friction (accelerates)
    bool restitution = false;  // a touching pair has restitution (its solve relaxes every substep)
    Real massRatio = 1;
};

TouchSummary summarizeTouches(const World& world, const std::vector<int>& contacts);

/// Working memory of supportDepth, kept from frame to frame so that the search allocates nothing
/// once it has run: the contact graph in compressed rows, and the breadth-first search.
struct StackSearch {
    std::vector<int> start, fill, neighbours, depth, queue;
    std::vector<int> ends;                // the contacts' bodies, two a contact
    std::vector<unsigned char> dynamic;   // a byte a body: whether it is dynamic
    std::vector<int> downward, layerLanes, layerGroups;  // the shock sweep's cost (shockSweepSubsteps)
    LoadPathSearch loads;                                // the mass ratio along load paths
};

/// How many dynamic bodies the deepest stack has between its top and what holds it up (a static
/// or kinematic body): the longest of the shortest paths, in touching contacts, from a dynamic
/// body down to a support. 0 when no dynamic body touches a support.
/// With `withJoints`, a joint ties its two bodies as a contact does (chapter 8's solve).
int supportDepth(const World& world, const std::vector<int>& contactOrder, StackSearch& search,
                 bool withJoints = false);

/// What a shock sweep over these contacts would cost, in substeps (kShockBlockSubsteps): its blocks
/// counted as shock_propagation.h groups them (a layer's contacts, in as many groups as an upper
/// body there has contacts downwards), over the frame's. Reads the depths supportDepth left.
Real shockSweepSubsteps(const World& world, const std::vector<int>& contactOrder, StackSearch& search);

/// The substep count for a solve of `dt` over this frame's contacts (indices into
/// World::contacts), and what the planner saw, into `plan` (World::step.iterationPlan: its
/// iterations are the count).
/// `shockAllowed` false (the speed bench's A/B): the same count, without the sweep.
int plannedIterations(const World& world, Real dt, const std::vector<int>& contactOrder, IterationPlan& plan,
                      StackSearch& search, bool shockAllowed = true);

/// Counts the rule that decided this frame (plan.reason) in plan.reasons: the run report's
/// "counts", which say why each count was chosen. The plan stage calls it once a frame.
void tallyPlanReason(IterationPlan& plan);

/// plannedIterations for a scene with joints, solved in the same substeps as the contacts
/// (chapter 11's joint pass): the contacts' count, and no fewer than the joints need: as many as
/// hold what hangs from the world by joints to kHeldChainSag, the scene's count where a joint joins
/// two awake dynamic bodies or joints and contacts stack bodies on one another (a chain carries
/// its load link by link, as a stack does), and the mass-ratio law over jointed pairs too (a chain
/// under a heavy body). No shock sweep: it holds contacts only.
int plannedLinkedIterations(const World& world, Real dt, const std::vector<int>& contactOrder, IterationPlan& plan,
                            StackSearch& search);

/// The substep count for chapter 8's solve, which chapters 10 to 12 keep for scenes with joints: where
/// every dynamic body hangs or rests on the world alone, through a joint or a contact, and nothing
/// bounces, substeps of kFreeFlightSubstep if nothing touches (a pendulum: one at 60 Hz), else of
/// kRestingSubstep or kSlidingSubstep; the scene's count elsewhere. Scenes without joints, with
/// springs, or with a stabilisation that does not substep keep the scene's count.
/// `contacts` is working memory (the touching contacts' indices).
int plannedJointSolveIterations(const World& world, Real dt, std::vector<int>& contacts, IterationPlan& plan,
                                StackSearch& search);

}  // namespace stepwise
