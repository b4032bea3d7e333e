// The lane groups' scalar work made wide: which kept joints' lanes keep their rows, and their
// feedback made again from their moved errors (packed_joint_rows.h). Built for the wide solve's
// instruction set (chapters/CMakeLists.txt); the same arithmetic as the scalar rules, lane by lane.
#include "11_wide_solve/packed_joint_rows.h"

#include "11_wide_solve/body_pack.h"
#include "11_wide_solve/lane_vec.h"

#include <algorithm>
#include <limits>

namespace stepwise {

namespace {

constexpr int N = kWideLanes;
using Lanes = Pack<N>;
using namespace lane_vec;

Vec<Lanes> load(const PackVec3<N>& v) { return {v.x, v.y, v.z}; }

// Where `take` is positive the new value, elsewhere the old.
void put(PackVec3<N>& to, const Lanes& take, const Vec<Lanes>& v) {
    to.x = selectPositive(take, v.x, to.x);
    to.y = selectPositive(take, v.y, to.y);
    to.z = selectPositive(take, v.z, to.z);
}

#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE) && STEPWISE_WIDE_BYTES == 32
// Eight states' second rows (dp.z, the turn, three unused floats) loaded whole and transposed, as
// the sweeps gather their first rows (packed_joint_sweep.cpp).
PackQuat<N> gatherTurns(const SolverBodyState* states, const int* slots) {
    __m256 row[8];
    for (int i = 0; i < 8; ++i) row[i] = _mm256_load_ps(reinterpret_cast<const float*>(&states[slots[i]]) + 8);
    transpose8(row);
    PackQuat<N> turn;
    _mm256_store_ps(turn.x.data(), row[1]);
    _mm256_store_ps(turn.y.data(), row[2]);
    _mm256_store_ps(turn.z.data(), row[3]);
    _mm256_store_ps(turn.w.data(), row[4]);
    return turn;
}
#else
PackQuat<N> gatherTurns(const SolverBodyState* states, const int* slots) {
    PackQuat<N> turn;
    for (int lane = 0; lane < N; ++lane) {
        const Real* q = states[slots[lane]].deltaRotation;
        turn.x[lane] = q[0], turn.y[lane] = q[1], turn.z[lane] = q[2], turn.w[lane] = q[3];
    }
    return turn;
}
#endif

}  // namespace

// [ch11-lanes-turned]
unsigned lanesTurnedAtMost(const JointLaneGroup& group, const SolverBodyState* states, Real most) {
    // Each lane's bodies' turns since the piece began (slot 0: none).
    const PackQuat<N> turnA = gatherTurns(states, group.slotA), turnB = gatherTurns(states, group.slotB);
    const Lanes limit = Lanes::splat(most * most / 4), one = Lanes::splat(1);
    // The quotient's w is the dot product of two unit quaternions; |v|^2 = 1 - w^2.
    const auto little = [&](const PackQuat<N>& built, const PackQuat<N>& now) {
        const Lanes w = (built.x * now.x + built.z * now.z) + (built.y * now.y + built.w * now.w);
        return limit - (one - w * w);  // >= 0 where the turn is at most `most`
    };
    const Lanes slackA = little(group.builtA, turnA), slackB = little(group.builtB, turnB);
    unsigned lanes = 0;
    for (int lane = 0; lane < group.lanes; ++lane)
        if (slackA[lane] >= 0 && slackB[lane] >= 0) lanes |= 1u << lane;
    return lanes;
}
// [ch11-lanes-turned]

// [ch11-lane-feedback]
// Chapter 8's jointRowFeedback for the soft step, in lanes: the same rule and the same arithmetic,
// each lane's kind picking its case. Lanes outside `lanes` keep what they hold.
void refreshPackedFeedbackLanes(PackedJointRows& packed, int g, unsigned lanes, const JointFeedback& feedback, Real h) {
    JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
    if (feedback.kind != JointFeedback::Kind::Soft) {  // chapter 8's other rules, lane by lane
        for (int lane = 0; lane < N; ++lane)
            if (lanes >> lane & 1u) refreshPackedFeedback(packed, group.entry[lane], feedback, h);
        return;
    }
    Lanes kept = Lanes::splat(0), keptBlock = Lanes::splat(0);
    for (int lane = 0; lane < N; ++lane) {
        kept[lane] = lanes >> lane & 1u ? 1 : 0;
        keptBlock[lane] = kept[lane] * group.block.present[lane];
    }
    const Lanes zero = Lanes::splat(0), one = Lanes::splat(1);
    const Lanes fedRate = Lanes::splat(feedback.soft.biasRate), fedMass = Lanes::splat(feedback.soft.massScale),
                fedImpulse = Lanes::splat(feedback.soft.impulseScale);
    const auto fedBias = [&](const Lanes& error, const Lanes& cap) {  // clamp(-rate C, -cap, cap)
        return min(cap, max(negated(cap), negated(fedRate) * error));
    };
    if (group.blocks) {  // a point block is an equality on all three axes, its rows move points
        JointBlockLanes& block = group.block;
        const Lanes cap = Lanes::splat(kMaxJointPushOutSpeed);
        Lanes* bias[3] = {&block.bias.x, &block.bias.y, &block.bias.z};
        const Lanes* error[3] = {&block.error.x, &block.error.y, &block.error.z};
        for (int axis = 0; axis < 3; ++axis) {
            *bias[axis] = selectPositive(keptBlock, fedBias(*error[axis], cap), *bias[axis]);
            block.fedBack[axis] = selectPositive(keptBlock, one, block.fedBack[axis]);
        }
        block.biasRate = selectPositive(keptBlock, fedRate, block.biasRate);
        block.massScale = selectPositive(keptBlock, fedMass, block.massScale);
        block.impulseScale = selectPositive(keptBlock, fedImpulse, block.impulseScale);
    }
    const Lanes step = Lanes::splat(h);
    for (int k = 0; k < group.rowsInUse; ++k) {  // the rows' kinds: chapter 8's jointRowFeedback
        JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
        // 1 per kept lane in its case (a lane past its joint's rows is zero, of kind Free: none).
        const Lanes spring = kept * row.isSpring;
        const Lanes opened = kept * selectPositive(row.error, row.isLimit, zero);
        const Lanes passed = kept * row.isEquality + (kept * row.isLimit - opened);
        const Lanes& cap = row.pushCap;
        // A spring: its own rate. A limit not reached: speculative, rigid, not fed back.
        Lanes bias = selectPositive(spring, negated(row.biasRate) * row.error, row.bias);
        bias = selectPositive(opened, negated(row.error) / step, bias);
        // An equality, or a limit passed: the soft step's feedback, capped.
        bias = selectPositive(passed, fedBias(row.error, cap), bias);
        row.bias = bias;
        row.biasRate = selectPositive(opened, zero, selectPositive(passed, fedRate, row.biasRate));
        row.massScale = selectPositive(opened, one, selectPositive(passed, fedMass, row.massScale));
        row.impulseScale = selectPositive(opened, zero, selectPositive(passed, fedImpulse, row.impulseScale));
        row.fedBack = selectPositive(opened, zero, selectPositive(passed, one, row.fedBack));
    }
}
// [ch11-lane-feedback]

}  // namespace stepwise

namespace stepwise {

// [ch11-lane-moves]
// writePackedJoint's setMoves for a group's rows at once: M^-1 J^T and 1 / (J M^-1 J^T), in the
// order Eigen sums them (lane_vec.h), so each lane holds the number the joint alone would.
void makeLaneMoves(JointLaneGroup& group, unsigned lanes, const int* rows, const LaneMasses& masses) {
    int most = 0;
    for (int lane = 0; lane < N; ++lane)
        if (lanes >> lane & 1u) most = std::max(most, rows[lane]);
    const Lanes zero = Lanes::splat(0), one = Lanes::splat(1);
    for (int k = 0; k < most; ++k) {
        Lanes take = zero;  // 1 in the lanes whose row k is new
        for (int lane = 0; lane < N; ++lane) take[lane] = (lanes >> lane & 1u) && k < rows[lane] ? 1 : 0;
        JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
        const Vec<Lanes> linearA = load(row.linearA), angularA = load(row.angularA);
        const Vec<Lanes> linearB = load(row.linearB), angularB = load(row.angularB);
        const Vec<Lanes> moveAngularA = times(masses.inverseInertiaA, angularA);
        const Vec<Lanes> moveAngularB = times(masses.inverseInertiaB, angularB);
        const Lanes inverse = ((masses.inverseMassA * dot3(linearA, linearA) + dot3(angularA, moveAngularA)) +
                               masses.inverseMassB * dot3(linearB, linearB)) +
                              dot3(angularB, moveAngularB);
        put(row.moveLinearA, take, masses.inverseMassA * linearA);
        put(row.moveAngularA, take, moveAngularA);
        put(row.moveLinearB, take, masses.inverseMassB * linearB);
        put(row.moveAngularB, take, moveAngularB);
        // Only a positive sum is divided (the rest take 0, as the scalar rule's 'inverse > 0 ? 1 / inverse : 0').
        const Lanes mass = selectPositive(inverse, one / selectPositive(inverse, inverse, one), zero);
        row.effectiveMass = selectPositive(take, mass, row.effectiveMass);
    }
}
// [ch11-lane-moves]

// [ch11-lane-point-mass]
// Chapter 8's setPointBlock for a group's joints at once: K = (1/mA + 1/mB) 1 - [rA]x IA^-1 [rA]x
// - [rB]x IB^-1 [rB]x, its norm, its determinant and its inverse, each sum in the order Eigen
// makes it (tests/ch11/packed_joint_rows_test.cpp compares every lane's bits with chapter 8's).
void makeLanePointMasses(const PackVec3<N>& armA, const PackVec3<N>& armB, const LaneMasses& masses, Lanes (&inverse)[9],
                         Lanes& scale, Lanes& determinant) {
    const Lanes zero = Lanes::splat(0), one = Lanes::splat(1);
    const auto skew = [&](const PackVec3<N>& v, Lanes (&m)[9]) {  // row by row, as math.h's skew
        m[0] = zero, m[1] = negated(v.z), m[2] = v.y;
        m[3] = v.z, m[4] = zero, m[5] = negated(v.x);
        m[6] = negated(v.y), m[7] = v.x, m[8] = zero;
    };
    const auto product = [](const Lanes (&a)[9], const Lanes (&b)[9], Lanes (&c)[9]) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                c[3 * i + j] = dot3(Vec<Lanes>{a[3 * i], a[3 * i + 1], a[3 * i + 2]}, Vec<Lanes>{b[j], b[3 + j], b[6 + j]});
    };
    Lanes skewA[9], skewB[9], half[9], turnA[9], turnB[9];
    skew(armA, skewA);
    skew(armB, skewB);
    product(skewA, masses.inverseInertiaA, half);
    product(half, skewA, turnA);
    product(skewB, masses.inverseInertiaB, half);
    product(half, skewB, turnB);
    const Lanes linear = masses.inverseMassA + masses.inverseMassB;
    Lanes k[9];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) k[3 * i + j] = (linear * (i == j ? one : zero) - turnA[3 * i + j]) - turnB[3 * i + j];
    // The norm: Eigen sums the nine squares, stored column by column, a register at a time.
    Lanes square[9];
    for (int m = 0; m < 9; ++m) square[m] = k[3 * (m % 3) + m / 3] * k[3 * (m % 3) + m / 3];
#if defined(STEPWISE_DOUBLE)
    const Lanes sum = (((square[0] + square[2]) + (square[4] + square[6])) + ((square[1] + square[3]) + (square[5] + square[7]))) +
                      square[8];
#else
    const Lanes sum = (((square[0] + square[4]) + (square[2] + square[6])) + ((square[1] + square[5]) + (square[3] + square[7]))) +
                      square[8];
#endif
    scale = sqrt(sum);
    // The determinant along the first row, and the inverse by cofactors (Eigen's 3x3 rules).
    const auto at = [&](int i, int j) -> const Lanes& { return k[3 * i + j]; };
    const auto minor = [&](int a, int b, int c) { return at(0, a) * (at(1, b) * at(2, c) - at(1, c) * at(2, b)); };
    determinant = (minor(0, 1, 2) - minor(1, 0, 2)) + minor(2, 0, 1);
    const auto cofactor = [&](int i, int j) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        return at(i1, j1) * at(i2, j2) - at(i1, j2) * at(i2, j1);
    };
    const Lanes byColumn = dot3(Vec<Lanes>{cofactor(0, 0), cofactor(1, 0), cofactor(2, 0)}, Vec<Lanes>{at(0, 0), at(1, 0), at(2, 0)});
    // A zero determinant (an empty lane, both bodies fixed) is not divided by: its inverse is NaN,
    // which chapter 8's 1 / 0 makes of it too, and which no lane keeps.
    const Lanes nonZero = max(byColumn, negated(byColumn));
    const Lanes inverseDeterminant = one / selectPositive(nonZero, byColumn, one);
    const Lanes notANumber = Lanes::splat(std::numeric_limits<Real>::quiet_NaN());
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            inverse[3 * i + j] = selectPositive(nonZero, cofactor(j, i) * inverseDeterminant, notANumber);
}
// [ch11-lane-point-mass]

// [ch11-turns-rebased]
// Each lane's turns at build, from the piece's start to the poses it leaves: a body's pose is its
// turn since the start after the start's (slotPose), so the turn at build after the new start is
// the old one after the inverse of the turn since the start, b d*, normalised (a group at once,
// the same bits in every lane as one at a time; slot 0 and empty lanes do not turn).
namespace {

void turnBack(PackQuat<N>& built, const int* slots, int lanes, const SolverBodyState* states) {
    Lanes dx = Lanes::splat(0), dy = dx, dz = dx, dw = Lanes::splat(1), turns = dx;
    for (int lane = 0; lane < lanes; ++lane) {
        if (slots[lane] == 0) continue;
        const Real* d = states[slots[lane]].deltaRotation;
        dx[lane] = d[0], dy[lane] = d[1], dz[lane] = d[2], dw[lane] = d[3], turns[lane] = 1;
    }
    const Lanes &x = built.x, &y = built.y, &z = built.z, &w = built.w;
    const Lanes rw = ((w * dw + x * dx) + y * dy) + z * dz;
    const Lanes rx = ((x * dw - w * dx) - y * dz) + z * dy;
    const Lanes ry = ((y * dw + x * dz) - w * dy) - z * dx;
    const Lanes rz = ((z * dw - x * dy) + y * dx) - w * dz;
    const Lanes length = sqrt(((rx * rx + ry * ry) + rz * rz) + rw * rw);
    const Lanes safe = selectPositive(turns, length, Lanes::splat(1));
    built.x = selectPositive(turns, rx / safe, x);
    built.y = selectPositive(turns, ry / safe, y);
    built.z = selectPositive(turns, rz / safe, z);
    built.w = selectPositive(turns, rw / safe, w);
}

}  // namespace

void rebaseBuiltTurns(PackedJointRows& packed, const SolverBodyState* states) {
    for (int g = 0; g < packed.groupCount; ++g) {
        JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        turnBack(group.builtA, group.slotA, group.lanes, states);
        turnBack(group.builtB, group.slotB, group.lanes, states);
    }
}
// [ch11-turns-rebased]

}  // namespace stepwise
