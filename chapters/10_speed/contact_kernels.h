#pragma once
// The contact solve written once for any lane count (lanes.h): warm start, one Gauss-Seidel
// sweep with or without position feedback, and restitution, over a ManifoldBlock. The scalar
// solver runs it with N = 1 in contact order; the wide solver with N = kWideLanes over the
// colours. The arithmetic is the same, so the two agree to the Gauss-Seidel ordering.

#include "01_integrators/rotation.h"
#include "10_speed/solver_data.h"

#include <algorithm>

namespace stepwise {

// [ch10-body-pack]
/// Both bodies of every lane, gathered from the states array (the one place that reads it).
template <int N>
struct BodyPack {
    PackVec3<N> linearVelocity, angularVelocity, deltaPosition;
    PackQuat<N> deltaRotation;
};

template <int N>
inline BodyPack<N> gatherBodies(const SolverBodyState* states, const int* slots) {
    BodyPack<N> body;
    for (int i = 0; i < N; ++i) {
        const SolverBodyState& s = states[slots[i]];
        body.linearVelocity.x[i] = s.linearVelocity[0];
        body.linearVelocity.y[i] = s.linearVelocity[1];
        body.linearVelocity.z[i] = s.linearVelocity[2];
        body.angularVelocity.x[i] = s.angularVelocity[0];
        body.angularVelocity.y[i] = s.angularVelocity[1];
        body.angularVelocity.z[i] = s.angularVelocity[2];
        body.deltaPosition.x[i] = s.deltaPosition[0];
        body.deltaPosition.y[i] = s.deltaPosition[1];
        body.deltaPosition.z[i] = s.deltaPosition[2];
        body.deltaRotation.x[i] = s.deltaRotation[0];
        body.deltaRotation.y[i] = s.deltaRotation[1];
        body.deltaRotation.z[i] = s.deltaRotation[2];
        body.deltaRotation.w[i] = s.deltaRotation[3];
    }
    return body;
}

/// Writes the velocities back. Slot 0 (statics, sleepers, empty lanes) is never written: its
/// lanes computed a zero change (zero inverse mass), and several lanes may share it.
template <int N>
inline void scatterVelocities(SolverBodyState* states, const int* slots, const BodyPack<N>& body) {
    for (int i = 0; i < N; ++i) {
        if (slots[i] == 0) continue;
        SolverBodyState& s = states[slots[i]];
        s.linearVelocity[0] = body.linearVelocity.x[i];
        s.linearVelocity[1] = body.linearVelocity.y[i];
        s.linearVelocity[2] = body.linearVelocity.z[i];
        s.angularVelocity[0] = body.angularVelocity.x[i];
        s.angularVelocity[1] = body.angularVelocity.y[i];
        s.angularVelocity[2] = body.angularVelocity.z[i];
    }
}

/// Writes every field back (the integration's scatter); slot 0 is skipped as above.
template <int N>
inline void scatterBodies(SolverBodyState* states, const int* slots, const BodyPack<N>& body) {
    scatterVelocities(states, slots, body);
    for (int i = 0; i < N; ++i) {
        if (slots[i] == 0) continue;
        SolverBodyState& s = states[slots[i]];
        s.deltaPosition[0] = body.deltaPosition.x[i];
        s.deltaPosition[1] = body.deltaPosition.y[i];
        s.deltaPosition[2] = body.deltaPosition.z[i];
        s.deltaRotation[0] = body.deltaRotation.x[i];
        s.deltaRotation[1] = body.deltaRotation.y[i];
        s.deltaRotation[2] = body.deltaRotation.z[i];
        s.deltaRotation[3] = body.deltaRotation.w[i];
    }
}
// [ch10-body-pack]

#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE)
// [ch10-avx2-gather]
// The AVX2 float build gathers eight bodies with two loads each and an 8x8 transpose (rows: lanes'
// states; columns: fields), the way Box3D gathers its bodies, instead of 8 x 13 scalar loads.
inline void transpose8(__m256 (&row)[8]) {
    const __m256 t0 = _mm256_unpacklo_ps(row[0], row[1]), t1 = _mm256_unpackhi_ps(row[0], row[1]);
    const __m256 t2 = _mm256_unpacklo_ps(row[2], row[3]), t3 = _mm256_unpackhi_ps(row[2], row[3]);
    const __m256 t4 = _mm256_unpacklo_ps(row[4], row[5]), t5 = _mm256_unpackhi_ps(row[4], row[5]);
    const __m256 t6 = _mm256_unpacklo_ps(row[6], row[7]), t7 = _mm256_unpackhi_ps(row[6], row[7]);
    const __m256 u0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)), u1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 u2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)), u3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 u4 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(1, 0, 1, 0)), u5 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 u6 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(1, 0, 1, 0)), u7 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(3, 2, 3, 2));
    row[0] = _mm256_permute2f128_ps(u0, u4, 0x20);
    row[1] = _mm256_permute2f128_ps(u1, u5, 0x20);
    row[2] = _mm256_permute2f128_ps(u2, u6, 0x20);
    row[3] = _mm256_permute2f128_ps(u3, u7, 0x20);
    row[4] = _mm256_permute2f128_ps(u0, u4, 0x31);
    row[5] = _mm256_permute2f128_ps(u1, u5, 0x31);
    row[6] = _mm256_permute2f128_ps(u2, u6, 0x31);
    row[7] = _mm256_permute2f128_ps(u3, u7, 0x31);
}

/// Lanes [first, first + 8) of `body` from eight states.
template <int N>
inline void gatherEight(const SolverBodyState* states, const int* slots, int first, BodyPack<N>& body) {
    static_assert(sizeof(SolverBodyState) == 16 * sizeof(float), "two 8-float rows per body");
    __m256 low[8], high[8];
    for (int i = 0; i < 8; ++i) {
        const float* state = reinterpret_cast<const float*>(&states[slots[first + i]]);
        low[i] = _mm256_load_ps(state);        // v.xyz w.xyz dp.xy
        high[i] = _mm256_load_ps(state + 8);   // dp.z dq.xyzw (3 unused)
    }
    transpose8(low);
    transpose8(high);
    Pack<N>* fields[13] = {&body.linearVelocity.x,  &body.linearVelocity.y,  &body.linearVelocity.z,
                           &body.angularVelocity.x, &body.angularVelocity.y, &body.angularVelocity.z,
                           &body.deltaPosition.x,   &body.deltaPosition.y,   &body.deltaPosition.z,
                           &body.deltaRotation.x,   &body.deltaRotation.y,   &body.deltaRotation.z,
                           &body.deltaRotation.w};
    for (int k = 0; k < 8; ++k) _mm256_store_ps(fields[k]->data() + first, low[k]);
    for (int k = 0; k < 5; ++k) _mm256_store_ps(fields[8 + k]->data() + first, high[k]);
}

template <int N>
inline void scatterEight(SolverBodyState* states, const int* slots, int first, const BodyPack<N>& body) {
    __m256 row[8] = {_mm256_load_ps(body.linearVelocity.x.data() + first),  _mm256_load_ps(body.linearVelocity.y.data() + first),
                     _mm256_load_ps(body.linearVelocity.z.data() + first),  _mm256_load_ps(body.angularVelocity.x.data() + first),
                     _mm256_load_ps(body.angularVelocity.y.data() + first), _mm256_load_ps(body.angularVelocity.z.data() + first),
                     _mm256_load_ps(body.deltaPosition.x.data() + first),   _mm256_load_ps(body.deltaPosition.y.data() + first)};
    transpose8(row);  // back to one row per lane; the delta position goes back as it was read
    for (int i = 0; i < 8; ++i)
        if (slots[first + i] != 0) _mm256_store_ps(reinterpret_cast<float*>(&states[slots[first + i]]), row[i]);
}

/// Every field of lanes [first, first + 8) back to their states (the integration's scatter).
template <int N>
inline void scatterAllEight(SolverBodyState* states, const int* slots, int first, const BodyPack<N>& body) {
    const __m256 zero = _mm256_setzero_ps();
    const auto lanes = [first](const Pack<N>& field) { return _mm256_load_ps(field.data() + first); };
    __m256 low[8] = {lanes(body.linearVelocity.x),  lanes(body.linearVelocity.y),  lanes(body.linearVelocity.z),
                     lanes(body.angularVelocity.x), lanes(body.angularVelocity.y), lanes(body.angularVelocity.z),
                     lanes(body.deltaPosition.x),   lanes(body.deltaPosition.y)};
    __m256 high[8] = {lanes(body.deltaPosition.z), lanes(body.deltaRotation.x), lanes(body.deltaRotation.y),
                      lanes(body.deltaRotation.z), lanes(body.deltaRotation.w), zero, zero, zero};
    transpose8(low);
    transpose8(high);
    for (int i = 0; i < 8; ++i) {
        if (slots[first + i] == 0) continue;
        float* state = reinterpret_cast<float*>(&states[slots[first + i]]);  // the 16 floats of one cache line
        _mm256_store_ps(state, low[i]);
        _mm256_store_ps(state + 8, high[i]);
    }
}

template <>
inline void scatterBodies<8>(SolverBodyState* states, const int* slots, const BodyPack<8>& body) {
    scatterAllEight(states, slots, 0, body);
}

template <>
inline BodyPack<8> gatherBodies<8>(const SolverBodyState* states, const int* slots) {
    BodyPack<8> body;
    gatherEight(states, slots, 0, body);
    return body;
}
template <>
inline void scatterVelocities<8>(SolverBodyState* states, const int* slots, const BodyPack<8>& body) {
    scatterEight(states, slots, 0, body);
}
// [ch10-avx2-gather]

// The AVX-512 build's sixteen lanes: two rows of eight each way.
template <>
inline BodyPack<16> gatherBodies<16>(const SolverBodyState* states, const int* slots) {
    BodyPack<16> body;
    gatherEight(states, slots, 0, body);
    gatherEight(states, slots, 8, body);
    return body;
}
template <>
inline void scatterVelocities<16>(SolverBodyState* states, const int* slots, const BodyPack<16>& body) {
    scatterEight(states, slots, 0, body);
    scatterEight(states, slots, 8, body);
}
template <>
inline void scatterBodies<16>(SolverBodyState* states, const int* slots, const BodyPack<16>& body) {
    scatterAllEight(states, slots, 0, body);
    scatterAllEight(states, slots, 8, body);
}
#endif

/// v += m^-1 P and w += I^-1 (arm x P) on B, the opposite on A.
template <int N>
inline void applyImpulse(const ManifoldBlock<N>& c, const PackVec3<N>& armA, const PackVec3<N>& armB,
                         const PackVec3<N>& impulse, BodyPack<N>& a, BodyPack<N>& b) {
    a.linearVelocity = a.linearVelocity - c.inverseMassA * impulse;
    a.angularVelocity = a.angularVelocity - c.inverseInertiaA * cross(armA, impulse);
    b.linearVelocity = b.linearVelocity + c.inverseMassB * impulse;
    b.angularVelocity = b.angularVelocity + c.inverseInertiaB * cross(armB, impulse);
}

/// Velocity of B's material point minus A's, at the arms.
template <int N>
inline PackVec3<N> relativeVelocity(const BodyPack<N>& a, const BodyPack<N>& b, const PackVec3<N>& armA,
                                    const PackVec3<N>& armB) {
    return (b.linearVelocity + cross(b.angularVelocity, armB)) - (a.linearVelocity + cross(a.angularVelocity, armA));
}

// [ch10-integrate-positions]
/// Chapter 1's position step for N bodies at once: the centre moves by h v, the rotation since
/// the frame began turns by h |w| about w (turnRotation, the same series on every lane; a lane
/// spinning too fast for the series takes chapter 1's own step).
template <int N>
inline void integratePositionsPack(SolverBodyState* states, const int* slots, Real h) {
    BodyPack<N> body = gatherBodies<N>(states, slots);
    const Pack<N> step = Pack<N>::splat(h), half = Pack<N>::splat(Real(0.5));
    body.deltaPosition = body.deltaPosition + step * body.linearVelocity;
    PackQuat<N>& q = body.deltaRotation;
    const PackVec3<N>& w = body.angularVelocity;
    const Pack<N> halfStep = half * step;
    const Pack<N> y = halfStep * halfStep * dot(w, w);
    bool seriesHolds = true;
    for (int lane = 0; lane < N; ++lane) seriesHolds &= y[lane] <= kTurnSeriesLimit;
    const PackQuat<N> start = q;  // a lane too fast for the series turns from here (below)
    Pack<N> cosine, sineRatio;
    turnSeries(y, [](Real value) { return Pack<N>::splat(value); }, cosine, sineRatio);
    // 1/2 (0, w) q, as quaternionDerivative.
    const PackVec3<N> turning = half * (q.w * w + cross(w, PackVec3<N>{q.x, q.y, q.z}));
    const Pack<N> turningW = half * -dot(w, PackVec3<N>{q.x, q.y, q.z});
    const Pack<N> along = step * sineRatio;
    q.x = cosine * q.x + along * turning.x;
    q.y = cosine * q.y + along * turning.y;
    q.z = cosine * q.z + along * turning.z;
    q.w = cosine * q.w + along * turningW;
    q = normalized(q);
    for (int lane = 0; !seriesHolds && lane < N; ++lane) {
        if (y[lane] <= kTurnSeriesLimit) continue;
        const Quat turned = turnRotation(Quat(start.w[lane], start.x[lane], start.y[lane], start.z[lane]),
                                         Vec3(w.x[lane], w.y[lane], w.z[lane]), h);
        q.x[lane] = turned.x(), q.y[lane] = turned.y(), q.z[lane] = turned.z(), q.w[lane] = turned.w();
    }
    scatterBodies(states, slots, body);
}
// [ch10-integrate-positions]

/// The centre's tangent impulses on both bodies, through the angular parts prepareBlock computed.
template <int N>
inline void applyFriction(const ManifoldBlock<N>& c, const Pack<N>& impulse1, const Pack<N>& impulse2, BodyPack<N>& a,
                          BodyPack<N>& b) {
    const PackVec3<N> impulse = impulse1 * c.tangent1 + impulse2 * c.tangent2;
    a.linearVelocity = a.linearVelocity - c.inverseMassA * impulse;
    b.linearVelocity = b.linearVelocity + c.inverseMassB * impulse;
    a.angularVelocity = a.angularVelocity - (impulse1 * c.frictionTurnA[0] + impulse2 * c.frictionTurnA[1]);
    b.angularVelocity = b.angularVelocity + (impulse1 * c.frictionTurnB[0] + impulse2 * c.frictionTurnB[1]);
}

// [ch10-warm-start]
/// Pushes the bodies by the impulses the manifold carries (from last frame, then from each
/// substep): every substep starts from the whole accumulated impulse, as Box3D does. The normal
/// impulses all point along n, so their turning adds up as one cross product:
/// sum(lambda_i r_i x n) = (sum(lambda_i r_i)) x n.
template <int N>
inline void warmStartBlock(const ManifoldBlock<N>& c, SolverBodyState* states) {
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
// [ch10-warm-start]

// [ch10-fill-block]
/// The block's fields that fillLane's contact records give, computed for every lane at once from
/// what it gathered: the arms, the friction basis at the manifold's centre, each point's offsets,
/// and last frame's impulses carried into this frame's cone. The arithmetic is chapter 6's Eigen
/// formulas', in Eigen's order (the golden hashes did not change), and a point past a contact's
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
// [ch10-fill-block]

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

// [ch10-row-angulars]
/// The angular parts of the rows, arm x direction: each point's normal row (the arm reaches the
/// point) and the centre's two tangent rows (the centre's arm). Computed where they are read, not
/// kept in the block: a few cross products cost less than the 36 cache lines they took in a block
/// of sixteen lanes, read from memory by every sweep of a scene too large for the cache.
template <int N>
inline void normalAngulars(const ManifoldBlock<N>& c, PackVec3<N> angularA[4], PackVec3<N> angularB[4]) {
    for (int k = 0; k < 4; ++k) {
        angularA[k] = cross(c.point[k].armA, c.normal);
        angularB[k] = cross(c.point[k].armB, c.normal);
    }
}
template <int N>
inline void tangentAngulars(const ManifoldBlock<N>& c, PackVec3<N> angularA[2], PackVec3<N> angularB[2]) {
    for (int k = 0; k < 2; ++k) {
        const PackVec3<N>& tangent = k == 0 ? c.tangent1 : c.tangent2;
        angularA[k] = cross(c.centerArmA, tangent);
        angularB[k] = cross(c.centerArmB, tangent);
    }
}
// [ch10-row-angulars]

// [ch10-normal-block]
/// The rows' effective masses for bodies of the given inverse masses and inertias (the frame's, or
/// the shock sweep's with its held body's zeroed), from the angular parts prepareBlock computed.
/// The normal block is the inverse of the four normal rows' effective-mass matrix,
/// K_ij = mA + mB + (rA_i x n) . IA^-1 (rA_j x n) + (rB_i x n) . IB^-1 (rB_j x n), with a missing
/// point's row and column those of the identity; Gauss-Jordan without pivoting, since
/// K + eps diag K is symmetric positive definite. `presence`: > 0 where the point exists.
template <int N>
inline void rowMasses(const ManifoldBlock<N>& c, const Pack<N>& inverseMassA, const Pack<N>& inverseMassB,
                      const PackSym3<N>& inverseInertiaA, const PackSym3<N>& inverseInertiaB, const Pack<N> presence[4],
                      RowMasses<N>& out) {
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    const Pack<N> linearInverse = inverseMassA + inverseMassB;
    PackVec3<N> angularA[4], angularB[4], turnA[4], turnB[4];
    normalAngulars(c, angularA, angularB);
    for (int k = 0; k < 4; ++k) {
        turnA[k] = inverseInertiaA * angularA[k];
        turnB[k] = inverseInertiaB * angularB[k];
    }
    Pack<N> matrix[4][4], inverse[4][4];
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const Pack<N> coupling = linearInverse + dot(angularA[i], turnA[j]) + dot(angularB[i], turnB[j]);
            const Pack<N> identity = i == j ? one : zero;
            const Pack<N> present = min(presence[i], presence[j]);  // > 0: both points exist
            matrix[i][j] = selectPositive(present, coupling, identity);
            inverse[i][j] = identity;
        }
        out.normalMass[i] = selectPositive(presence[i], one / matrix[i][i], zero);
        matrix[i][i] = matrix[i][i] * Pack<N>::splat(1 + kNormalBlockRegularisation);
    }
    for (int column = 0; column < 4; ++column) {
        const Pack<N> scale = one / matrix[column][column];
        for (int j = 0; j < 4; ++j) {
            matrix[column][j] = matrix[column][j] * scale;
            inverse[column][j] = inverse[column][j] * scale;
        }
        for (int row = 0; row < 4; ++row) {
            if (row == column) continue;
            const Pack<N> factor = matrix[row][column];
            for (int j = 0; j < 4; ++j) {
                matrix[row][j] = matrix[row][j] - factor * matrix[column][j];
                inverse[row][j] = inverse[row][j] - factor * inverse[column][j];
            }
        }
    }
    int entry = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i; j < 4; ++j) out.blockInverse[entry++] = inverse[i][j];

    // The centre's two tangent rows (t1 . t2 = 0, so the linear parts do not couple) and the twist.
    PackVec3<N> frictionA[2], frictionB[2];
    tangentAngulars(c, frictionA, frictionB);
    const PackVec3<N>& tangentA1 = frictionA[0];
    const PackVec3<N>& tangentA2 = frictionA[1];
    const PackVec3<N>& tangentB1 = frictionB[0];
    const PackVec3<N>& tangentB2 = frictionB[1];
    const PackVec3<N> turnA1 = inverseInertiaA * tangentA1, turnA2 = inverseInertiaA * tangentA2;
    const PackVec3<N> turnB1 = inverseInertiaB * tangentB1, turnB2 = inverseInertiaB * tangentB2;
    const Pack<N> k11 = linearInverse + dot(tangentA1, turnA1) + dot(tangentB1, turnB1);
    const Pack<N> k22 = linearInverse + dot(tangentA2, turnA2) + dot(tangentB2, turnB2);
    const Pack<N> k12 = dot(tangentA1, turnA2) + dot(tangentB1, turnB2);
    const Pack<N> determinant = k11 * k22 - k12 * k12;
    // A lane without a moving body (empty) has K = 0: no friction there.
    const Pack<N> safe = selectPositive(determinant - Pack<N>::splat(Real(1e-12)) * max(one, k11 * k22), determinant, zero);
    const Pack<N> inverseDeterminant = selectPositive(safe, one / max(safe, Pack<N>::splat(Real(1e-30))), zero);
    out.tangentInverse11 = k22 * inverseDeterminant;
    out.tangentInverse12 = -k12 * inverseDeterminant;
    out.tangentInverse22 = k11 * inverseDeterminant;
    const Pack<N> twistInverse = dot(c.normal, inverseInertiaA * c.normal) + dot(c.normal, inverseInertiaB * c.normal);
    out.twistMass = selectPositive(twistInverse, one / max(twistInverse, Pack<N>::splat(Real(1e-30))), zero);
}
// [ch10-normal-block]

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

/// Once per frame, after fillLane: everything about the rows that depends only on the frame's
/// start, for all lanes at once. fillLane marks each point that exists with normalMass = 1; here
/// it becomes the row's effective mass (rowMasses). `held`: the frame ends with the shock sweep,
/// which solves the lanes it takes with one body held still (prepareHeld).
template <int N>
inline void prepareBlock(ManifoldBlock<N>& c, const SolverBodyState* states, bool held = false) {
    const Pack<N> zero = Pack<N>::splat(0);
    const bool bounces = anyNegative(-c.restitution);  // approachSpeed is read only where a lane bounces
    PackVec3<N> angularA[4], angularB[4];
    normalAngulars(c, angularA, angularB);
    for (int k = 0; k < 4; ++k) {
        c.point[k].turnA = c.inverseInertiaA * angularA[k];
        c.point[k].turnB = c.inverseInertiaB * angularB[k];
    }
    if (bounces) {
        const BodyPack<N> a = gatherBodies<N>(states, c.slotA);
        const BodyPack<N> b = gatherBodies<N>(states, c.slotB);
        for (ManifoldPointPack<N>& p : c.point)
            p.approachSpeed = selectPositive(p.normalMass, dot(c.normal, relativeVelocity(a, b, p.armA, p.armB)), zero);
    } else {
        for (ManifoldPointPack<N>& p : c.point) p.approachSpeed = zero;
    }
    PackVec3<N> frictionA[2], frictionB[2];
    tangentAngulars(c, frictionA, frictionB);
    for (int k = 0; k < 2; ++k) {
        c.frictionTurnA[k] = c.inverseInertiaA * frictionA[k];
        c.frictionTurnB[k] = c.inverseInertiaB * frictionB[k];
    }
    c.twistTurnA = c.inverseInertiaA * c.normal;
    c.twistTurnB = c.inverseInertiaB * c.normal;
    const Pack<N> presence[4] = {c.point[0].normalMass, c.point[1].normalMass, c.point[2].normalMass, c.point[3].normalMass};
    RowMasses<N> masses;
    rowMasses(c, c.inverseMassA, c.inverseMassB, c.inverseInertiaA, c.inverseInertiaB, presence, masses);
    for (int k = 0; k < 4; ++k) c.point[k].normalMass = masses.normalMass[k];
    for (int entry = 0; entry < 10; ++entry) c.normalBlockInverse[entry] = masses.blockInverse[entry];
    c.tangentInverse11 = masses.tangentInverse11;
    c.tangentInverse12 = masses.tangentInverse12;
    c.tangentInverse22 = masses.tangentInverse22;
    c.twistMass = masses.twistMass;
    if (anyNegative(-c.rollingLength)) prepareRolling(c);
    if (held && std::any_of(c.shockGroup, c.shockGroup + N, [](int group) { return group > 0; })) prepareHeld(c);
}

// [ch10-rolling]
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
    total = selectPositive(lengthSquared - limit * limit, limit / sqrt(max(lengthSquared, Pack<N>::splat(Real(1e-30)))), one) *
            total;
    const PackVec3<N> change = total - c.rollingImpulse;
    c.rollingImpulse = total;
    a.angularVelocity = a.angularVelocity - c.inverseInertiaA * change;
    b.angularVelocity = b.angularVelocity + c.inverseInertiaB * change;
}
// [ch10-rolling]

// [ch10-friction]
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
    const Pack<N> scale = selectPositive(lengthSquared - limit * limit,
                                         limit / sqrt(max(lengthSquared, Pack<N>::splat(Real(1e-30)))), Pack<N>::splat(1));
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
// [ch10-friction]

/// Each point's separation from where its two material points are now: the separation found at
/// the frame's start plus how far the bodies have moved and turned since (adjustedSeparation holds
/// the start's normal . (armB - armA) taken out, so the arms as turned now go in whole).
template <int N>
inline void pointSeparations(const ManifoldBlock<N>& c, const BodyPack<N>& a, const BodyPack<N>& b, Pack<N> separations[4]) {
    const Pack<N> movedApart = dot(c.normal, b.deltaPosition - a.deltaPosition);
    // n . (R arm) = (R^T n) . arm: the normal turned back once per body serves all four points.
    const PackVec3<N> normalSeenByA = rotate(conjugate(a.deltaRotation), c.normal);
    const PackVec3<N> normalSeenByB = rotate(conjugate(b.deltaRotation), c.normal);
    for (int k = 0; k < 4; ++k) {
        const ManifoldPointPack<N>& p = c.point[k];
        separations[k] = movedApart + dot(normalSeenByB, p.armB) - dot(normalSeenByA, p.armA) + p.adjustedSeparation;
    }
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

// [ch10-solve-block]
/// One sweep over the block's points: the four normal rows as one block (or one at a time where
/// the block would pull, with position feedback when `useBias`), then friction against the normal
/// impulses just found.
template <int N>
inline void solveBlock(ManifoldBlock<N>& c, SolverBodyState* states, const ContactSolveParams& params, bool useBias) {
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    const Pack<N> inverseH = Pack<N>::splat(1 / params.substep);
    const Pack<N> slop = Pack<N>::splat(params.slop);
    const Pack<N> maxPush = Pack<N>::splat(-params.maxPushOutSpeed);

    // Each point's target, from where its two material points are now (pointSeparations). A gap
    // may close by itself within the substep and no faster (speculative); a point deeper than the
    // slop is pushed out (Baumgarte or a soft spring), at most maxPushOutSpeed.
    Pack<N> bias[4], massScale[4], impulseScale[4], separations[4];
    pointSeparations(c, a, b, separations);
    for (int k = 0; k < 4; ++k) {
        const Pack<N> separation = separations[k];
        bias[k] = separation * inverseH;
        massScale[k] = one;
        impulseScale[k] = zero;
        if (useBias) {
            const Pack<N> excess = separation + slop;  // < 0: deeper than the slop
            const Pack<N> push = max(c.biasRate * excess, maxPush);
            const Pack<N> deep = -excess;
            bias[k] = selectPositive(separation, bias[k], selectPositive(deep, push, zero));
            massScale[k] = selectPositive(deep, c.massScale, one);
            impulseScale[k] = selectPositive(deep, c.impulseScale, zero);
        } else {
            bias[k] = selectPositive(separation, bias[k], zero);
        }
    }

    // The four normal rows at once (Box2D solves its two-point manifolds the same way, as a block):
    // the increments d that make every row's speed its target, d = -K^-1 (J v + bias), kept where
    // they leave every point pushing (lambda + d >= 0) and every row rigid.
    Pack<N> target[4], increment[4];  // target: each row's speed plus bias; increment: the block's change
    PackVec3<N> angularA[4], angularB[4];
    normalAngulars(c, angularA, angularB);
    const Pack<N> approach = dot(c.normal, b.linearVelocity - a.linearVelocity);
    const bool bounces = anyNegative(-c.restitution);  // approachSpeed is read only where a lane bounces
    for (int k = 0; k < 4; ++k) {
        const Pack<N> speed = approach + dot(b.angularVelocity, angularB[k]) - dot(a.angularVelocity, angularA[k]) + bias[k];
        target[k] = selectPositive(c.point[k].normalMass, speed, zero);  // a missing point asks for nothing
        if (!bounces) continue;
        // A gap that a substep's motion closes (the relax sweep looks one substep ahead):
        // restitution reverses the fastest speed it closed at, not the speed at the frame's
        // start, which the fall has not finished (a ball dropped from 1 m hit at 4.41 m/s and
        // bounced as if at 4.25). The fastest: once stopped, a point stays a rounding error
        // apart and "closes" again at gravity's speed.
        const Pack<N> closes = min(separations[k], -target[k]);  // > 0: apart now, closed within h
        c.point[k].approachSpeed =
            selectPositive(closes, min(c.point[k].approachSpeed, speed - bias[k]), c.point[k].approachSpeed);
    }
    Pack<N> total[4], leastLoad = zero, softness = zero;
    for (int i = 0; i < 4; ++i) {
        increment[i] = -(c.normalBlockInverse[kBlockEntry[i][0]] * target[0] + c.normalBlockInverse[kBlockEntry[i][1]] * target[1] +
                         c.normalBlockInverse[kBlockEntry[i][2]] * target[2] + c.normalBlockInverse[kBlockEntry[i][3]] * target[3]);
        total[i] = c.point[i].normalImpulse + increment[i];
        leastLoad = min(leastLoad, total[i]);
        softness = max(softness, impulseScale[i]);
    }
    const Pack<N> rigid = selectPositive(softness, zero, one);
    const Pack<N> useBlock = selectNonNegative(leastLoad, rigid, zero);

    // Where one corner would pull, let it go: its impulse becomes zero and the other rows still
    // meet their targets. With M = K^-1 that is d + s M e_j, s = -(lambda_j + d_j) / M_jj, exact
    // when s >= 0 (the corner then separates) and the others still push. j is the corner that
    // pulls hardest. Skipped where every lane takes the whole block (most of a resting stack's).
    Pack<N> dropped[4] = {zero, zero, zero, zero}, useDropped = zero;
    if (anyNegative(useBlock - one)) {
        const Pack<N> impulses[4] = {c.point[0].normalImpulse, c.point[1].normalImpulse, c.point[2].normalImpulse,
                                     c.point[3].normalImpulse};
        dropCorner(c.normalBlockInverse, impulses, total, increment, useBlock, rigid, dropped, useDropped);
    }
    const Pack<N> blockFails = one - useBlock - useDropped;

    Pack<N> pushed = zero;
    PackVec3<N> turnedA{zero, zero, zero}, turnedB{zero, zero, zero};
    for (int i = 0; i < 4; ++i) {
        ManifoldPointPack<N>& p = c.point[i];
        const Pack<N> impulse = increment[i] * useBlock + dropped[i] * useDropped;
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

    // Otherwise the normal rows one at a time, swept forwards and backwards: a single sweep in one
    // order leaves the first corner pushing harder than the last, a torque that tilts a tall stack;
    // symmetric sweeps bring the corners to nearly the same answer (chapter 6 sweeps 8 times).
    // Only the lanes whose block failed change (selectPositive on blockFails): a lane's answer
    // must not depend on which manifolds share its block, so that the scalar solve and wide solves
    // of any width give the same bits.
    if (anyNegative(-blockFails)) {
        for (int sweep = 0; sweep < kNormalSweeps; ++sweep) {
            for (int k = 0; k < 4; ++k) {
                const int i = sweep % 2 == 0 ? k : 3 - k;
                ManifoldPointPack<N>& p = c.point[i];
                const Pack<N> normalSpeed = dot(c.normal, b.linearVelocity - a.linearVelocity) +
                                            dot(b.angularVelocity, angularB[i]) - dot(a.angularVelocity, angularA[i]);
                Pack<N> impulse = -(p.normalMass * massScale[i] * (normalSpeed + bias[i])) - impulseScale[i] * p.normalImpulse;
                const Pack<N> accumulated = max(p.normalImpulse + impulse, zero);
                impulse = accumulated - p.normalImpulse;
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

    solveFriction(c, a, b);
    scatterVelocities(states, c.slotA, a);
    scatterVelocities(states, c.slotB, b);
}
// [ch10-solve-block]

// [ch10-shock-solve]
/// The shock sweep's relax sweep over the lanes of one of its groups (shockGroup == group): each
/// contact's held body read as at rest where it is now and never written (infinitely heavy: the
/// masses of prepareHeld), its other body relaxed against it, normal block first, then friction,
/// as solveBlock does. Lanes of other groups change nothing, nor does the block: the sweep starts
/// from the impulses the substeps accumulated, and what it adds is not carried to the next frame.
template <int N>
inline void solveHeldBlock(const ManifoldBlock<N>& c, SolverBodyState* states, const ContactSolveParams& params, int group) {
    const Pack<N> zero = Pack<N>::splat(0), one = Pack<N>::splat(1);
    const PackVec3<N> still{zero, zero, zero};
    const RowMasses<N>& m = c.heldMasses;
    BodyPack<N> a = gatherBodies<N>(states, c.slotA);
    BodyPack<N> b = gatherBodies<N>(states, c.slotB);
    const auto hold = [&] {  // the held body's velocity stays zero, whatever the rows pushed it by
        a.linearVelocity = select(c.heldA, still, a.linearVelocity);
        a.angularVelocity = select(c.heldA, still, a.angularVelocity);
        b.linearVelocity = select(c.heldB, still, b.linearVelocity);
        b.angularVelocity = select(c.heldB, still, b.angularVelocity);
    };
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

    // Friction at the centre against the loads just found (solveFriction, with the held masses).
    Pack<N> load = zero, twistLoad = zero;
    for (int k = 0; k < 4; ++k) {
        load = load + impulse[k];
        twistLoad = twistLoad + impulse[k] * c.point[k].twistRadius;
    }
    Pack<N> total1, total2;
    coneImpulses(c, a, b, load, m.tangentInverse11, m.tangentInverse12, m.tangentInverse22, total1, total2);
    applyFriction(c, total1 - c.tangentImpulse1, total2 - c.tangentImpulse2, a, b);
    hold();
    const Pack<N> twistLimit = c.friction * twistLoad;
    const Pack<N> spin = dot(c.normal, b.angularVelocity - a.angularVelocity);
    const Pack<N> twistChange = max(min(c.twistImpulse - m.twistMass * spin, twistLimit), -twistLimit) - c.twistImpulse;
    a.angularVelocity = a.angularVelocity - twistChange * c.twistTurnA;
    b.angularVelocity = b.angularVelocity + twistChange * c.twistTurnB;
    hold();

    // Only the moving body of each lane of the group is written (slot 0 never is).
    int slotA[N], slotB[N];
    for (int lane = 0; lane < N; ++lane) {
        const bool swept = c.shockGroup[lane] == group;
        slotA[lane] = swept && !(c.heldA[lane] > 0) ? c.slotA[lane] : 0;
        slotB[lane] = swept && !(c.heldB[lane] > 0) ? c.slotB[lane] : 0;
    }
    scatterVelocities(states, slotA, a);
    scatterVelocities(states, slotB, b);
}
// [ch10-shock-solve]

// [ch10-collide]
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
        // substep ahead and would take part of the approach speed first (a head-on pair at
        // 3.5 m/s parted at 2.5 with e = 1); 0.1 mm for the rounding of a gap that closes exactly
        // then. The price: a ball may bounce up to two substeps' travel early, which puts the
        // apex (1 - e^2) times that higher.
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
// [ch10-collide]

// [ch10-restitution]
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
// [ch10-restitution]

}  // namespace stepwise
