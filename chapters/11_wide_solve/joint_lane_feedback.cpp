// The lane groups' scalar work made wide: which kept joints' lanes keep their rows, and their
// feedback made again from their moved errors (packed_joint_rows.h). Built for the wide solve's
// instruction set (chapters/CMakeLists.txt); the same arithmetic as the scalar rules, lane by lane.
#include "11_wide_solve/packed_joint_rows.h"

#include "11_wide_solve/lane_vec.h"

#include <algorithm>

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

}  // namespace

// [ch11-lanes-turned]
unsigned lanesTurnedAtMost(const JointLaneGroup& group, const SolverBodyState* states, Real most) {
    PackQuat<N> turnA, turnB;  // each lane's bodies' turns since the piece began (slot 0: none)
    for (int lane = 0; lane < N; ++lane) {
        const Real* a = states[group.slotA[lane]].deltaRotation;
        const Real* b = states[group.slotB[lane]].deltaRotation;
        turnA.x[lane] = a[0], turnA.y[lane] = a[1], turnA.z[lane] = a[2], turnA.w[lane] = a[3];
        turnB.x[lane] = b[0], turnB.y[lane] = b[1], turnB.z[lane] = b[2], turnB.w[lane] = b[3];
    }
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

}  // namespace stepwise
