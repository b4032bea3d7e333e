#pragma once
// The planner's constants, in one place. Each is a rule's parameter fitted to a measurement; the
// runs that fix them are in bench/results/planner-fits.txt (section numbers below), and the tests
// of tests/ch12/iteration_plan_test.cpp hold the planner to them.

#include "math/math.h"

namespace stepwise {

// Where no load passes from body to body, one sweep settles each contact and substeps buy only
// accuracy in time: the planner takes as many as keep each no longer than a length, so a scene
// stepped at 1/30 s does the same work a second as at 1/60 s. A frame in which a bouncy pair
// arrives keeps the scene's count: restitution reverses the speed of the substep a ball arrives
// in, and a long one overshoots (section 6).
/// Nothing touches: a free body moves on its exact parabola (chapter 11), so one substep at 60 Hz.
constexpr Real kFreeFlightSubstep = Real(1) / Real(60);
/// Bodies resting on the world alone, still or rolling steadily: nothing accelerates them.
constexpr Real kRestingSubstep = Real(1) / Real(60);
/// A body friction drags along accelerates, and Euler's step puts it h a t / 2 behind.
constexpr Real kSlidingSubstep = Real(1) / Real(120);
/// A touching pair slides when its friction impulses exceed this fraction of its normal ones and
/// one of its bodies moves faster than kRestingSpeed.
constexpr Real kFrictionAtRest = Real(1e-3);
constexpr Real kRestingSpeed = Real(1e-3);  // m/s

/// The frame the laws below were measured at. A stack's walk is set by the substep's length, so at
/// another dt the planner scales the counts by dt / kMeasuredFrame (section 7).
constexpr Real kMeasuredFrame = Real(1) / Real(60);

/// Touching mass ratios up to this solve at the scene's count; above it, the scene's count times
/// sqrt(ratio / kPlainMassRatio). Towers of four boxes, heaviest on top, stand at that count with
/// a substep or more to spare from 1:30 to 1:1000 (section 1).
constexpr Real kPlainMassRatio = 200;
/// The most the planner multiplies the scene's count by.
constexpr int kMostIterationFactor = 4;

/// A stack of like masses kPlainStackDepth deep walks kPlainStackDrift at the scene's count; the
/// walk goes as (depth^2 / substeps)^2, and the planner holds it to kHeldStackDrift without the
/// shock sweep: scene (d / kPlainStackDepth)^2 sqrt(kPlainStackDrift / kHeldStackDrift) (section 2).
constexpr int kPlainStackDepth = 20;
constexpr Real kPlainStackDrift = Real(0.0015);  // m
constexpr Real kHeldStackDrift = Real(0.005);    // m
/// A body resting on another sinks into it as the square of the stack over the substeps: a stack
/// takes at least this many (section 2).
constexpr int kFewestStackSubsteps = 2;
/// Touching masses within this ratio count as like; stacks of unlike masses keep the scene's count
/// and no sweep (section 5).
constexpr Real kLikeMassRatio = 2;
/// A heap of unlike masses no deeper than this takes the square-root law on its load-path ratio
/// instead of the scene's count: the heaps measured at that depth (the 600-body unlike pile, the
/// field of 100 ragdolls) sleep as soon at it, the 2,000-body mixed pile (9 to 13 deep) does not
/// (sections 5 and 9).
constexpr int kShallowUnlikeDepth = 6;
/// A shallow heap of unlike masses takes no fewer substeps than this, whatever its ratio: a 1:10
/// tower stands from three (section 5), and bench worlds' terrain pile, whose load paths read 7.6
/// (the law: two), sinks 21.7 mm into the ground at two and 9.3 mm at three (section 1).
constexpr int kFewestUnlikeSubsteps = 3;

/// With the shock sweep the walk goes as depth^2.4 / substeps^2; allowing kHeldWalkPerBody of walk
/// for each body of depth gives n = kShockStackSubsteps (d / 20)^kShockDepthExponent (section 3).
constexpr Real kHeldWalkPerBody = Real(0.000125);  // m
constexpr Real kShockStackSubsteps = Real(3.34);
constexpr Real kShockDepthExponent = Real(0.7);
/// A swept stack's substeps relax only after a biased sweep that pushed a point deeper than the
/// slop (chapter 11's relaxSweepNeeded): in a stack at rest none lies that deep, and each substep
/// is one sweep where a relaxed one is two. Measured, the walk goes as depth^2.4 / (n^2 sweeps),
/// so such substeps hold the relaxed count's walk at sqrt(2) times the count, about seven tenths
/// of its sweeps: a 100-row pyramid walks 13.9 mm at 15 of them against 15.2 mm at 11 relaxed
/// ones (section 10).
constexpr Real kOneSweepSubstepFactor = Real(1.41421356);
/// The sweep's price in substeps: kShockBlockSubsteps for each of its blocks over the frame's, a
/// one-lane block counting kShockLaneBlocks of a wide one. The planner takes the sweep where its
/// substeps and this price come to fewer than the substeps that hold the same walk without it
/// (section 4: a conservative price).
constexpr Real kShockBlockSubsteps = Real(2.1);
constexpr Real kShockLaneBlocks = Real(0.65);

/// A chain hanging from the world sags by its joints' springs: each joint gives F / (m_eff w^2),
/// with w at most a quarter of the substep rate (chapter 11), so the sag goes as the substep's
/// square and, over a chain of like links, as its depth. A 20-link chain of 25 cm links sags
/// kPlainChainSag of its length at the scene's count (ten substeps at 60 Hz: springs of 150 Hz;
/// docs/ch08_joints.md derives it, tests/ch12/joint_plan_test.cpp measures it). The planner holds
/// a chain of depth d to kHeldChainSag: scene sqrt(d / kPlainChainDepth x kPlainChainSag /
/// kHeldChainSag) substeps.
constexpr int kPlainChainDepth = 20;
constexpr Real kPlainChainSag = Real(0.000884);
constexpr Real kHeldChainSag = Real(0.0003);
/// Bodies joined to bodies and resting on the world take the sag law by their depth, but no fewer
/// than this: a limb pinned under a body a dozen times its mass (a forearm under a ragdoll's
/// chest) bends off its hinge at eight substeps and holds at nine, as at ten; and a count that
/// follows the depth from frame to frame below nine pumps a pinned elbow off its axis (sections 8
/// and 9).
constexpr int kFewestJointedSubsteps = 9;

}  // namespace stepwise
