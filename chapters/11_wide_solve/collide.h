#pragma once
// Collisions before contacts, and restitution at the frame's end.
#include "11_wide_solve/block_solve.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

// [ch11-collide]
/// Guendelman, Bridson and Fedkiw's collisions before contacts ("Nonconvex rigid bodies with
/// stacking", SIGGRAPH 2003), in the substep where they happen: each point that approaches faster
/// than the restitution threshold, with restitution, and touches or closes within two substeps,
/// gets the impulse that reverses its normal speed times e, on the speeds as they are now. Swept
/// until nothing approaches, the impulses travel down a row of touching balls one pair at a time,
/// which the contact solve, spreading an impact over every touching pair at once, cannot do
/// (Newton's cradle). Returns whether any point was struck.
template <int N>
inline bool collideBlock(ManifoldBlock<N>& c, SolverBodyState* states, const ContactSolveParams& params) {
    if (!anyNegative(-c.restitution)) return false;  // no lane bounces
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    const Pack<N> fastApproach = Pack<N>::splat(-params.restitutionThreshold);
    const Pack<N> h = Pack<N>::splat(params.substep);
    const Pack<N> margin = Pack<N>::splat(Real(1e-4));
    Pack<N> separations[4];
    pointSeparations(c, a, b, separations);
    Pack<N> struck = zero;
    for (int k = 0; k < 4; ++k) {
        ManifoldPointPack<N>& p = c.point[k];
        const Pack<N> separation = separations[k];
        const Pack<N> normalSpeed = dot(c.normal, relativeVelocity(a, b, p.armA, p.armB));
        // > 0 where all three hold: faster than the threshold, restitution, a real point.
        const Pack<N> fast = min(min(fastApproach - normalSpeed, c.restitution), p.normalMass);
        // Touching, or closing within two substeps: the relax sweep of this substep looks one
        // substep ahead and would take part of the approach speed first (struck only when
        // touching, a head-on pair at 3.5 m/s with e = 1 parts at 2.5); 0.1 mm for the rounding
        // of a gap that closes exactly then. The price: a ball may bounce up to two substeps'
        // travel early, which puts the apex (1 - e^2) times that higher.
        const Pack<N> closes = margin - (separation + normalSpeed * (h + h));
        const Pack<N> mass = selectPositive(fast, selectNonNegative(closes, p.normalMass, zero), zero);
        const Pack<N> impulse = -((one + c.restitution) * mass * normalSpeed);
        applyImpulse(c, p.armA, p.armB, impulse * c.normal, a, b);
        // Its impact is spent: the restitution after the substeps must not reverse it again.
        p.approachSpeed = selectPositive(mass, zero, p.approachSpeed);
        struck = max(struck, mass);
    }
    scatterVelocities(states, c.slotA, a);
    scatterVelocities(states, c.slotB, b);
    return anyNegative(-struck);
}
// [ch11-collide]

/// After the last substep (Box3D's order): a point with restitution that approached faster than
/// the threshold and pushed this frame gets its normal speed set to -e times the approach speed,
/// push only. Without restitution a point is left as the relax sweep left it (Box2D v3 skips it
/// too), so a scene without restitution has no pass to run.
template <int N>
inline void restitutionBlock(ManifoldBlock<N>& c, SolverBodyState* states, Real threshold) {
    if (!anyNegative(-c.restitution)) return;  // no lane bounces
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    const Pack<N> zero = Pack<N>::splat(0);
    const Pack<N> fastApproach = Pack<N>::splat(-threshold);
    for (ManifoldPointPack<N>& p : c.point) {
        // Lanes where the rule does not apply get a zero mass, so a zero impulse.
        const Pack<N> applies =
            selectPositive(c.restitution, selectPositive(fastApproach - p.approachSpeed, p.maxNormalImpulse, zero), zero);
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
