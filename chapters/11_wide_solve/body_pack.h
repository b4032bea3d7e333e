#pragma once
// A block's two bodies per lane, gathered from the frame's body states and scattered back: the one
// place the solve reads and writes them (Box3D's b2BodyStateW). Generic over the lane count; the
// AVX2 and AVX-512 builds replace the gather and scatter of 8 and 16 lanes with transposes
// (body_pack_avx2.h, body_pack_avx512.h).
#include "01_integrators/rotation.h"
#include "11_wide_solve/solver_data.h"

#include <algorithm>

namespace stepwise {
inline namespace STEPWISE_ISA {

// [ch11-body-pack]
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
// [ch11-body-pack]


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

// [ch11-integrate-positions]
/// holdSpin's rule on the lanes where `held` is positive (the dynamic bodies): a spin faster than
/// `most` keeps its axis at that speed. The scalar rule's arithmetic, lane by lane.
template <int N>
inline void holdSpinPack(PackVec3<N>& w, const Pack<N>& held, Real most) {
    const Pack<N> speedSquared = (w.x * w.x + w.y * w.y) + w.z * w.z;
    const Pack<N> over = held * (speedSquared - Pack<N>::splat(most * most));  // > 0: too fast
    if (!anyNegative(-over)) return;
    const Pack<N> scale = Pack<N>::splat(most) / sqrt(speedSquared);
    w.x = selectPositive(over, w.x * scale, w.x);
    w.y = selectPositive(over, w.y * scale, w.y);
    w.z = selectPositive(over, w.z * scale, w.z);
}

/// Chapter 1's position step for N bodies at once: the centre moves by h v, the rotation since
/// the frame began turns by h |w| about w (turnRotation, the same series on every lane; a lane
/// spinning too fast for the series takes chapter 1's own step). A dynamic body's spin is held
/// first (holdSpinPack); slots below `firstDynamic` are kinematic and keep theirs.
template <int N>
inline void integratePositionsPack(SolverBodyState* states, const int* slots, Real h, Real mostSpin, int firstDynamic) {
    BodyPack<N> body = gatherBodies<N>(states, slots);
    Pack<N> held;
    for (int lane = 0; lane < N; ++lane) held[lane] = slots[lane] >= firstDynamic ? Real(1) : Real(0);
    holdSpinPack(body.angularVelocity, held, mostSpin);
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
// [ch11-integrate-positions]

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
}  // namespace STEPWISE_ISA
}  // namespace stepwise

#include "11_wide_solve/body_pack_avx2.h"
#include "11_wide_solve/body_pack_avx512.h"
