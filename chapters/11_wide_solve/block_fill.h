#pragma once
// A block's fields from its lanes' contact records, once per frame: arms, the friction basis at
// the manifold's centre, each point's offsets, last frame's impulses carried into this frame's
// cone, and the rolling rows' mass.
#include "11_wide_solve/body_pack.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

/// The block's fields that fillLane's contact records give, computed for every lane at once from
/// what it gathered: the arms, the friction basis at the manifold's centre, each point's offsets,
/// and last frame's impulses carried into this frame's cone. The arithmetic is chapter 6's Eigen
/// formulas', in Eigen's order (so the fields are Eigen's to the bit), and a point past a contact's
/// count changes nothing
/// (selects, not products), so a lane comes out the same whatever lanes share its block.
template <int N>
inline void fillBlockFields(ManifoldBlock<N>& c, const LaneInputs<N>& in, Real carryScale, bool warm) {
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1), half = Pack<N>::splat(Real(0.5));
    const Pack<N> carry = Pack<N>::splat(carryScale);
    const PackVec3<N>& n = in.normal;
    const PackVec3<N> none{zero, zero, zero};
    // Eigen's order for a 3-vector's dot product: floats x + (y + z) (its unrolled reduction halves
    // the terms), doubles (x + y) + z (one SSE2 pair, then the third term).
    const auto eigenDot = [](const PackVec3<N>& a, const PackVec3<N>& b) {
        if constexpr (sizeof(Real) == 8) return (a.x * b.x + a.y * b.y) + a.z * b.z;
        else return a.x * b.x + (a.y * b.y + a.z * b.z);
    };
    const auto midpoint = [&](const typename LaneInputs<N>::Point& p) {
        return PackVec3<N>{half * (p.pointA.x + p.pointB.x), half * (p.pointA.y + p.pointB.y), half * (p.pointA.z + p.pointB.z)};
    };
    PackVec3<N> middle = none;
    // > 0 for each point a lane's contact has: its count less the point's index.
    const auto presence = [&](int i) { return in.pointCount - Pack<N>::splat(static_cast<Real>(i)); };
    for (int i = 0; i < 4; ++i) middle = select(presence(i), middle + midpoint(in.point[i]), middle);
    const Pack<N> count = max(one, in.pointCount);
    middle = {middle.x / count, middle.y / count, middle.z / count};
    // tangentBasis: anyPerpendicular(n), then n x t1.
    const Pack<N> tilted = max(n.x, -n.x) - Pack<N>::splat(Real(0.57735));  // >= 0: |n.x| >= 0.57735
    const PackVec3<N> helper{selectNonNegative(tilted, n.y, zero), selectNonNegative(tilted, -n.x, n.z),
                             selectNonNegative(tilted, zero, -n.y)};
    const Pack<N> squared = eigenDot(helper, helper);
    const Pack<N> length = sqrt(squared);
    const PackVec3<N> tangent1 = select(squared, PackVec3<N>{helper.x / length, helper.y / length, helper.z / length}, helper);
    const PackVec3<N> tangent2 = cross(n, tangent1);
    c.normal = n;
    c.tangent1 = tangent1;
    c.tangent2 = tangent2;
    c.centerArmA = middle - in.centerA;
    c.centerArmB = middle - in.centerB;

    Pack<N> carried1 = zero, carried2 = zero, carriedTwist = zero, carriedLoad = zero, carriedTwistLoad = zero;
    for (int i = 0; i < 4; ++i) {
        const auto& input = in.point[i];
        ManifoldPointPack<N>& p = c.point[i];
        const Pack<N> present = presence(i);
        const PackVec3<N> at = midpoint(input);
        const PackVec3<N> armA = (at - in.centerA) - in.roundA * n;
        const PackVec3<N> armB = (at - in.centerB) + in.roundB * n;
        p.armA = select(present, armA, none);
        p.armB = select(present, armB, none);
        p.adjustedSeparation = selectPositive(present, -input.depth - eigenDot(n, armB - armA), zero);
        p.normalMass = selectPositive(present, one, zero);  // prepareBlock puts the effective mass in its place
        p.maxNormalImpulse = zero;
        const PackVec3<N> fromMiddle = at - middle;
        const Pack<N> offset1 = eigenDot(tangent1, fromMiddle), offset2 = eigenDot(tangent2, fromMiddle);
        const Pack<N> radius = sqrt(offset1 * offset1 + offset2 * offset2);
        p.offset1 = selectPositive(present, offset1, zero);
        p.offset2 = selectPositive(present, offset2, zero);
        p.twistRadius = selectPositive(present, radius, zero);
        // Last frame's impulses: the points' friction summed into the centre's force and twist.
        const Pack<N> carriedNormal = selectPositive(input.normalImpulse, input.normalImpulse, zero) * carry;
        const Pack<N> carriedTangent1 = input.tangentImpulse1 * carry, carriedTangent2 = input.tangentImpulse2 * carry;
        carried1 = selectPositive(present, carried1 + carriedTangent1, carried1);
        carried2 = selectPositive(present, carried2 + carriedTangent2, carried2);
        carriedTwist = selectPositive(present, carriedTwist + (offset1 * carriedTangent2 - offset2 * carriedTangent1), carriedTwist);
        carriedLoad = selectPositive(present, carriedLoad + carriedNormal, carriedLoad);
        carriedTwistLoad = selectPositive(present, carriedTwistLoad + carriedNormal * radius, carriedTwistLoad);
        p.normalImpulse = warm ? selectPositive(present, carriedNormal, zero) : zero;
    }
    // ...kept inside this frame's friction cone and twist limit of the carried normal impulses.
    const Pack<N> limit = in.friction * carriedLoad, size = sqrt(carried1 * carried1 + carried2 * carried2);
    const Pack<N> shrink = selectPositive(size - limit, selectPositive(size, limit / size, zero), one);
    const Pack<N> twistLimit = in.friction * carriedTwistLoad;
    c.tangentImpulse1 = warm ? shrink * carried1 : zero;
    c.tangentImpulse2 = warm ? shrink * carried2 : zero;
    const Pack<N> clamped = selectPositive(-twistLimit - carriedTwist, -twistLimit,
                                           selectPositive(carriedTwist - twistLimit, twistLimit, carriedTwist));
    c.twistImpulse = warm ? clamped : zero;
}

/// The rolling rows' effective mass, the inverse of K = IA^-1 + IB^-1 (symmetric, by its
/// adjugate); zero in lanes without rolling resistance or without a body that turns.
template <int N>
inline void prepareRolling(ManifoldBlock<N>& c) {
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    const PackSym3<N>& ia = c.inverseInertiaA;
    const PackSym3<N>& ib = c.inverseInertiaB;
    const PackSym3<N> k{ia.xx + ib.xx, ia.yy + ib.yy, ia.zz + ib.zz, ia.xy + ib.xy, ia.xz + ib.xz, ia.yz + ib.yz};
    const PackSym3<N> adjugate{k.yy * k.zz - k.yz * k.yz, k.xx * k.zz - k.xz * k.xz, k.xx * k.yy - k.xy * k.xy,
                               k.xz * k.yz - k.xy * k.zz, k.xy * k.yz - k.xz * k.yy, k.xy * k.xz - k.xx * k.yz};
    const Pack<N> determinant = k.xx * adjugate.xx + k.xy * adjugate.xy + k.xz * adjugate.xz;
    const Pack<N> scale = selectPositive(min(determinant, c.rollingLength),
                                         one / max(determinant, Pack<N>::splat(Real(1e-30))), zero);
    c.rollingMass = {scale * adjugate.xx, scale * adjugate.yy, scale * adjugate.zz,
                     scale * adjugate.xy, scale * adjugate.xz, scale * adjugate.yz};
}
}  // namespace STEPWISE_ISA
}  // namespace stepwise
