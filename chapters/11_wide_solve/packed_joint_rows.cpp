#include "11_wide_solve/packed_joint_rows.h"

#include "06_manifolds/stabilisation.h"
#include "11_wide_solve/lanes.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

Vec3 linearOf(const SolverBodyState& s) { return Vec3(s.linearVelocity[0], s.linearVelocity[1], s.linearVelocity[2]); }
Vec3 angularOf(const SolverBodyState& s) { return Vec3(s.angularVelocity[0], s.angularVelocity[1], s.angularVelocity[2]); }

// Slot 0 never moves: every push on it is zero (its inverse mass is), and it is not written, so
// that a static body's velocity stays exactly zero.
void push(SolverBodyState* states, int slot, const Vec3& linear, const Vec3& angular) {
    if (slot == 0) return;
    SolverBodyState& s = states[slot];
    for (int k = 0; k < 3; ++k) {
        s.linearVelocity[k] += linear[k];
        s.angularVelocity[k] += angular[k];
    }
}

void pushTurn(SolverBodyState* states, int slot, const Vec3& angular) {
    if (slot == 0) return;
    SolverBodyState& s = states[slot];
    for (int k = 0; k < 3; ++k) s.angularVelocity[k] += angular[k];
}

// The row's impulse change `applied` into its bodies' velocities: inlined by force, as the lanes'
// kernels are (three sweeps a substep call it for every row; a call was a tenth of a chain's frame).
STEPWISE_LANE_INLINE void pushRow(const PackedJointRow& row, Real applied, SolverBodyState* states) {
    if (row.turnOnly) {
        pushTurn(states, row.slotA, applied * row.moveAngularA);
        pushTurn(states, row.slotB, applied * row.moveAngularB);
        return;
    }
    push(states, row.slotA, applied * row.moveLinearA, applied * row.moveAngularA);
    push(states, row.slotB, applied * row.moveLinearB, applied * row.moveAngularB);
}

// A packed row's M^-1 J^T and effective mass, from its Jacobian and its bodies' inverse masses.
void setMoves(const SolverBody& a, const SolverBody& b, PackedJointRow& packed) {
    packed.moveLinearA = a.inverseMass * packed.linearA;
    packed.moveAngularA = a.inverseInertia * packed.angularA;
    packed.moveLinearB = b.inverseMass * packed.linearB;
    packed.moveAngularB = b.inverseInertia * packed.angularB;
    // Chapter 4's effectiveMass, 1 / (J M^-1 J^T), with M^-1 J^T made once above.
    const Real inverseEffectiveMass = a.inverseMass * packed.linearA.squaredNorm() + packed.angularA.dot(packed.moveAngularA) +
                                      b.inverseMass * packed.linearB.squaredNorm() + packed.angularB.dot(packed.moveAngularB);
    packed.effectiveMass = inverseEffectiveMass > 0 ? 1 / inverseEffectiveMass : 0;
}

// One row with what the sweeps read, M^-1 J^T and the effective mass made here.
void packRow(const ConstraintRow& row, const Softness& softness, bool fedBack, JointRowKind kind, Real error, int slot,
             const std::vector<SolverBody>& bodies, const std::vector<int>& slotOfEntry, PackedJointRow& packed) {
    const SolverBody& a = bodies[static_cast<std::size_t>(row.bodyA)];
    const SolverBody& b = bodies[static_cast<std::size_t>(row.bodyB)];
    packed.slotA = slotOfEntry[static_cast<std::size_t>(row.bodyA)];
    packed.slotB = slotOfEntry[static_cast<std::size_t>(row.bodyB)];
    packed.slot = slot;
    packed.fedBack = fedBack;
    packed.turnOnly = row.linearA.isZero(0) && row.linearB.isZero(0);
    packed.kind = kind;
    packed.error = error;
    packed.linearA = row.linearA;
    packed.angularA = row.angularA;
    packed.linearB = row.linearB;
    packed.angularB = row.angularB;
    setMoves(a, b, packed);
    packed.bias = row.bias;
    packed.lower = row.lower;
    packed.upper = row.upper;
    packed.impulse = row.impulse;
    packed.soft = softness;
}

void packBlock(const JointRowBatch& batch, const std::vector<SolverBody>& bodies, const std::vector<int>& slotOfEntry,
               PackedPointBlock& block) {
    const ConstraintRow& row = batch.rows[0];
    const SolverBody& a = bodies[static_cast<std::size_t>(row.bodyA)];
    const SolverBody& b = bodies[static_cast<std::size_t>(row.bodyB)];
    block.slotA = slotOfEntry[static_cast<std::size_t>(row.bodyA)];
    block.slotB = slotOfEntry[static_cast<std::size_t>(row.bodyB)];
    block.armA = batch.set.pointArmA;
    block.armB = batch.set.pointArmB;
    block.mass = batch.set.pointMass;
    block.inverseMassA = a.inverseMass;
    block.inverseMassB = b.inverseMass;
    block.inverseInertiaA = a.inverseInertia;
    block.inverseInertiaB = b.inverseInertia;
    for (int axis = 0; axis < 3; ++axis) {
        block.fedBack[axis] = batch.fedBack[axis];
        block.bias[axis] = batch.rows[axis].bias;
        block.impulse[axis] = batch.rows[axis].impulse;
        block.error[axis] = batch.error[axis];
    }
    block.soft = batch.softness[0];
}

// How fast the anchors part: B's anchor's velocity less A's (the point rows' J v).
Vec3 anchorsRate(const PackedPointBlock& block, const SolverBodyState* states) {
    const SolverBodyState& a = states[block.slotA];
    const SolverBodyState& b = states[block.slotB];
    return linearOf(b) + angularOf(b).cross(block.armB) - linearOf(a) - angularOf(a).cross(block.armA);
}

// The block's impulse: the anchors' relative velocity to the bias, softened (chapter 8's
// solveJointRows).
void solveBlock(PackedPointBlock& block, SolverBodyState* states, bool relax) {
    const Vec3 relative = anchorsRate(block, states);
    Vec3 bias = block.bias;
    for (int axis = 0; axis < 3; ++axis)
        if (relax && block.fedBack[axis]) bias[axis] = 0;
    const Softness soft = relax && block.fedBack[0] ? Softness{} : block.soft;
    const Vec3 impulse = soft.massScale * (block.mass * (bias - relative)) - soft.impulseScale * block.impulse;
    block.impulse += impulse;
    push(states, block.slotA, -block.inverseMassA * impulse, -(block.inverseInertiaA * block.armA.cross(impulse)));
    push(states, block.slotB, block.inverseMassB * impulse, block.inverseInertiaB * block.armB.cross(impulse));
}

// [ch11-packed-sweep]
// How fast the row's C changes: J v (a turn-only row without its zero linear part).
Real rowRate(const PackedJointRow& row, const SolverBodyState* states) {
    const SolverBodyState& a = states[row.slotA];
    const SolverBodyState& b = states[row.slotB];
    if (row.turnOnly) return row.angularA.dot(angularOf(a)) + row.angularB.dot(angularOf(b));
    return row.linearA.dot(linearOf(a)) + row.angularA.dot(angularOf(a)) + row.linearB.dot(linearOf(b)) +
           row.angularB.dot(angularOf(b));
}

void solveRow(PackedJointRow& row, SolverBodyState* states, bool relax) {
    const Real velocity = rowRate(row, states);
    const bool plain = relax && row.fedBack;  // the relax pass: no bias, rigid
    const Softness soft = plain ? Softness{} : row.soft;
    const Real bias = plain ? Real(0) : row.bias;
    const Real previous = row.impulse;
    const Real increment = soft.massScale * row.effectiveMass * (bias - velocity) - soft.impulseScale * previous;
    row.impulse = std::clamp(previous + increment, row.lower, row.upper);
    pushRow(row, row.impulse - previous, states);
}
// [ch11-packed-sweep]

}  // namespace

void reservePackedJoint(PackedJointRows& packed, int joint, int rows, bool block, bool keepable) {
    PackedJoint entry;
    entry.joint = joint;
    entry.keepable = keepable;
    entry.firstRow = packed.rowsReserved;
    entry.rowRoom = rows;
    packed.rowsReserved += rows;
    if (packed.rows.size() < static_cast<std::size_t>(packed.rowsReserved))
        packed.rows.resize(static_cast<std::size_t>(packed.rowsReserved));
    if (block) {
        entry.blockRoom = packed.blocksReserved++;
        if (packed.blocks.size() < static_cast<std::size_t>(packed.blocksReserved))
            packed.blocks.resize(static_cast<std::size_t>(packed.blocksReserved));
    }
    packed.joints.push_back(entry);
}

bool writePackedJoint(const JointRowBatch& batch, const std::vector<SolverBody>& bodies,
                      const std::vector<int>& slotOfEntry, PackedJointRows& packed, int entry) {
    PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    emptyPackedJoint(packed, entry);
    const int begin = batch.set.pointBlock ? 3 : 0;
    if (batch.count - begin > joint.rowRoom || (batch.set.pointBlock && joint.blockRoom < 0)) return false;
    joint.slotCount = batch.count;
    if (batch.set.pointBlock) {
        joint.block = joint.blockRoom;
        packBlock(batch, bodies, slotOfEntry, packed.blocks[static_cast<std::size_t>(joint.block)]);
    }
    for (int slot = begin; slot < batch.count; ++slot) {
        if (!batch.used[slot]) continue;
        PackedJointRow& row = packed.rows[static_cast<std::size_t>(joint.firstRow + joint.rowCount)];
        packRow(batch.rows[slot], batch.softness[slot], batch.fedBack[slot], batch.kind[slot], batch.error[slot], slot,
                bodies, slotOfEntry, row);
        if (row.effectiveMass == 0) continue;  // chapter 8's sweep skips it too: the next row overwrites it
        ++joint.rowCount;
    }
    return true;
}

// [ch11-distance-row]
bool writeDistanceJoint(const JointDesc& joint, const JointFrame& frame, int entryA, int entryB, Real h,
                        const JointFeedback& feedback, Real carried, const std::vector<SolverBody>& bodies,
                        const std::vector<int>& slotOfEntry, PackedJointRows& packed, int entry) {
    PackedJoint& packedJoint = packed.joints[static_cast<std::size_t>(entry)];
    emptyPackedJoint(packed, entry);
    if (packedJoint.rowRoom < 1) return false;
    PackedJointRow& row = packed.rows[static_cast<std::size_t>(packedJoint.firstRow)];
    // Chapter 8's distance row: along the line between the anchors, J as chapter 4's pointVelocityRow.
    const DistanceLine line = distanceLine(joint, frame);
    const Vec3& direction = line.direction;
    row.linearA = -direction;
    row.angularA = -frame.armA.cross(direction);
    row.linearB = direction;
    row.angularB = frame.armB.cross(direction);
    row.error = line.error;
    const bool spring = joint.springHertz > 0;
    row.kind = spring ? JointRowKind::Spring : JointRowKind::Equality;
    row.soft = spring ? makeSoftness(joint.springHertz, joint.springDampingRatio, h) : Softness{};
    row.fedBack = false;
    row.turnOnly = direction.isZero(0);
    jointRowFeedback(row.bias, row.soft, row.fedBack, row.kind, row.error, /*movesPoints=*/!row.turnOnly, feedback, h);
    // Chapter 8's finiteRow: x - x is 0 for every finite x.
    const Real finite = (direction - direction).sum() + (row.angularA - row.angularA).sum() +
                        (row.angularB - row.angularB).sum() + (row.bias - row.bias);
    if (finite != 0) return false;
    row.lower = -kRealMax;
    row.upper = kRealMax;
    row.impulse = std::isfinite(carried) ? std::clamp(carried, row.lower, row.upper) : Real(0);
    row.slot = 0;
    row.slotA = slotOfEntry[static_cast<std::size_t>(entryA)];
    row.slotB = slotOfEntry[static_cast<std::size_t>(entryB)];
    setMoves(bodies[static_cast<std::size_t>(entryA)], bodies[static_cast<std::size_t>(entryB)], row);
    packedJoint.slotCount = 1;
    packedJoint.rowCount = row.effectiveMass == 0 ? 0 : 1;  // chapter 8's sweep skips a row without mass too
    return true;
}
// [ch11-distance-row]

void emptyPackedJoint(PackedJointRows& packed, int entry) {
    PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    joint.block = -1;
    joint.rowCount = 0;
    joint.slotCount = 0;
}

// [ch11-advance-errors]
void advancePackedErrors(PackedJointRows& packed, const SolverBodyState* states, Real h) {
    for (const PackedJoint& joint : packed.joints) {
        if (!joint.keepable) continue;  // built again where the bodies stand next substep
        if (joint.block >= 0) {
            PackedPointBlock& block = packed.blocks[static_cast<std::size_t>(joint.block)];
            block.error += h * anchorsRate(block, states);
        }
        for (int i = joint.firstRow; i < joint.firstRow + joint.rowCount; ++i) {
            PackedJointRow& row = packed.rows[static_cast<std::size_t>(i)];
            if (row.kind != JointRowKind::Free) row.error += h * rowRate(row, states);  // a motor's bias is a speed
        }
    }
}
// [ch11-advance-errors]

void refreshPackedFeedback(PackedJointRows& packed, int entry, const JointFeedback& feedback, Real h) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    if (joint.block >= 0) {
        PackedPointBlock& block = packed.blocks[static_cast<std::size_t>(joint.block)];
        for (int axis = 0; axis < 3; ++axis)
            jointRowFeedback(block.bias[axis], block.soft, block.fedBack[axis], JointRowKind::Equality,
                             block.error[axis], /*movesPoints=*/true, feedback, h);
    }
    for (int i = joint.firstRow; i < joint.firstRow + joint.rowCount; ++i) {
        PackedJointRow& row = packed.rows[static_cast<std::size_t>(i)];
        jointRowFeedback(row.bias, row.soft, row.fedBack, row.kind, row.error, !row.turnOnly, feedback, h);
    }
}

void warmStartPacked(const PackedJointRows& packed, SolverBodyState* states) {
    // Every block first, then every row, each in joint order.
    for (const PackedJoint& joint : packed.joints) {
        if (joint.block < 0) continue;
        const PackedPointBlock& block = packed.blocks[static_cast<std::size_t>(joint.block)];
        const Vec3& impulse = block.impulse;
        push(states, block.slotA, -block.inverseMassA * impulse, -(block.inverseInertiaA * block.armA.cross(impulse)));
        push(states, block.slotB, block.inverseMassB * impulse, block.inverseInertiaB * block.armB.cross(impulse));
    }
    for (const PackedJoint& joint : packed.joints)
        for (int i = joint.firstRow; i < joint.firstRow + joint.rowCount; ++i) {
            const PackedJointRow& row = packed.rows[static_cast<std::size_t>(i)];
            if (row.impulse != 0) pushRow(row, row.impulse, states);
        }
}

void solvePacked(PackedJointRows& packed, SolverBodyState* states, bool relax) {
    for (const PackedJoint& joint : packed.joints) {
        if (joint.block >= 0) solveBlock(packed.blocks[static_cast<std::size_t>(joint.block)], states, relax);
        for (int i = joint.firstRow; i < joint.firstRow + joint.rowCount; ++i)
            solveRow(packed.rows[static_cast<std::size_t>(i)], states, relax);
    }
}

void keepPackedImpulsesOf(const PackedJointRows& packed, int entry, std::vector<JointImpulses>& carried) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    JointImpulses& impulses = carried[static_cast<std::size_t>(joint.joint)];
    if (joint.block >= 0) {
        const Vec3& impulse = packed.blocks[static_cast<std::size_t>(joint.block)].impulse;
        for (int axis = 0; axis < 3; ++axis) impulses.slot[axis] = impulse[axis];
    }
    for (int i = joint.firstRow; i < joint.firstRow + joint.rowCount; ++i) {
        const PackedJointRow& row = packed.rows[static_cast<std::size_t>(i)];
        impulses.slot[row.slot] = row.impulse;
    }
}

void keepPackedImpulses(const PackedJointRows& packed, std::vector<JointImpulses>& carried) {
    for (std::size_t entry = 0; entry < packed.joints.size(); ++entry)
        keepPackedImpulsesOf(packed, static_cast<int>(entry), carried);
}

void resetPackedImpulses(PackedJointRows& packed, std::vector<JointImpulses>& carried) {
    for (const PackedJoint& joint : packed.joints) {
        if (joint.block >= 0) packed.blocks[static_cast<std::size_t>(joint.block)].impulse = Vec3::Zero();
        for (int i = joint.firstRow; i < joint.firstRow + joint.rowCount; ++i) packed.rows[static_cast<std::size_t>(i)].impulse = 0;
        for (int slot = 0; slot < joint.slotCount; ++slot) carried[static_cast<std::size_t>(joint.joint)].slot[slot] = 0;
    }
}

}  // namespace stepwise
