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

/// How long a substep may be where no load passes from body to body (solver_iterations "auto").
/// Bodies that carry one another need the scene's count of sweeps in every solve, however short
/// (a load crosses one contact layer a sweep). Where nothing touches, or where every touching body
/// rests on the world alone and nothing bounces, one sweep settles each contact, and substeps buy
/// only accuracy in time: the planner takes as many as keep each no longer than these, so a scene
/// stepped at 1/30 s does the same work a second as at 1/60 s (docs/ch10_speed.md). A frame in
/// which a bouncy pair arrives (closes faster than the restitution threshold) keeps the scene's
/// count: restitution reverses the speed of the substep a ball arrives in, and a long one
/// overshoots (an elastic ball dropped from 2 m rose 3 cm above its start with two). Bouncy bodies
/// that rest against one another, or part, do not bounce, and take the lengths below.
/// Free flight: semi-implicit Euler's fall is off by g h t / 2, 8 cm after a second at 1/60 s;
/// chapter 10 moves a free body on its exact parabola instead.
constexpr Real kFreeFlightSubstep = Real(1) / Real(60);
/// Bodies resting on the world alone, at rest or rolling steadily: nothing accelerates them along
/// the surface, and one substep a frame at 60 Hz holds them (the reference rolling ball ends within
/// 2e-5 m/s of 5/7 of its speed, docs/engine_bench.md).
constexpr Real kRestingSubstep = Real(1) / Real(60);
/// ...and where friction drags one along (a sliding block, a ball still skidding): it accelerates,
/// and Euler's step puts it h a t / 2 behind; the reference ramp's sliding block is 2 cm off at
/// one substep a frame, 1 cm at two (its tolerance 4 cm).
constexpr Real kSlidingSubstep = Real(1) / Real(120);
/// A touching pair slides under friction when its friction impulses are more than this fraction
/// of its normal ones and one of its bodies moves faster than kRestingSpeed.
constexpr Real kFrictionAtRest = Real(1e-3);
constexpr Real kRestingSpeed = Real(1e-3);  // m/s

/// Substeps that keep each no longer than `longest` (at least one).
int substepsFor(Real dt, Real longest);

/// The frame the stack and mass-ratio laws below were measured at (60 Hz). What sets how far a
/// stack walks and sinks is the substep's length, not the frame's: at another dt the planner takes
/// the measured count times dt / kMeasuredFrame (the same substep), so a 20-row pyramid stepped at
/// 30 Hz stands as it does at 60 Hz (at the 60 Hz count it walked 1 cm, and the 1:1000 tower fell).
constexpr Real kMeasuredFrame = Real(1) / Real(60);

/// Touching mass ratios up to this solve at the scene's count: a 100 kg box on 1 kg boxes
/// stands at ten substeps.
constexpr Real kPlainMassRatio = 100;
/// The most the planner multiplies the scene's count by.
constexpr int kMostIterationFactor = 4;

/// A stack of bodies of like mass, this many deep, at the scene's count (ten substeps): a 20-row
/// pyramid takes its load with its boxes kPlainStackDrift from where they started.
constexpr int kPlainStackDepth = 20;
constexpr Real kPlainStackDrift = Real(0.0015);  // m
/// How far the planner lets a stack's boxes walk: half the reference scenes' 1 cm. Measured on
/// pyramids of 1 m boxes, the walk goes as (depth^2 / substeps)^2 (docs/ch10_speed.md), so the
/// planner takes scene * (depth / kPlainStackDepth)^2 * sqrt(kPlainStackDrift / kHeldStackDrift).
constexpr Real kHeldStackDrift = Real(0.005);  // m
/// A body resting on another sinks into it as the square of the stack over the substeps: four
/// 1 m boxes sink 14 mm in all at one substep a frame, 3.6 mm at two (each contact within the
/// slop either way), 0.8 mm at four. A stack takes at least this many.
constexpr int kFewestStackSubsteps = 2;
/// Touching masses within this ratio count as like.
constexpr Real kLikeMassRatio = 2;

/// A stack of like masses into which nothing arrives bouncing ends each frame with the shock sweep
/// (shock_propagation.h), and then needs far fewer substeps. Measured on pyramids of 1 m boxes
/// with it, the walk goes as depth^2.4 / substeps^2 (docs/ch10_speed.md): 20 rows walk 10 mm at
/// two substeps, 3.1 mm at three, 1.7 mm at four; 40 rows 9.3 mm at four, 4.2 mm at six; 100 rows
/// 3.7 cm at six, 1.55 cm at ten, 6.5 mm at 16. The planner lets a stack walk kHeldWalkPerBody for
/// each body of its depth (a taller stack may settle further: 2.5 mm on 20 rows, 5 mm on 40, half
/// the reference pyramids' 1 cm), which gives
///   n = 3 (d / 20)^1.2 sqrt(3.1 mm / (d kHeldWalkPerBody)) = kShockStackSubsteps (d / 20)^0.7.
constexpr Real kHeldWalkPerBody = Real(0.000125);  // m
constexpr Real kShockStackSubsteps = Real(3.34);
constexpr Real kShockDepthExponent = Real(0.7);
/// The sweep is not free. Priced as its first version cost, which copied each of its lanes into
/// blocks of its own, prepared and solved them once: about kShockBlockSubsteps substeps' work on
/// one of the frame's blocks, and a one-lane block (a group of one contact) kShockLaneBlocks of a
/// wide one; the sweep now solves the frame's blocks and costs about a third of that, so the price
/// is conservative (docs/ch10_speed.md, What is left). Measured: on the 20-row pyramid,
/// where the sweep has about as many blocks as the frame, a sweep cost 2.6 substeps; on the 16-box
/// column, fifteen layers of one contact against the frame's two blocks, ten. The planner takes
/// the sweep where its substeps and this cost come to fewer than the substeps that, without it,
/// hold the walk the sweep's law allows (kHeldWalkPerBody a body of depth): from about 20 rows on a
/// pyramid, never on a column of single boxes.
constexpr Real kShockBlockSubsteps = Real(2.1);
constexpr Real kShockLaneBlocks = Real(0.65);
// Stacks of unlike masses keep the scene's count and no sweep: with it, towers of four boxes stand
// at fewer substeps (docs/ch10_speed.md), but the 2,000-body mixed pile given those counts never
// settled.

/// Working memory of supportDepth, kept from frame to frame so that the search allocates nothing
/// once it has run: the contact graph in compressed rows, and the breadth-first search.
struct StackSearch {
    std::vector<int> start, fill, neighbours, depth, queue;
    std::vector<int> downward, layerLanes, layerGroups;  // the shock sweep's cost (shockSweepSubsteps)
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

/// The substep count for chapter 8's solve, which chapters 10 to 12 keep for scenes with joints: where
/// every dynamic body hangs or rests on the world alone, through a joint or a contact, and nothing
/// bounces, substeps of kFreeFlightSubstep if nothing touches (a pendulum: one at 60 Hz), else of
/// kRestingSubstep or kSlidingSubstep; the scene's count elsewhere. Scenes without joints, with
/// springs, or with a stabilisation that does not substep keep the scene's count.
/// `contacts` is working memory (the touching contacts' indices).
int plannedJointSolveIterations(const World& world, Real dt, std::vector<int>& contacts, IterationPlan& plan,
                                StackSearch& search);

}  // namespace stepwise
