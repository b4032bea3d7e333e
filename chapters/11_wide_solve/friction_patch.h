#pragma once
// Friction at the manifold's centre (the patch): two tangent rows clamped to the friction cone and
// a twist row, and rolling resistance.
#include "11_wide_solve/block_prepare.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

// [ch11-rolling]
/// Rolling resistance: the angular impulse that stops the bodies' relative turn, kept within a
/// ball of radius rollingLength times the load (Box2D v3 clamps its one rolling axis the same way;
/// in 3D the ball also holds back spinning about the normal, which a one-point contact's twist
/// row cannot: its points have no spread).
template <int N>
inline void solveRolling(ManifoldBlock<N>& c, const Pack<N>& load, BodyPack<N>& a, BodyPack<N>& b) {
    const Pack<N> one = Pack<N>::splat(1);
    PackVec3<N> total = c.rollingImpulse - c.rollingMass * (b.angularVelocity - a.angularVelocity);
    const Pack<N> limit = c.rollingLength * load;
    const Pack<N> lengthSquared = dot(total, total);
    // No load, no impulse: exactly, also where the length's square underflows.
    const Pack<N> scale =
        selectPositive(lengthSquared - limit * limit, limit / sqrt(max(lengthSquared, Pack<N>::splat(Real(1e-30)))), one);
    total = selectPositive(limit, scale, Pack<N>::splat(0)) * total;
    const PackVec3<N> change = total - c.rollingImpulse;
    c.rollingImpulse = total;
    a.angularVelocity = a.angularVelocity - c.inverseInertiaA * change;
    b.angularVelocity = b.angularVelocity + c.inverseInertiaB * change;
}
// [ch11-rolling]

// [ch11-friction]
/// The centre's two tangent impulses that stop its slide, as totals, clamped to the friction cone
/// (a circle of radius mu times the load), through the tangent block's inverse (the frame's, or
/// the shock sweep's held one).
template <int N>
inline void coneImpulses(const ManifoldBlock<N>& c, const BodyPack<N>& a, const BodyPack<N>& b, const Pack<N>& load,
                         const Pack<N>& inverse11, const Pack<N>& inverse12, const Pack<N>& inverse22, Pack<N>& total1,
                         Pack<N>& total2) {
    const PackVec3<N> apart = b.linearVelocity - a.linearVelocity;
    PackVec3<N> frictionA[2], frictionB[2];
    tangentAngulars(c, frictionA, frictionB);
    const Pack<N> slide1 = dot(c.tangent1, apart) + dot(b.angularVelocity, frictionB[0]) - dot(a.angularVelocity, frictionA[0]);
    const Pack<N> slide2 = dot(c.tangent2, apart) + dot(b.angularVelocity, frictionB[1]) - dot(a.angularVelocity, frictionA[1]);
    total1 = c.tangentImpulse1 - (inverse11 * slide1 + inverse12 * slide2);
    total2 = c.tangentImpulse2 - (inverse12 * slide1 + inverse22 * slide2);
    const Pack<N> limit = c.friction * load;
    const Pack<N> lengthSquared = total1 * total1 + total2 * total2;
    const Pack<N> clamped = selectPositive(lengthSquared - limit * limit,
                                           limit / sqrt(max(lengthSquared, Pack<N>::splat(Real(1e-30)))), Pack<N>::splat(1));
    // No load, no friction: exactly, also where the impulse's square underflows.
    const Pack<N> scale = selectPositive(limit, clamped, Pack<N>::splat(0));
    total1 = total1 * scale;
    total2 = total2 * scale;
}

/// The manifold's friction at its centre, against the normal impulses just found: the two
/// tangent rows as one 2x2 block clamped to the friction cone (a circle of radius mu sum(lambda)),
/// then the twist about the normal, clamped to mu sum(lambda r). Three rows where a row per point
/// and direction would be eight (PhysX's patch friction and Havok's manifold friction do the same).
template <int N>
inline void solveFriction(ManifoldBlock<N>& c, BodyPack<N>& a, BodyPack<N>& b) {
    const Pack<N> zero = Pack<N>::splat(0);
    Pack<N> load = zero, twistLoad = zero;
    for (const ManifoldPointPack<N>& p : c.point) {
        load = load + p.normalImpulse;
        twistLoad = twistLoad + p.normalImpulse * p.twistRadius;
    }
    Pack<N> total1, total2;
    coneImpulses(c, a, b, load, c.tangentInverse11, c.tangentInverse12, c.tangentInverse22, total1, total2);
    const Pack<N> change1 = total1 - c.tangentImpulse1, change2 = total2 - c.tangentImpulse2;
    c.tangentImpulse1 = total1;
    c.tangentImpulse2 = total2;
    applyFriction(c, change1, change2, a, b);

    const Pack<N> twistLimit = c.friction * twistLoad;
    const Pack<N> spin = dot(c.normal, b.angularVelocity - a.angularVelocity);
    const Pack<N> twist = max(min(c.twistImpulse - c.twistMass * spin, twistLimit), -twistLimit);
    const Pack<N> twistChange = twist - c.twistImpulse;
    c.twistImpulse = twist;
    a.angularVelocity = a.angularVelocity - twistChange * c.twistTurnA;
    b.angularVelocity = b.angularVelocity + twistChange * c.twistTurnB;
    if (anyNegative(-c.rollingLength)) solveRolling(c, load, a, b);
}
// [ch11-friction]
}  // namespace STEPWISE_ISA
}  // namespace stepwise
