// The joints' three sweeps (warm start, biased pass, relax pass) and the errors' advance, a group
// of joints at a time, one joint per lane (packed_joint_rows.h). Built for the wide solve's
// instruction set (chapters/CMakeLists.txt). Every lane does chapter 8's arithmetic in the order
// the scalar rows did it, sums of three products as Eigen rounds them (ch11-eigen-order below), so
// the groups give the same numbers as a sweep joint after joint.
#include "11_wide_solve/packed_joint_rows.h"

#include "11_wide_solve/body_pack.h"

namespace stepwise {

namespace {

constexpr int N = kWideLanes;
using Lanes = Pack<N>;
using LaneVec = PackVec3<N>;

/// The velocities of one side's body in every lane (and, in the AVX2 float build, the two floats
/// that share their row of the state, carried back as they were read).
struct LaneBodies {
    LaneVec linear, angular;
    Lanes rest[2];
};

#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE) && STEPWISE_WIDE_BYTES == 32
// Eight states' first rows (v, w, two floats of the delta position) loaded whole and transposed,
// as the contacts gather theirs (body_pack_avx2.h).
LaneBodies gatherAll(const SolverBodyState* states, const int* slots) {
    __m256 row[8];
    for (int i = 0; i < 8; ++i) row[i] = _mm256_load_ps(reinterpret_cast<const float*>(&states[slots[i]]));
    transpose8(row);
    LaneBodies body;
    Lanes* fields[8] = {&body.linear.x,  &body.linear.y,  &body.linear.z, &body.angular.x,
                        &body.angular.y, &body.angular.z, &body.rest[0],  &body.rest[1]};
    for (int k = 0; k < 8; ++k) _mm256_store_ps(fields[k]->data(), row[k]);
    return body;
}

// Slot 0 is never written: its lanes pushed nothing, and several lanes may read it.
void scatterAll(SolverBodyState* states, const int* slots, const LaneBodies& body) {
    __m256 row[8] = {_mm256_load_ps(body.linear.x.data()),  _mm256_load_ps(body.linear.y.data()),
                     _mm256_load_ps(body.linear.z.data()),  _mm256_load_ps(body.angular.x.data()),
                     _mm256_load_ps(body.angular.y.data()), _mm256_load_ps(body.angular.z.data()),
                     _mm256_load_ps(body.rest[0].data()),   _mm256_load_ps(body.rest[1].data())};
    transpose8(row);
    for (int i = 0; i < 8; ++i)
        if (slots[i] != 0) _mm256_store_ps(reinterpret_cast<float*>(&states[slots[i]]), row[i]);
}
#else
LaneBodies gatherAll(const SolverBodyState* states, const int* slots) {
    LaneBodies body;
    for (int i = 0; i < N; ++i) {
        const SolverBodyState& s = states[slots[i]];
        body.linear.x[i] = s.linearVelocity[0];
        body.linear.y[i] = s.linearVelocity[1];
        body.linear.z[i] = s.linearVelocity[2];
        body.angular.x[i] = s.angularVelocity[0];
        body.angular.y[i] = s.angularVelocity[1];
        body.angular.z[i] = s.angularVelocity[2];
    }
    return body;
}

// Slot 0 is never written: its lanes pushed nothing, and several lanes may read it.
void scatterAll(SolverBodyState* states, const int* slots, const LaneBodies& body) {
    for (int i = 0; i < N; ++i) {
        if (slots[i] == 0) continue;
        SolverBodyState& s = states[slots[i]];
        s.linearVelocity[0] = body.linear.x[i];
        s.linearVelocity[1] = body.linear.y[i];
        s.linearVelocity[2] = body.linear.z[i];
        s.angularVelocity[0] = body.angular.x[i];
        s.angularVelocity[1] = body.angular.y[i];
        s.angularVelocity[2] = body.angular.z[i];
    }
}
#endif

// A group of one joint (a chain's links each share a body with the next, so each group holds one)
// reads and writes its two bodies alone, the other lanes zero: the full gather's eight loads and
// transposes cost more than the row they feed.
Lanes firstLane(Real value) {
#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE) && STEPWISE_WIDE_BYTES == 32
    return Lanes{reinterpret_cast<Lanes::Values>(_mm256_setr_ps(value, 0, 0, 0, 0, 0, 0, 0))};
#else
    Lanes lanes = Lanes::splat(0);
    lanes[0] = value;
    return lanes;
#endif
}

STEPWISE_LANE_INLINE LaneBodies gatherVelocities(const SolverBodyState* states, const JointLaneGroup& group, const int* slots) {
    if (group.lanes > 1) return gatherAll(states, slots);
    const SolverBodyState& s = states[slots[0]];
    LaneBodies body;
    body.linear = {firstLane(s.linearVelocity[0]), firstLane(s.linearVelocity[1]), firstLane(s.linearVelocity[2])};
    body.angular = {firstLane(s.angularVelocity[0]), firstLane(s.angularVelocity[1]), firstLane(s.angularVelocity[2])};
    return body;
}

STEPWISE_LANE_INLINE void scatterVelocities(SolverBodyState* states, const JointLaneGroup& group, const int* slots,
                                            const LaneBodies& body) {
    if (group.lanes > 1) return scatterAll(states, slots, body);
    if (slots[0] == 0) return;
    SolverBodyState& s = states[slots[0]];
    s.linearVelocity[0] = body.linear.x[0];
    s.linearVelocity[1] = body.linear.y[0];
    s.linearVelocity[2] = body.linear.z[0];
    s.angularVelocity[0] = body.angular.x[0];
    s.angularVelocity[1] = body.angular.y[0];
    s.angularVelocity[2] = body.angular.z[0];
}

// [ch11-eigen-order]
// How Eigen rounds a 3-vector dot product and a 3x3 matrix times a vector, which the scalar sweep
// used: with floats (four to an SSE register, so three do not fill one) every sum goes
// x0 + (x1 + x2); with doubles (two to a register) the dot product and the matrix's first two rows
// go (x0 + x1) + x2, its last row x0 + (x1 + x2). tests/ch11/joint_lanes_test.cpp holds the lanes
// to the scalar sweep's bits.
#if defined(STEPWISE_DOUBLE)
Lanes dot3(const LaneVec& a, const LaneVec& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
LaneVec times(const Lanes (&m)[9], const LaneVec& v) {
    return {(m[0] * v.x + m[1] * v.y) + m[2] * v.z, (m[3] * v.x + m[4] * v.y) + m[5] * v.z,
            m[6] * v.x + (m[7] * v.y + m[8] * v.z)};
}
#else
Lanes dot3(const LaneVec& a, const LaneVec& b) { return a.x * b.x + (a.y * b.y + a.z * b.z); }
LaneVec times(const Lanes (&m)[9], const LaneVec& v) {
    return {m[0] * v.x + (m[1] * v.y + m[2] * v.z), m[3] * v.x + (m[4] * v.y + m[5] * v.z),
            m[6] * v.x + (m[7] * v.y + m[8] * v.z)};
}
#endif
// [ch11-eigen-order]
// Negation that flips the sign of zero too, as the scalar code's unary minus does (lanes.h's
// operator- is 0 - a).
Lanes negated(const Lanes& a) {
#if defined(STEPWISE_VECTOR_PACKS)
    return Lanes{-a.v};
#else
    Lanes result;
    for (int i = 0; i < N; ++i) result[i] = -a[i];
    return result;
#endif
}
LaneVec negated(const LaneVec& v) { return {negated(v.x), negated(v.y), negated(v.z)}; }

// How fast the anchors part: B's anchor's velocity less A's (the point rows' J v).
LaneVec anchorsRate(const JointBlockLanes& block, const LaneBodies& a, const LaneBodies& b) {
    return ((b.linear + cross(b.angular, block.armB)) - a.linear) - cross(a.angular, block.armA);
}

// The block's impulse change into both bodies.
void pushBlock(const JointBlockLanes& block, const LaneVec& impulse, LaneBodies& a, LaneBodies& b) {
    a.linear = a.linear + negated(block.inverseMassA) * impulse;
    a.angular = a.angular + negated(times(block.inverseInertiaA, cross(block.armA, impulse)));
    b.linear = b.linear + block.inverseMassB * impulse;
    b.angular = b.angular + times(block.inverseInertiaB, cross(block.armB, impulse));
}

// How fast the row's C changes: J v.
Lanes rowRate(const JointRowLanes& row, const LaneBodies& a, const LaneBodies& b) {
    return ((dot3(row.linearA, a.linear) + dot3(row.angularA, a.angular)) + dot3(row.linearB, b.linear)) +
           dot3(row.angularB, b.angular);
}

void pushRow(const JointRowLanes& row, const Lanes& applied, LaneBodies& a, LaneBodies& b) {
    a.linear = a.linear + applied * row.moveLinearA;
    a.angular = a.angular + applied * row.moveAngularA;
    b.linear = b.linear + applied * row.moveLinearB;
    b.angular = b.angular + applied * row.moveAngularB;
}

// [ch11-joint-lane-solve]
// The block's impulse: the anchors' relative velocity to the bias, softened (chapter 8's
// solveJointRows); the relax pass takes the bias and softness out of the rows fed back.
void solveBlock(JointBlockLanes& block, bool relax, LaneBodies& a, LaneBodies& b) {
    const LaneVec relative = anchorsRate(block, a, b);
    LaneVec bias = block.bias;
    Lanes massScale = block.massScale, impulseScale = block.impulseScale;
    if (relax) {
        const Lanes zero = Lanes::splat(0);
        bias = {selectPositive(block.fedBack[0], zero, bias.x), selectPositive(block.fedBack[1], zero, bias.y),
                selectPositive(block.fedBack[2], zero, bias.z)};
        massScale = selectPositive(block.fedBack[0], Lanes::splat(1), massScale);
        impulseScale = selectPositive(block.fedBack[0], zero, impulseScale);
    }
    // Eigen makes s (K^-1 v) as (K^-1 s) v: the scale goes into the matrix first.
    Lanes scaledMass[9];
    for (int k = 0; k < 9; ++k) scaledMass[k] = block.mass[k] * massScale;
    const LaneVec impulse = times(scaledMass, bias - relative) - impulseScale * block.impulse;
    block.impulse = block.impulse + impulse;
    pushBlock(block, impulse, a, b);
}

void solveRow(JointRowLanes& row, bool relax, LaneBodies& a, LaneBodies& b) {
    const Lanes velocity = rowRate(row, a, b);
    Lanes bias = row.bias, massScale = row.massScale, impulseScale = row.impulseScale;
    if (relax) {  // no bias, rigid
        bias = selectPositive(row.fedBack, Lanes::splat(0), bias);
        massScale = selectPositive(row.fedBack, Lanes::splat(1), massScale);
        impulseScale = selectPositive(row.fedBack, Lanes::splat(0), impulseScale);
    }
    const Lanes previous = row.impulse;
    const Lanes increment = massScale * row.effectiveMass * (bias - velocity) - impulseScale * previous;
    // std::clamp as libstdc++ writes it: min(max(value, lower), upper).
    const Lanes total = previous + increment;
    row.impulse = min(row.upper, max(row.lower, total));
    pushRow(row, row.impulse - previous, a, b);
}
// [ch11-joint-lane-solve]

}  // namespace

void warmStartPacked(const PackedJointRows& packed, SolverBodyState* states) {
    // Every block first, then every row, each group in order: every body meets its joints' blocks
    // and then their rows in the sweep's order of joints.
    for (int g = 0; g < packed.groupCount; ++g) {
        const JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        if (!group.blocks) continue;
        LaneBodies a = gatherVelocities(states, group, group.slotA), b = gatherVelocities(states, group, group.slotB);
        pushBlock(group.block, group.block.impulse, a, b);
        scatterVelocities(states, group, group.slotA, a);
        scatterVelocities(states, group, group.slotB, b);
    }
    for (int g = 0; g < packed.groupCount; ++g) {
        const JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        if (group.rowsInUse == 0) continue;
        LaneBodies a = gatherVelocities(states, group, group.slotA), b = gatherVelocities(states, group, group.slotB);
        for (int k = 0; k < group.rowsInUse; ++k) {
            const JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
            pushRow(row, row.impulse, a, b);
        }
        scatterVelocities(states, group, group.slotA, a);
        scatterVelocities(states, group, group.slotB, b);
    }
}

void solvePacked(PackedJointRows& packed, SolverBodyState* states, bool relax) {
    for (int g = 0; g < packed.groupCount; ++g) {
        JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        LaneBodies a = gatherVelocities(states, group, group.slotA), b = gatherVelocities(states, group, group.slotB);
        if (group.blocks) solveBlock(group.block, relax, a, b);
        for (int k = 0; k < group.rowsInUse; ++k) solveRow(group.rows[static_cast<std::size_t>(k)], relax, a, b);
        scatterVelocities(states, group, group.slotA, a);
        scatterVelocities(states, group, group.slotB, b);
    }
}

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

// [ch11-advance-errors]
void advancePackedErrors(PackedJointRows& packed, const SolverBodyState* states, Real h) {
    const Lanes step = Lanes::splat(h);
    for (int g = 0; g < packed.groupCount; ++g) {
        JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        if (!group.keepable) continue;  // rows built every substep: their errors are measured
        const LaneBodies a = gatherVelocities(states, group, group.slotA), b = gatherVelocities(states, group, group.slotB);
        if (group.blocks) {
            JointBlockLanes& block = group.block;
            const LaneVec moved = block.error + step * anchorsRate(block, a, b);
            block.error = {selectPositive(block.present, moved.x, block.error.x),
                           selectPositive(block.present, moved.y, block.error.y),
                           selectPositive(block.present, moved.z, block.error.z)};
        }
        for (int k = 0; k < group.rowsInUse; ++k) {
            JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
            row.error = selectPositive(row.advances, row.error + step * rowRate(row, a, b), row.error);
        }
    }
}
// [ch11-advance-errors]

}  // namespace stepwise
