#pragma once
// The shock sweep's kernels over chapter 11's blocks: the masses with the held body infinitely
// heavy, and the sweep's solve of one group's lanes (shock_sweep.h says why and when).
#include "11_wide_solve/contact_kernels.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

/// The same masses with the shock sweep's held body infinitely heavy (heldA, heldB): its inverse
/// mass and inertia taken as zero.
template <int N>
inline void prepareHeld(ManifoldBlock<N>& c) {
    const Pack<N> zero = Pack<N>::splat(0);
    const auto hold = [&](const PackSym3<N>& inertia, const Pack<N>& held) {
        return PackSym3<N>{selectPositive(held, zero, inertia.xx), selectPositive(held, zero, inertia.yy),
                           selectPositive(held, zero, inertia.zz), selectPositive(held, zero, inertia.xy),
                           selectPositive(held, zero, inertia.xz), selectPositive(held, zero, inertia.yz)};
    };
    const Pack<N> presence[4] = {c.point[0].normalMass, c.point[1].normalMass, c.point[2].normalMass, c.point[3].normalMass};
    rowMasses(c, selectPositive(c.heldA, zero, c.inverseMassA), selectPositive(c.heldB, zero, c.inverseMassB),
              hold(c.inverseInertiaA, c.heldA), hold(c.inverseInertiaB, c.heldB), presence, c.heldMasses);
}
// [ch12-shock-solve]
/// The shock sweep's relax sweep over the lanes of one of its groups (shockGroup == group): each
/// contact's held body read as at rest where it is now and never written (infinitely heavy: the
/// masses of prepareHeld), its other body relaxed against it, normal block first, then friction,
/// as solveBlock does. Lanes of other groups change nothing, nor does the block: the sweep starts
/// from the impulses the substeps accumulated, and what it adds is not carried to the next frame.
/// The held body's velocity stays zero, whatever the rows pushed it by.
template <int N>
inline void holdStill(const ManifoldBlock<N>& c, BodyPack<N>& a, BodyPack<N>& b) {
    const Pack<N> zero = Pack<N>::splat(0);
    const PackVec3<N> still{zero, zero, zero};
    a.linearVelocity = select(c.heldA, still, a.linearVelocity);
    a.angularVelocity = select(c.heldA, still, a.angularVelocity);
    b.linearVelocity = select(c.heldB, still, b.linearVelocity);
    b.angularVelocity = select(c.heldB, still, b.angularVelocity);
}

/// Friction at the centre against the loads the sweep found (solveFriction, with the held masses).
template <int N>
inline void heldFriction(const ManifoldBlock<N>& c, const Pack<N> impulse[4], BodyPack<N>& a, BodyPack<N>& b) {
    const RowMasses<N>& m = c.heldMasses;
    Pack<N> load = Pack<N>::splat(0), twistLoad = Pack<N>::splat(0);
    for (int k = 0; k < 4; ++k) {
        load = load + impulse[k];
        twistLoad = twistLoad + impulse[k] * c.point[k].twistRadius;
    }
    Pack<N> total1, total2;
    coneImpulses(c, a, b, load, m.tangentInverse11, m.tangentInverse12, m.tangentInverse22, total1, total2);
    applyFriction(c, total1 - c.tangentImpulse1, total2 - c.tangentImpulse2, a, b);
    holdStill(c, a, b);
    const Pack<N> twistLimit = c.friction * twistLoad;
    const Pack<N> spin = dot(c.normal, b.angularVelocity - a.angularVelocity);
    const Pack<N> twistChange = max(min(c.twistImpulse - m.twistMass * spin, twistLimit), -twistLimit) - c.twistImpulse;
    a.angularVelocity = a.angularVelocity - twistChange * c.twistTurnA;
    b.angularVelocity = b.angularVelocity + twistChange * c.twistTurnB;
    holdStill(c, a, b);
}

/// Only the moving body of each lane of the group is written (slot 0 never is).
template <int N>
inline void scatterSwept(const ManifoldBlock<N>& c, int group, SolverBodyState* states, const BodyPack<N>& a,
                         const BodyPack<N>& b) {
    int slotA[N], slotB[N];
    for (int lane = 0; lane < N; ++lane) {
        const bool swept = c.shockGroup[lane] == group;
        slotA[lane] = swept && !(c.heldA[lane] > 0) ? c.slotA[lane] : 0;
        slotB[lane] = swept && !(c.heldB[lane] > 0) ? c.slotB[lane] : 0;
    }
    scatterVelocities(states, slotA, a);
    scatterVelocities(states, slotB, b);
}

template <int N>
inline void solveHeldBlock(const ManifoldBlock<N>& c, SolverBodyState* states, const ContactSolveParams& params, int group) {
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    const PackVec3<N> still{zero, zero, zero};
    const RowMasses<N>& m = c.heldMasses;
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    const auto hold = [&] { holdStill(c, a, b); };
    hold();
    Pack<N> separations[4], bias[4], target[4], impulse[4], increment[4], total[4];
    PackVec3<N> angularA[4], angularB[4];
    normalAngulars(c, angularA, angularB);
    pointSeparations(c, a, b, separations);
    const Pack<N> inverseH = Pack<N>::splat(1 / params.substep);
    const Pack<N> approach = dot(c.normal, b.linearVelocity - a.linearVelocity);
    for (int k = 0; k < 4; ++k) {
        bias[k] = selectPositive(separations[k], separations[k] * inverseH, zero);  // relax: gaps only
        const Pack<N> speed = approach + dot(b.angularVelocity, angularB[k]) - dot(a.angularVelocity, angularA[k]) + bias[k];
        target[k] = selectPositive(m.normalMass[k], speed, zero);
        impulse[k] = c.point[k].normalImpulse;
    }
    Pack<N> leastLoad = zero;
    for (int i = 0; i < 4; ++i) {
        increment[i] = -(m.blockInverse[kBlockEntry[i][0]] * target[0] + m.blockInverse[kBlockEntry[i][1]] * target[1] +
                         m.blockInverse[kBlockEntry[i][2]] * target[2] + m.blockInverse[kBlockEntry[i][3]] * target[3]);
        total[i] = impulse[i] + increment[i];
        leastLoad = min(leastLoad, total[i]);
    }
    const Pack<N> useBlock = selectNonNegative(leastLoad, one, zero);
    Pack<N> dropped[4] = {zero, zero, zero, zero}, useDropped = zero;
    if (anyNegative(useBlock - one)) dropCorner(m.blockInverse, impulse, total, increment, useBlock, one, dropped, useDropped);
    const Pack<N> blockFails = one - useBlock - useDropped;
    Pack<N> pushed = zero;
    PackVec3<N> turnedA = still, turnedB = still;
    for (int i = 0; i < 4; ++i) {
        const Pack<N> change = increment[i] * useBlock + dropped[i] * useDropped;
        impulse[i] = impulse[i] + change;
        pushed = pushed + change;
        turnedA = turnedA + change * c.point[i].turnA;
        turnedB = turnedB + change * c.point[i].turnB;
    }
    a.linearVelocity = a.linearVelocity - (c.inverseMassA * pushed) * c.normal;
    a.angularVelocity = a.angularVelocity - turnedA;
    b.linearVelocity = b.linearVelocity + (c.inverseMassB * pushed) * c.normal;
    b.angularVelocity = b.angularVelocity + turnedB;
    hold();
    if (anyNegative(-blockFails)) {  // the rows one at a time, where the block fails (solveBlock)
        for (int sweep = 0; sweep < kNormalSweeps; ++sweep) {
            for (int k = 0; k < 4; ++k) {
                const int i = sweep % 2 == 0 ? k : 3 - k;
                const ManifoldPointPack<N>& p = c.point[i];
                const Pack<N> normalSpeed = dot(c.normal, b.linearVelocity - a.linearVelocity) +
                                            dot(b.angularVelocity, angularB[i]) - dot(a.angularVelocity, angularA[i]);
                const Pack<N> accumulated = max(impulse[i] - m.normalMass[i] * (normalSpeed + bias[i]), zero);
                const Pack<N> change = accumulated - impulse[i];
                impulse[i] = selectPositive(blockFails, accumulated, impulse[i]);
                a.linearVelocity = select(blockFails, a.linearVelocity - (c.inverseMassA * change) * c.normal, a.linearVelocity);
                a.angularVelocity = select(blockFails, a.angularVelocity - change * p.turnA, a.angularVelocity);
                b.linearVelocity = select(blockFails, b.linearVelocity + (c.inverseMassB * change) * c.normal, b.linearVelocity);
                b.angularVelocity = select(blockFails, b.angularVelocity + change * p.turnB, b.angularVelocity);
                hold();
            }
        }
    }

    heldFriction(c, impulse, a, b);
    scatterSwept(c, group, states, a, b);
}
// [ch12-shock-solve]
}  // namespace STEPWISE_ISA
}  // namespace stepwise
