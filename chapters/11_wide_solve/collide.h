#pragma once
// Collisions before contacts, and restitution at the frame's end.
#include "11_wide_solve/block_solve.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

/// A point's normal row as the bodies are turned now. The solve's rows keep the arms and the
/// inverse inertia of the frame's start, which is right while a body turns little in a frame; a
/// thin stick spinning about its length turns far, and a (1 + e) impulse through the start's
/// inverse inertia then turns it about what is now a heavy axis: energy from nowhere. Seen from
/// each body's start frame the row is exact and costs no new inertia: with R the turn since the
/// start, (R r) x n = R (r x R^T n) and the inverse inertia now is R I0^-1 R^T, so the row's lever
/// is r x (R^T n), its speed reads the spin turned back (R^T w), and its impulse turns the body
/// by I0^-1 times the lever, turned forwards once at the end.
template <int N>
struct TurnedRow {
    PackVec3<N> leverA, leverB, turnA, turnB;
    Pack<N> mass;  // 1 / (J M^-1 J^T) as the bodies are turned now; 0 for a missing point
};
template <int N>
inline TurnedRow<N> turnedRow(const ManifoldBlock<N>& c, const ManifoldPointPack<N>& p, const SeparationFrame<N>& f) {
    TurnedRow<N> row;
    row.leverA = cross(p.armA, f.normalSeenByA);
    row.leverB = cross(p.armB, f.normalSeenByB);
    row.turnA = c.inverseInertiaA * row.leverA;
    row.turnB = c.inverseInertiaB * row.leverB;
    const Pack<N> inverseMass = c.inverseMassA + c.inverseMassB + dot(row.leverA, row.turnA) + dot(row.leverB, row.turnB);
    row.mass = selectPositive(p.normalMass, Pack<N>::splat(1) / max(inverseMass, Pack<N>::splat(Real(1e-30))),
                              Pack<N>::splat(0));
    return row;
}

// [ch11-collide]
/// Guendelman, Bridson and Fedkiw's collisions before contacts ("Nonconvex rigid bodies with
/// stacking", SIGGRAPH 2003), in the substep where they happen: each point that approaches faster
/// than the restitution threshold, with restitution, pushed nothing in the last substep (a new
/// impact, not a resting point), and touches or closes within two substeps,
/// gets the impulse that reverses its normal speed times e, on the speeds as they are now, along
/// its row as the bodies are turned now (turnedRow: an impulse that reverses a speed times e <= 1
/// along the true row can only take energy away). Swept until nothing approaches, the impulses
/// travel down a row of touching balls one pair at a time, which the contact solve, spreading an
/// impact over every touching pair at once, cannot do (Newton's cradle). Returns whether any
/// point was struck.
template <int N>
inline bool collideBlock(ManifoldBlock<N>& c, SolverBodyState* states, const ContactSolveParams& params) {
    if (!anyNegative(-c.restitution)) return false;  // no lane bounces
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    const Pack<N> fastApproach = Pack<N>::splat(-params.restitutionThreshold);
    const Pack<N> h = Pack<N>::splat(params.substep);
    const Pack<N> margin = Pack<N>::splat(Real(1e-4));
    const SeparationFrame<N> frame = separationFrame(c, a, b);
    PackVec3<N> spinA = rotate(conjugate(a.deltaRotation), a.angularVelocity);
    PackVec3<N> spinB = rotate(conjugate(b.deltaRotation), b.angularVelocity);
    Pack<N> struck = zero;
    for (ManifoldPointPack<N>& p : c.point) {
        const Pack<N> separation = pointSeparation(p, frame);
        const TurnedRow<N> row = turnedRow(c, p, frame);
        const Pack<N> normalSpeed =
            dot(c.normal, b.linearVelocity - a.linearVelocity) + dot(spinB, row.leverB) - dot(spinA, row.leverA);
        // > 0 where all four hold: faster than the threshold, restitution, a real point, and one
        // that pushed nothing in the last substep. A point that pushed rests: its warm start is
        // about to hold it, and a collision struck there too pushes twice (a capsule spinning on
        // its end, its cap bobbing faster than the threshold, gained 44% of its energy that way).
        const Pack<N> idle = selectPositive(p.normalImpulse, zero, one);
        const Pack<N> fast = min(min(min(fastApproach - normalSpeed, c.restitution), p.normalMass), idle);
        // Touching, or closing within two substeps: the relax sweep of this substep looks one
        // substep ahead and would take part of the approach speed first (struck only when
        // touching, a head-on pair at 3.5 m/s with e = 1 parts at 2.5); 0.1 mm for the rounding
        // of a gap that closes exactly then. The price: a ball may bounce up to two substeps'
        // travel early, which puts the apex (1 - e^2) times that higher.
        const Pack<N> closes = margin - (separation + normalSpeed * (h + h));
        const Pack<N> mass = selectPositive(fast, selectNonNegative(closes, row.mass, zero), zero);
        const Pack<N> impulse = -((one + c.restitution) * mass * normalSpeed);
        a.linearVelocity = a.linearVelocity - (c.inverseMassA * impulse) * c.normal;
        b.linearVelocity = b.linearVelocity + (c.inverseMassB * impulse) * c.normal;
        spinA = spinA - impulse * row.turnA;
        spinB = spinB + impulse * row.turnB;
        // Its impact is spent: the restitution after the substeps must not reverse it again.
        p.approachSpeed = selectPositive(mass, zero, p.approachSpeed);
        struck = max(struck, mass);
    }
    if (!anyNegative(-struck)) return false;
    // Only struck lanes take the spin turned forwards: the others keep their bits.
    a.angularVelocity = select(struck, rotate(a.deltaRotation, spinA), a.angularVelocity);
    b.angularVelocity = select(struck, rotate(b.deltaRotation, spinB), b.angularVelocity);
    scatterVelocities(states, c.slotA, a);
    scatterVelocities(states, c.slotB, b);
    return true;
}
// [ch11-collide]

/// After the last substep (Box3D's order): a point with restitution that approached faster than
/// the threshold and pushed this frame gets its normal speed set to -e times the approach speed,
/// push only. Without restitution a point is left as the relax sweep left it (Box2D v3 skips it
/// too), so a scene without restitution has no pass to run. Its row is the solve's own (the
/// frame-start arms), not turnedRow: the approach speed it reverses was read along that row by the
/// sweeps, and a target read along one row and met along another can add energy (a 10 t box
/// spinning at 10.5 rad/s gained 193 kJ in one frame that way).
/// That row stands for the true one only while the bodies turn little in the solve's piece: a point
/// whose row a body's turn since the piece began misreads by more than the threshold (staleRowSpeed)
/// cannot tell a bounce from a rest, and gets no restitution here; collideBlock, along the rows
/// as turned, has struck it where it struck (a needle spinning half a turn a frame on a bouncy
/// floor took the stale row's 40 m/s for an approach and left at 39 m/s).
template <int N>
inline Pack<N> staleRowSpeed(const BodyPack<N>& a, const BodyPack<N>& b, const ManifoldPointPack<N>& p) {
    const PackVec3<N> movedA = rotate(a.deltaRotation, p.armA) - p.armA;  // the arm's tip since the piece began
    const PackVec3<N> movedB = rotate(b.deltaRotation, p.armB) - p.armB;
    return sqrt(dot(a.angularVelocity, a.angularVelocity) * dot(movedA, movedA)) +
           sqrt(dot(b.angularVelocity, b.angularVelocity) * dot(movedB, movedB));
}
template <int N>
inline void restitutionBlock(ManifoldBlock<N>& c, SolverBodyState* states, Real threshold) {
    if (!anyNegative(-c.restitution)) return;  // no lane bounces
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    const Pack<N> zero = Pack<N>::splat(0);
    const Pack<N> fastApproach = Pack<N>::splat(-threshold);
    for (ManifoldPointPack<N>& p : c.point) {
        // Lanes where the rule does not apply get a zero mass, so a zero impulse.
        const Pack<N> trusted = Pack<N>::splat(threshold) - staleRowSpeed(a, b, p);  // >= 0: the row reads true
        const Pack<N> applies = selectNonNegative(
            trusted,
            selectPositive(c.restitution, selectPositive(fastApproach - p.approachSpeed, p.maxNormalImpulse, zero), zero),
            zero);
        const Pack<N> mass = selectPositive(applies, p.normalMass, zero);
        const Pack<N> normalSpeed = dot(c.normal, relativeVelocity(a, b, p.armA, p.armB));
        Pack<N> impulse = -(mass * (normalSpeed + c.restitution * p.approachSpeed));
        const Pack<N> accumulated = max(p.normalImpulse + impulse, zero);
        impulse = accumulated - p.normalImpulse;
        p.normalImpulse = accumulated;
        applyImpulse(c, p.armA, p.armB, impulse * c.normal, a, b);
    }
    scatterVelocities(states, c.slotA, a);
    scatterVelocities(states, c.slotB, b);
}
}  // namespace STEPWISE_ISA
}  // namespace stepwise
