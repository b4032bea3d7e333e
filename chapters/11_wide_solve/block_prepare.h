#pragma once
// A block's effective masses, once per frame: the rows' angular parts, the normal block's
// inverse and the friction rows' masses (rowMasses, prepareBlock).
#include "11_wide_solve/block_fill.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

/// The angular parts of the rows, arm x direction: each point's normal row (the arm reaches the
/// point) and the centre's two tangent rows (the centre's arm). Computed where they are read, not
/// kept in the block: a few cross products cost less than reading them back, 36 cache lines of a
/// sixteen-lane block for every sweep of a scene too large for the cache.
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

// [ch11-normal-block]
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
// [ch11-normal-block]
/// Once per frame, after fillLane: everything about the rows that depends only on the frame's
/// start, for all lanes at once. fillLane marks each point that exists with normalMass = 1; here
/// it becomes the row's effective mass (rowMasses).
template <int N>
inline void prepareBlock(ManifoldBlock<N>& c, const SolverBodyState* states) {
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
}
}  // namespace STEPWISE_ISA
}  // namespace stepwise
