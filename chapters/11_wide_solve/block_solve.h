#pragma once
// A block's sweep: the warm start, the four normal rows solved as one block (a corner that would
// pull let go), then friction against the loads just found.
#include "11_wide_solve/friction_patch.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

// [ch11-idle-block]
/// Whether no lane of the block holds an impulse: every point's normal impulse, the friction,
/// twist and rolling impulses all zero. Such a block's warm start pushes by zero, and so does its
/// sweep where no lane asks for an impulse either (every lane idle, normalBlockStep): it is
/// skipped, and its bodies keep their velocities exactly as a sweep adding zeros would leave them.
/// In a touching 100-row pyramid a fifth of the blocks are such: bricks side by side in a row,
/// touching and carrying nothing.
template <int N>
inline bool holdsNoImpulse(const ManifoldBlock<N>& c) {
    bool held = anyNonZero(c.tangentImpulse1) || anyNonZero(c.tangentImpulse2) || anyNonZero(c.twistImpulse) ||
                anyNonZero(c.rollingImpulse.x) || anyNonZero(c.rollingImpulse.y) || anyNonZero(c.rollingImpulse.z);
    for (const ManifoldPointPack<N>& p : c.point) held = held || anyNonZero(p.normalImpulse);
    return !held;
}
// [ch11-idle-block]

/// Pushes the bodies by the impulses the manifold carries (from last frame, then from each
/// substep): every substep starts from the whole accumulated impulse, as Box3D does. The normal
/// impulses all point along n, so their turning adds up as one cross product:
/// sum(lambda_i r_i x n) = (sum(lambda_i r_i)) x n.
template <int N>
inline void warmStartBlock(const ManifoldBlock<N>& c, SolverBodyState* states) {
    if (holdsNoImpulse(c)) return;  // it would push by zero
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    const Pack<N> zero = Pack<N>::splat(0);
    Pack<N> pushed = zero;
    PackVec3<N> leverA{zero, zero, zero}, leverB{zero, zero, zero};
    for (const ManifoldPointPack<N>& p : c.point) {
        pushed = pushed + p.normalImpulse;
        leverA = leverA + p.normalImpulse * p.armA;
        leverB = leverB + p.normalImpulse * p.armB;
    }
    a.linearVelocity = a.linearVelocity - (c.inverseMassA * pushed) * c.normal;
    a.angularVelocity = a.angularVelocity - c.inverseInertiaA * cross(leverA, c.normal);
    b.linearVelocity = b.linearVelocity + (c.inverseMassB * pushed) * c.normal;
    b.angularVelocity = b.angularVelocity + c.inverseInertiaB * cross(leverB, c.normal);
    applyFriction(c, c.tangentImpulse1, c.tangentImpulse2, a, b);
    a.angularVelocity = a.angularVelocity - c.twistImpulse * c.twistTurnA;
    b.angularVelocity = b.angularVelocity + c.twistImpulse * c.twistTurnB;
    if (anyNegative(-c.rollingLength)) {  // a lane resists rolling
        a.angularVelocity = a.angularVelocity - c.inverseInertiaA * c.rollingImpulse;
        b.angularVelocity = b.angularVelocity + c.inverseInertiaB * c.rollingImpulse;
    }
    scatterVelocities(states, c.slotA, a);
    scatterVelocities(states, c.slotB, b);
}

/// What every point of a manifold shares in its separation: how far the bodies have moved apart
/// along the normal, and the normal turned back into each body's start frame.
template <int N>
struct SeparationFrame {
    Pack<N> movedApart;
    PackVec3<N> normalSeenByA, normalSeenByB;  // n . (R arm) = (R^T n) . arm: turned back once per body
};
template <int N>
inline SeparationFrame<N> separationFrame(const ManifoldBlock<N>& c, const BodyPack<N>& a, const BodyPack<N>& b) {
    return {dot(c.normal, b.deltaPosition - a.deltaPosition), rotate(conjugate(a.deltaRotation), c.normal),
            rotate(conjugate(b.deltaRotation), c.normal)};
}
/// Each point's separation from where its two material points are now: the separation found at
/// the frame's start plus how far the bodies have moved and turned since (adjustedSeparation holds
/// the start's normal . (armB - armA) taken out, so the arms as turned now go in whole).
template <int N>
inline Pack<N> pointSeparation(const ManifoldPointPack<N>& p, const SeparationFrame<N>& f) {
    return f.movedApart + dot(f.normalSeenByB, p.armB) - dot(f.normalSeenByA, p.armA) + p.adjustedSeparation;
}
template <int N>
inline void pointSeparations(const ManifoldBlock<N>& c, const BodyPack<N>& a, const BodyPack<N>& b, Pack<N> separations[4]) {
    const SeparationFrame<N> frame = separationFrame(c, a, b);  // serves all four points
    for (int k = 0; k < 4; ++k) separations[k] = pointSeparation(c.point[k], frame);
}

/// Entries of the normal block's inverse M = K^-1 by point pair (normalBlockInverse keeps the upper triangle).
constexpr int kBlockEntry[4][4] = {{0, 1, 2, 3}, {1, 4, 5, 6}, {2, 5, 7, 8}, {3, 6, 8, 9}};

/// solveBlock's increments with the corner that pulls hardest let go, and the lanes where that
/// answer holds (useDropped 1: the corner separates, the others still push, the rows are rigid).
template <int N>
inline void dropCorner(const Pack<N> blockInverse[10], const Pack<N> normalImpulse[4], const Pack<N> total[4],
                       const Pack<N> increment[4], const Pack<N>& useBlock, const Pack<N>& rigid, Pack<N> dropped[4],
                       Pack<N>& useDropped) {
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    Pack<N> worst = total[0], column[4], chosen[4];
    for (int i = 0; i < 4; ++i) {
        column[i] = blockInverse[kBlockEntry[i][0]];
        chosen[i] = i == 0 ? one : zero;
    }
    for (int j = 1; j < 4; ++j) {
        const Pack<N> worse = worst - total[j];  // > 0: corner j pulls harder
        for (int i = 0; i < 4; ++i) {
            column[i] = selectPositive(worse, blockInverse[kBlockEntry[i][j]], column[i]);
            chosen[i] = selectPositive(worse, i == j ? one : zero, chosen[i]);
        }
        worst = min(worst, total[j]);
    }
    Pack<N> pivot = zero;  // M_jj
    for (int i = 0; i < 4; ++i) pivot = pivot + chosen[i] * column[i];
    const Pack<N> release = -worst / max(pivot, Pack<N>::splat(Real(1e-30)));
    Pack<N> leastDropped = zero;
    for (int i = 0; i < 4; ++i) {
        dropped[i] = selectPositive(chosen[i], -normalImpulse[i], increment[i] + release * column[i]);
        leastDropped = min(leastDropped, selectPositive(chosen[i], zero, normalImpulse[i] + dropped[i]));
    }
    useDropped = (one - useBlock) * selectNonNegative(leastDropped, selectNonNegative(release, rigid, zero), zero);
}

/// Each point's target and softness for this sweep, from where its two material points are now
/// (pointSeparations). A gap may close by itself within the substep and no faster (speculative);
/// with `useBias` a point deeper than the slop is pushed out (Baumgarte or a soft spring), at most
/// maxPushOutSpeed.
template <int N>
struct PointTargets {
    Pack<N> bias[4], massScale[4], impulseScale[4], separations[4];
};

/// One point's bias, mass scale and impulse scale from its separation.
template <int N>
inline void pointTarget(const ManifoldBlock<N>& c, const Pack<N>& separation, const ContactSolveParams& params,
                        bool useBias, Pack<N>& bias, Pack<N>& massScale, Pack<N>& impulseScale) {
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    bias = separation * Pack<N>::splat(1 / params.substep);
    massScale = one;
    impulseScale = zero;
    if (useBias) {
        const Pack<N> excess = separation + Pack<N>::splat(params.slop);  // < 0: deeper than the slop
        const Pack<N> push = max(c.biasRate * excess, Pack<N>::splat(-params.maxPushOutSpeed));
        const Pack<N> deep = -excess;
        bias = selectPositive(separation, bias, selectPositive(deep, push, zero));
        massScale = selectPositive(deep, c.massScale, one);
        impulseScale = selectPositive(deep, c.impulseScale, zero);
    } else {
        bias = selectPositive(separation, bias, zero);
    }
}

template <int N>
inline void pointTargets(const ManifoldBlock<N>& c, const BodyPack<N>& a, const BodyPack<N>& b,
                         const ContactSolveParams& params, bool useBias, PointTargets<N>& t) {
    pointSeparations(c, a, b, t.separations);
    for (int k = 0; k < 4; ++k) pointTarget(c, t.separations[k], params, useBias, t.bias[k], t.massScale[k], t.impulseScale[k]);
}

// [ch11-deeper-than-slop]
/// Whether a point of the block (a present one: normalMass > 0) lies deeper than the slop: the
/// points a biased sweep pushes out (pointTarget), whose push the relax sweep takes back. Counted
/// whether or not the push is applied (a lane separating fast enough takes none): a sweep that
/// says "none" pushed nothing.
template <int N>
inline bool anyPointDeep(const ManifoldBlock<N>& c, const Pack<N>* separations, const ContactSolveParams& params,
                         int points = 4) {
    const Pack<N> zero = Pack<N>::splat(0);
    Pack<N> deepest = zero;  // the most negative excess over the slop
    for (int k = 0; k < points; ++k)
        deepest = min(deepest, selectPositive(c.point[k].normalMass, separations[k] + Pack<N>::splat(params.slop), zero));
    return anyNegative(deepest);
}
// [ch11-deeper-than-slop]

/// Restitution's record of a closing gap (the relax sweep looks one substep ahead): restitution
/// reverses the fastest speed it closed at, not the speed at the frame's start, which the fall has
/// not finished. The fastest: once stopped, a point stays a rounding error apart and "closes"
/// again at gravity's speed. `target` is the row's speed plus bias, `speed` without the bias.
template <int N>
inline void keepApproachSpeed(ManifoldPointPack<N>& p, const Pack<N>& separation, const Pack<N>& target,
                              const Pack<N>& speed) {
    const Pack<N> closes = min(separation, -target);  // > 0: apart now, closed within h
    p.approachSpeed = selectPositive(closes, min(p.approachSpeed, speed), p.approachSpeed);
}

/// How fast a point's two material points close along the normal (its row's J v).
template <int N>
inline Pack<N> normalRowSpeed(const ManifoldBlock<N>& c, const BodyPack<N>& a, const BodyPack<N>& b,
                              const PackVec3<N>& angularA, const PackVec3<N>& angularB) {
    return dot(c.normal, b.linearVelocity - a.linearVelocity) + dot(b.angularVelocity, angularB) -
           dot(a.angularVelocity, angularA);
}

/// Chapter 4's row update of one normal row, softened: the point's accumulated impulse after it.
template <int N>
inline Pack<N> normalRowImpulse(const ManifoldPointPack<N>& p, const Pack<N>& speed, const Pack<N>& bias,
                                const Pack<N>& massScale, const Pack<N>& impulseScale) {
    const Pack<N> impulse = -(p.normalMass * massScale * (speed + bias)) - impulseScale * p.normalImpulse;
    return max(p.normalImpulse + impulse, Pack<N>::splat(0));
}

/// The four normal rows' change as one block, and where it holds (useBlock) or holds with the
/// corner that pulls hardest let go (useDropped); idle is 1 where the rows carry nothing and ask
/// for nothing (no change), blockFails 1 where none of the three holds.
template <int N>
struct BlockStep {
    Pack<N> increment[4], dropped[4], useBlock, useDropped, blockFails;
    Pack<N> idle;  // 1 where the lane holds no normal impulse and no row asks for one
};

// [ch11-normal-block-step]
/// The increments that make every row's speed its target at once: chapter 4's row, four rows at a
/// time, K d = b - J v with b each row's target. The code keeps -b as the row's bias, so
/// d = -K^-1 (J v + bias). Kept where they leave every point pushing (lambda + d >= 0) and every
/// row rigid.
/// Also keeps each point's fastest closing speed for restitution where a lane bounces.
template <int N>
inline void normalBlockStep(ManifoldBlock<N>& c, const BodyPack<N>& a, const BodyPack<N>& b, const PointTargets<N>& t,
                            const PackVec3<N> angularA[4], const PackVec3<N> angularB[4], bool bounces,
                            BlockStep<N>& s) {
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    Pack<N> target[4];  // each row's speed plus bias
    const Pack<N> approach = dot(c.normal, b.linearVelocity - a.linearVelocity);
    for (int k = 0; k < 4; ++k) {
        const Pack<N> speed = approach + dot(b.angularVelocity, angularB[k]) - dot(a.angularVelocity, angularA[k]) + t.bias[k];
        target[k] = selectPositive(c.point[k].normalMass, speed, zero);  // a missing point asks for nothing
        if (bounces) keepApproachSpeed(c.point[k], t.separations[k], target[k], speed - t.bias[k]);
    }
    Pack<N> total[4], leastLoad = zero, softness = zero, leastTarget = target[0], mostImpulse = zero;
    for (int i = 0; i < 4; ++i) {
        leastTarget = min(leastTarget, target[i]);
        mostImpulse = max(mostImpulse, c.point[i].normalImpulse);
        s.increment[i] = -(c.normalBlockInverse[kBlockEntry[i][0]] * target[0] + c.normalBlockInverse[kBlockEntry[i][1]] * target[1] +
                           c.normalBlockInverse[kBlockEntry[i][2]] * target[2] + c.normalBlockInverse[kBlockEntry[i][3]] * target[3]);
        total[i] = c.point[i].normalImpulse + s.increment[i];
        leastLoad = min(leastLoad, total[i]);
        softness = max(softness, t.impulseScale[i]);
    }
    const Pack<N> rigid = selectPositive(softness, zero, one);
    s.useBlock = selectNonNegative(leastLoad, rigid, zero);
    // A lane whose rows hold no impulse and whose points all part or keep their distance (every
    // target at least zero) has nothing to do: the rows' answer is no impulse at all (K is
    // positive definite, so it is the only answer), which is what sweeping them one at a time
    // finds too. Its block "fails" only because K^-1 asks every corner to pull a little (two
    // touching neighbours in a row of bricks: a third of a touching pyramid's manifolds).
    // Such a lane takes exactly no impulse, not the rounding of K^-1's columns that the block or a
    // corner let go would give it (so that a block of such lanes can be skipped, holdsNoImpulse).
    s.idle = selectNonNegative(leastTarget, one, zero) * selectPositive(mostImpulse, zero, one);
    // Where one corner would pull, let it go: its impulse becomes zero and the other rows still
    // meet their targets. With M = K^-1 that is d + s M e_j, s = -(lambda_j + d_j) / M_jj, exact
    // when s >= 0 (the corner then separates) and the others still push. j is the corner that
    // pulls hardest. Skipped where every lane takes the whole block or is idle (most of a resting
    // stack's).
    for (Pack<N>& dropped : s.dropped) dropped = zero;
    s.useDropped = zero;
    if (anyNegative(s.useBlock + s.idle - one)) {
        const Pack<N> impulses[4] = {c.point[0].normalImpulse, c.point[1].normalImpulse, c.point[2].normalImpulse,
                                     c.point[3].normalImpulse};
        dropCorner(c.normalBlockInverse, impulses, total, s.increment, s.useBlock, rigid, s.dropped, s.useDropped);
    }
    s.useBlock = s.useBlock * (one - s.idle);
    s.useDropped = s.useDropped * (one - s.idle);
    s.blockFails = one - s.useBlock - s.useDropped - s.idle;
}
// [ch11-normal-block-step]

/// The block's impulses onto the points and the bodies, in the lanes where it held.
template <int N>
inline void applyBlockStep(ManifoldBlock<N>& c, const BlockStep<N>& s, bool bounces, BodyPack<N>& a, BodyPack<N>& b) {
    const Pack<N> zero = Pack<N>::splat(0);
    Pack<N> pushed = zero;
    PackVec3<N> turnedA{zero, zero, zero}, turnedB{zero, zero, zero};
    for (int i = 0; i < 4; ++i) {
        ManifoldPointPack<N>& p = c.point[i];
        const Pack<N> impulse = s.increment[i] * s.useBlock + s.dropped[i] * s.useDropped;
        p.normalImpulse = p.normalImpulse + impulse;
        if (bounces) p.maxNormalImpulse = max(p.maxNormalImpulse, impulse);  // read by restitution only
        pushed = pushed + impulse;
        turnedA = turnedA + impulse * p.turnA;
        turnedB = turnedB + impulse * p.turnB;
    }
    a.linearVelocity = a.linearVelocity - (c.inverseMassA * pushed) * c.normal;
    a.angularVelocity = a.angularVelocity - turnedA;
    b.linearVelocity = b.linearVelocity + (c.inverseMassB * pushed) * c.normal;
    b.angularVelocity = b.angularVelocity + turnedB;
}

/// Where the block failed, the normal rows one at a time, swept forwards and backwards: a single
/// sweep in one order leaves the first corner pushing harder than the last, a torque that tilts a
/// tall stack; symmetric sweeps bring the corners to nearly the same answer. Only the lanes whose
/// block failed change (selectPositive on blockFails): a lane's answer must not depend on which
/// manifolds share its block, so that the scalar solve and wide solves of any width give the same bits.
template <int N>
inline void sweepNormalRows(ManifoldBlock<N>& c, const PointTargets<N>& t, const PackVec3<N> angularA[4],
                            const PackVec3<N> angularB[4], const Pack<N>& blockFails, bool bounces, BodyPack<N>& a,
                            BodyPack<N>& b) {
    for (int sweep = 0; sweep < kNormalSweeps; ++sweep) {
        for (int k = 0; k < 4; ++k) {
            const int i = sweep % 2 == 0 ? k : 3 - k;
            ManifoldPointPack<N>& p = c.point[i];
            const Pack<N> normalSpeed = normalRowSpeed(c, a, b, angularA[i], angularB[i]);
            const Pack<N> accumulated = normalRowImpulse(p, normalSpeed, t.bias[i], t.massScale[i], t.impulseScale[i]);
            const Pack<N> impulse = accumulated - p.normalImpulse;
            p.normalImpulse = selectPositive(blockFails, accumulated, p.normalImpulse);
            if (bounces)
                p.maxNormalImpulse = selectPositive(blockFails, max(p.maxNormalImpulse, impulse), p.maxNormalImpulse);
            a.linearVelocity = select(blockFails, a.linearVelocity - (c.inverseMassA * impulse) * c.normal, a.linearVelocity);
            a.angularVelocity = select(blockFails, a.angularVelocity - impulse * p.turnA, a.angularVelocity);
            b.linearVelocity = select(blockFails, b.linearVelocity + (c.inverseMassB * impulse) * c.normal, b.linearVelocity);
            b.angularVelocity = select(blockFails, b.angularVelocity + impulse * p.turnB, b.angularVelocity);
        }
    }
}

// [ch11-single-point]
/// A block whose every lane has one point (a ball, a capsule's end, a hull's corner on the
/// ground: most manifolds of a pile of round shapes) has one normal row a lane, and chapter 4's
/// row update is its exact answer: no block to invert, no corner to let go, no three empty rows
/// swept. The row is swept kNormalSweeps times, as a failed block's rows are, so that a soft point
/// (deeper than the slop) answers as in any block; for a rigid one the second sweep changes
/// nothing but round-off.
/// False, having pushed nothing, where the block holds no impulse and no lane asks for one.
/// `deep`: with `useBias`, whether a point lies deeper than the slop (anyPointDeep).
template <int N>
inline bool solveSinglePoint(ManifoldBlock<N>& c, const ContactSolveParams& params, bool useBias, BodyPack<N>& a,
                             BodyPack<N>& b, bool& deep) {
    ManifoldPointPack<N>& p = c.point[0];
    const Pack<N> separation = pointSeparation(p, separationFrame(c, a, b));
    deep = useBias && anyPointDeep(c, &separation, params, 1);
    Pack<N> bias, massScale, impulseScale;
    pointTarget(c, separation, params, useBias, bias, massScale, impulseScale);
    const PackVec3<N> angularA = cross(p.armA, c.normal), angularB = cross(p.armB, c.normal);
    const bool bounces = anyNegative(-c.restitution);
    for (int sweep = 0; sweep < kNormalSweeps; ++sweep) {
        const Pack<N> speed = normalRowSpeed(c, a, b, angularA, angularB);
        // A row that holds nothing and whose target is at least zero finds no impulse, in both
        // sweeps (the first changes no speed): where every lane is such, the block is skipped.
        if (sweep == 0 && !bounces &&
            !anyNegative(selectPositive(p.normalMass, speed + bias, Pack<N>::splat(0))) && holdsNoImpulse(c))
            return false;
        if (bounces && sweep == 0)  // as normalBlockStep keeps it, before the row moves
            keepApproachSpeed(p, separation, selectPositive(p.normalMass, speed + bias, Pack<N>::splat(0)), speed);
        const Pack<N> accumulated = normalRowImpulse(p, speed, bias, massScale, impulseScale);
        const Pack<N> impulse = accumulated - p.normalImpulse;
        p.normalImpulse = accumulated;
        if (bounces) p.maxNormalImpulse = max(p.maxNormalImpulse, impulse);
        a.linearVelocity = a.linearVelocity - (c.inverseMassA * impulse) * c.normal;
        a.angularVelocity = a.angularVelocity - impulse * p.turnA;
        b.linearVelocity = b.linearVelocity + (c.inverseMassB * impulse) * c.normal;
        b.angularVelocity = b.angularVelocity + impulse * p.turnB;
    }
    return true;
}
// [ch11-single-point]

// [ch11-solve-block]
/// One sweep over the block's points: the four normal rows as one block (or one at a time where
/// the block would pull, with position feedback when `useBias`), then friction against the normal
/// impulses just found. A block of single points takes solveSinglePointBlock instead.
/// Returns, with `useBias`, whether a point lies deeper than the slop (anyPointDeep).
template <int N>
inline bool solveBlock(ManifoldBlock<N>& c, SolverBodyState* states, const ContactSolveParams& params, bool useBias) {
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    PointTargets<N> targets;
    pointTargets(c, a, b, params, useBias, targets);
    const bool deep = useBias && anyPointDeep(c, targets.separations, params);
    PackVec3<N> angularA[4], angularB[4];
    normalAngulars(c, angularA, angularB);
    const bool bounces = anyNegative(-c.restitution);  // approachSpeed is read only where a lane bounces
    BlockStep<N> step;
    normalBlockStep(c, a, b, targets, angularA, angularB, bounces, step);
    // Every lane idle and nothing held: the block would push by zero (holdsNoImpulse).
    if (!bounces && !anyNegative(step.idle - Pack<N>::splat(1)) && holdsNoImpulse(c)) return deep;
    applyBlockStep(c, step, bounces, a, b);
    if (anyNegative(-step.blockFails)) sweepNormalRows(c, targets, angularA, angularB, step.blockFails, bounces, a, b);
    solveFriction(c, a, b);
    scatterVelocities(states, c.slotA, a);
    scatterVelocities(states, c.slotB, b);
    return deep;
}
// [ch11-solve-block]

/// solveBlock for a block of single points (ManifoldBlock::singlePoint).
template <int N>
inline bool solveSinglePointBlock(ManifoldBlock<N>& c, SolverBodyState* states, const ContactSolveParams& params,
                                  bool useBias) {
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    bool deep = false;
    if (!solveSinglePoint(c, params, useBias, a, b, deep)) return deep;
    solveFriction(c, a, b);
    scatterVelocities(states, c.slotA, a);
    scatterVelocities(states, c.slotB, b);
    return deep;
}

/// A sweep of any block: single points one row a lane, others as one block. Two kernels, not one
/// with a branch inside: the four-row kernel compiles as lean as without the other.
/// Returns, with `useBias`, whether a point lies deeper than the slop (anyPointDeep).
template <int N>
inline bool solveAnyBlock(ManifoldBlock<N>& c, SolverBodyState* states, const ContactSolveParams& params, bool useBias) {
    if (c.singlePoint) return solveSinglePointBlock(c, states, params, useBias);
    return solveBlock(c, states, params, useBias);
}
}  // namespace STEPWISE_ISA
}  // namespace stepwise
