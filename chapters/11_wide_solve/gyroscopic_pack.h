#pragma once
// Chapter 1's implicit gyroscopic step (gyroscopicStepImplicit), N bodies at a time. In a settling
// pile every box and hull takes it once a substep, and as chapter 1 writes it (Eigen's 3x3
// inverse, two quaternion turns, one body at a time) it is a large part of the pile's frame; over
// packs it is the same arithmetic for N bodies at once (docs/ch11_wide_solve.md, the speed bench's
// profile). The step is chapter 1's, to the rounding: one Newton step of the implicit midpoint
// rule in body axes, then the angular momentum rescaled to its old length (both invariants of
// torque-free motion kept).

#include "11_wide_solve/body_pack.h"
#include "11_wide_solve/solver_data.h"

#include <limits>

namespace stepwise {
inline namespace STEPWISE_ISA {

/// What the step reads of N bodies: each one's spin, its turn since the piece began, its rotation
/// when the piece began, and its inertia in body axes (symmetric, six packs).
template <int N>
struct GyroscopicLanes {
    PackVec3<N> omega;
    PackQuat<N> delta, start;
    PackSym3<N> inertia;
};

template <int N>
inline GyroscopicLanes<N> gatherGyroscopic(const SolverBodyState* states, const GyroscopicBody* bodies) {
    GyroscopicLanes<N> in;
    for (int i = 0; i < N; ++i) {
        const SolverBodyState& s = states[bodies[i].slot];
        const Real* q = bodies[i].startRotation;
        const Real* m = bodies[i].inertia;
        in.omega.x[i] = s.angularVelocity[0], in.omega.y[i] = s.angularVelocity[1], in.omega.z[i] = s.angularVelocity[2];
        in.delta.x[i] = s.deltaRotation[0], in.delta.y[i] = s.deltaRotation[1];
        in.delta.z[i] = s.deltaRotation[2], in.delta.w[i] = s.deltaRotation[3];
        in.start.x[i] = q[0], in.start.y[i] = q[1], in.start.z[i] = q[2], in.start.w[i] = q[3];
        in.inertia.xx[i] = m[0], in.inertia.yy[i] = m[1], in.inertia.zz[i] = m[2];
        in.inertia.xy[i] = m[3], in.inertia.xz[i] = m[4], in.inertia.yz[i] = m[5];
    }
    return in;
}

template <int N>
inline void scatterSpin(SolverBodyState* states, const GyroscopicBody* bodies, const PackVec3<N>& omega) {
    for (int i = 0; i < N; ++i) {
        SolverBodyState& s = states[bodies[i].slot];
        s.angularVelocity[0] = omega.x[i], s.angularVelocity[1] = omega.y[i], s.angularVelocity[2] = omega.z[i];
    }
}

#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE)
// Eight bodies as the contacts gather theirs (body_pack_avx2.h): two rows of eight floats from
// each state and each GyroscopicBody, transposed, where the loop above makes 8 x 17 scalar loads.
template <>
inline GyroscopicLanes<8> gatherGyroscopic<8>(const SolverBodyState* states, const GyroscopicBody* bodies) {
    static_assert(sizeof(GyroscopicBody) == 64 && alignof(GyroscopicBody) == 32, "two aligned 8-float rows");
    __m256 spin[8], turn[8], pose[8], rest[8];
    for (int i = 0; i < 8; ++i) {
        const float* state = reinterpret_cast<const float*>(&states[bodies[i].slot]);
        spin[i] = _mm256_load_ps(state);              // v.xyz w.xyz dp.xy
        turn[i] = _mm256_load_ps(state + 8);          // dp.z dq.xyzw (3 unused)
        pose[i] = _mm256_load_ps(bodies[i].startRotation);  // q.xyzw I.xx yy zz xy
        rest[i] = _mm256_load_ps(bodies[i].inertia + 4);    // I.xz yz, the slot and padding (unused)
    }
    transpose8(spin);
    transpose8(turn);
    transpose8(pose);
    transpose8(rest);
    GyroscopicLanes<8> in;
    const auto put = [](Pack<8>& field, __m256 value) { _mm256_store_ps(field.data(), value); };
    put(in.omega.x, spin[3]), put(in.omega.y, spin[4]), put(in.omega.z, spin[5]);
    put(in.delta.x, turn[1]), put(in.delta.y, turn[2]), put(in.delta.z, turn[3]), put(in.delta.w, turn[4]);
    put(in.start.x, pose[0]), put(in.start.y, pose[1]), put(in.start.z, pose[2]), put(in.start.w, pose[3]);
    put(in.inertia.xx, pose[4]), put(in.inertia.yy, pose[5]), put(in.inertia.zz, pose[6]);
    put(in.inertia.xy, pose[7]), put(in.inertia.xz, rest[0]), put(in.inertia.yz, rest[1]);
    return in;
}
#endif

template <int N>
inline Pack<N> absolute(const Pack<N>& a) {
    return max(a, -a);
}

template <int N>
inline Pack<N> largestEntry(const PackVec3<N>& a, const PackVec3<N>& b, const PackVec3<N>& c) {
    const auto largest = [](const PackVec3<N>& v) { return max(absolute(v.x), max(absolute(v.y), absolute(v.z))); };
    return max(largest(a), max(largest(b), largest(c)));
}

// [ch11-gyroscopic-pack]
/// The gyroscopic step of N bodies over a substep of length h: each body's rotation is its start
/// rotation turned by what it turned since (SolverBodyState::deltaRotation). Only the angular
/// velocities are written.
template <int N>
inline void gyroscopicStepPack(SolverBodyState* states, const GyroscopicBody* bodies, Real h) {
    const GyroscopicLanes<N> in = gatherGyroscopic<N>(states, bodies);
    const PackVec3<N>& omega = in.omega;
    const PackSym3<N>& inertia = in.inertia;
    const PackQuat<N> rotation = normalized(multiply(in.delta, in.start));

    // Body axes, where the inertia is constant: w0 and the momentum I w0.
    const PackVec3<N> omega0 = rotate(conjugate(rotation), omega);
    const PackVec3<N> momentum0 = inertia * omega0;
    const Pack<N> step = Pack<N>::splat(h), halfStep = Pack<N>::splat(h / 2);
    const PackVec3<N> residual = step * cross(omega0, momentum0);

    // The Jacobian I + h/2 ([w]x I - [m]x), a column at a time: column j is I_j + h/2 (w x I_j - m x e_j).
    const PackVec3<N> inertiaX{inertia.xx, inertia.xy, inertia.xz}, inertiaY{inertia.xy, inertia.yy, inertia.yz},
        inertiaZ{inertia.xz, inertia.yz, inertia.zz};
    const Pack<N> zero = Pack<N>::splat(0);
    const PackVec3<N> column0 = inertiaX + halfStep * (cross(omega0, inertiaX) - PackVec3<N>{zero, momentum0.z, -momentum0.y});
    const PackVec3<N> column1 = inertiaY + halfStep * (cross(omega0, inertiaY) - PackVec3<N>{-momentum0.z, zero, momentum0.x});
    const PackVec3<N> column2 = inertiaZ + halfStep * (cross(omega0, inertiaZ) - PackVec3<N>{momentum0.y, -momentum0.x, zero});

    // Solved by the inverse's rows, the columns' cross products over the determinant; a lane whose
    // Jacobian is singular for its own scale keeps its velocity, as chapter 1's solve3 does.
    const PackVec3<N> row0 = cross(column1, column2), row1 = cross(column2, column0), row2 = cross(column0, column1);
    const Pack<N> determinant = dot(column0, row0);
    const Pack<N> scale = largestEntry(column0, column1, column2);
    const Pack<N> solvable = absolute(determinant) - Pack<N>::splat(16 * kEpsilon) * scale * scale * scale;
    const Pack<N> safeDeterminant = selectPositive(solvable, determinant, Pack<N>::splat(1));
    const PackVec3<N> correction{dot(row0, residual) / safeDeterminant, dot(row1, residual) / safeDeterminant,
                                 dot(row2, residual) / safeDeterminant};
    PackVec3<N> omega1 = omega0 - correction;

    // The momentum back to its old length (chapter 1 says why).
    const PackVec3<N> momentum1 = inertia * omega1;
    const Pack<N> length1 = sqrt(dot(momentum1, momentum1)), length0 = sqrt(dot(momentum0, momentum0));
    const Pack<N> tiny = Pack<N>::splat(std::numeric_limits<Real>::min());  // no 0/0 in a lane not taken
    const Pack<N> rescale = selectPositive(length1, length0 / max(length1, tiny), Pack<N>::splat(1));
    omega1 = rescale * omega1;
    scatterSpin<N>(states, bodies, select(solvable, rotate(rotation, omega1), omega));
}
// [ch11-gyroscopic-pack]

}  // namespace STEPWISE_ISA
}  // namespace stepwise
