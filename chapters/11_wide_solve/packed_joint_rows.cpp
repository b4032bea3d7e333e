#include "11_wide_solve/packed_joint_rows.h"

#include "06_manifolds/stabilisation.h"
#include "11_wide_solve/lanes.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

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

}  // namespace

// A lane of the layout as one row or block: the scalar work (building, feedback, impulses back)
// reads and writes a joint's lane through these; the sweeps read the lanes whole.
namespace {

Real& at(PackVec3<kWideLanes>& v, int axis, int lane) { return (axis == 0 ? v.x : axis == 1 ? v.y : v.z)[lane]; }
Real at(const PackVec3<kWideLanes>& v, int axis, int lane) { return (axis == 0 ? v.x : axis == 1 ? v.y : v.z)[lane]; }

void storeVec(PackVec3<kWideLanes>& to, int lane, const Vec3& v) {
    to.x[lane] = v.x();
    to.y[lane] = v.y();
    to.z[lane] = v.z();
}
Vec3 loadVec(const PackVec3<kWideLanes>& from, int lane) { return Vec3(from.x[lane], from.y[lane], from.z[lane]); }

void storeMat(Pack<kWideLanes> (&to)[9], int lane, const Mat3& m) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) to[3 * i + j][lane] = m(i, j);
}
Mat3 loadMat(const Pack<kWideLanes> (&from)[9], int lane) {
    Mat3 m;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = from[3 * i + j][lane];
    return m;
}

void storeRow(JointRowLanes& to, int lane, const PackedJointRow& row, bool keepable) {
    storeVec(to.linearA, lane, row.linearA);
    storeVec(to.angularA, lane, row.angularA);
    storeVec(to.linearB, lane, row.linearB);
    storeVec(to.angularB, lane, row.angularB);
    storeVec(to.moveLinearA, lane, row.moveLinearA);
    storeVec(to.moveAngularA, lane, row.moveAngularA);
    storeVec(to.moveLinearB, lane, row.moveLinearB);
    storeVec(to.moveAngularB, lane, row.moveAngularB);
    to.effectiveMass[lane] = row.effectiveMass;
    to.bias[lane] = row.bias;
    to.lower[lane] = row.lower;
    to.upper[lane] = row.upper;
    to.impulse[lane] = row.impulse;
    to.error[lane] = row.error;
    to.biasRate[lane] = row.soft.biasRate;
    to.massScale[lane] = row.soft.massScale;
    to.impulseScale[lane] = row.soft.impulseScale;
    to.fedBack[lane] = row.fedBack ? 1 : 0;
    to.advances[lane] = keepable && row.kind != JointRowKind::Free ? 1 : 0;  // a motor's bias is a speed
    to.isSpring[lane] = row.kind == JointRowKind::Spring ? 1 : 0;
    to.isLimit[lane] = row.kind == JointRowKind::Limit ? 1 : 0;
    to.isEquality[lane] = row.kind == JointRowKind::Equality ? 1 : 0;
    to.pushCap[lane] = row.turnOnly ? kMaxJointPushOutTurn : kMaxJointPushOutSpeed;
    to.slot[lane] = row.slot;
    to.kind[lane] = row.kind;
    to.turnOnly[lane] = row.turnOnly;
}

PackedJointRow loadRow(const JointRowLanes& from, int lane) {
    PackedJointRow row;
    row.linearA = loadVec(from.linearA, lane);
    row.angularA = loadVec(from.angularA, lane);
    row.linearB = loadVec(from.linearB, lane);
    row.angularB = loadVec(from.angularB, lane);
    row.moveLinearA = loadVec(from.moveLinearA, lane);
    row.moveAngularA = loadVec(from.moveAngularA, lane);
    row.moveLinearB = loadVec(from.moveLinearB, lane);
    row.moveAngularB = loadVec(from.moveAngularB, lane);
    row.effectiveMass = from.effectiveMass[lane];
    row.bias = from.bias[lane];
    row.lower = from.lower[lane];
    row.upper = from.upper[lane];
    row.impulse = from.impulse[lane];
    row.error = from.error[lane];
    row.soft = Softness{from.biasRate[lane], from.massScale[lane], from.impulseScale[lane]};
    row.fedBack = from.fedBack[lane] != 0;
    row.slot = from.slot[lane];
    row.kind = from.kind[lane];
    row.turnOnly = from.turnOnly[lane];
    return row;
}

void storeBlock(JointBlockLanes& to, int lane, const PackedPointBlock& block) {
    storeVec(to.armA, lane, block.armA);
    storeVec(to.armB, lane, block.armB);
    storeMat(to.mass, lane, block.mass);
    to.inverseMassA[lane] = block.inverseMassA;
    to.inverseMassB[lane] = block.inverseMassB;
    storeMat(to.inverseInertiaA, lane, block.inverseInertiaA);
    storeMat(to.inverseInertiaB, lane, block.inverseInertiaB);
    storeVec(to.bias, lane, block.bias);
    storeVec(to.impulse, lane, block.impulse);
    storeVec(to.error, lane, block.error);
    to.biasRate[lane] = block.soft.biasRate;
    to.massScale[lane] = block.soft.massScale;
    to.impulseScale[lane] = block.soft.impulseScale;
    for (int axis = 0; axis < 3; ++axis) to.fedBack[axis][lane] = block.fedBack[axis] ? 1 : 0;
    to.present[lane] = 1;
}

// Every field of the lane zero: no mass, no Jacobian, no impulse; the sweeps change nothing by it.
void zeroRow(JointRowLanes& to, int lane) {
    storeRow(to, lane, PackedJointRow{}, false);
    to.massScale[lane] = 0;
}
void zeroBlock(JointBlockLanes& to, int lane) {
    storeBlock(to, lane, PackedPointBlock{});
    to.massScale[lane] = 0;
    to.present[lane] = 0;
}

}  // namespace

// [ch11-joint-groups]
void reservePackedJoint(PackedJointRows& packed, int joint, int rows, bool block, bool keepable, int slotA, int slotB) {
    const auto last = [&](int slot) -> int& {
        if (packed.lastGroupOfSlot.size() <= static_cast<std::size_t>(slot))
            packed.lastGroupOfSlot.resize(static_cast<std::size_t>(slot) + 1, -1);
        return packed.lastGroupOfSlot[static_cast<std::size_t>(slot)];
    };
    // After every group holding an earlier joint of either moving body (slot 0 does not move, and
    // any number of lanes may read it), in the first such group with a free lane.
    const auto full = [&](int group) { return packed.groups[static_cast<std::size_t>(group)].lanes == kWideLanes; };
    while (packed.firstOpenGroup < packed.groupCount && full(packed.firstOpenGroup)) ++packed.firstOpenGroup;
    int g = packed.firstOpenGroup;
    if (slotA != 0) g = std::max(g, last(slotA) + 1);
    if (slotB != 0) g = std::max(g, last(slotB) + 1);
    while (g < packed.groupCount && full(g)) ++g;
    if (g == packed.groupCount) {
        if (packed.groups.size() <= static_cast<std::size_t>(g)) packed.groups.emplace_back();
        JointLaneGroup& fresh = packed.groups[static_cast<std::size_t>(g)];
        fresh.lanes = 0;
        fresh.blocks = false;
        fresh.keepable = false;
        fresh.rowCount = 0;
        fresh.rowsInUse = 0;
        fresh.keepableLanes = fresh.builtLanes = 0;
        for (int lane = 0; lane < kWideLanes; ++lane) fresh.slotA[lane] = fresh.slotB[lane] = 0;

        ++packed.groupCount;
    }
    JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
    PackedJoint entry;
    entry.joint = joint;
    entry.keepable = keepable;
    entry.group = g;
    entry.lane = group.lanes++;
    entry.rowRoom = rows;
    entry.blockRoom = block;
    group.slotA[entry.lane] = slotA;
    group.slotB[entry.lane] = slotB;
    group.entry[entry.lane] = static_cast<int>(packed.joints.size());
    if (block && !group.blocks) group.block = JointBlockLanes{};  // every lane zero until its joint writes it
    group.blocks = group.blocks || block;
    group.keepable = group.keepable || keepable;
    if (keepable) group.keepableLanes |= 1u << entry.lane;
    if (rows > group.rowCount) {  // room only: a row is zeroed when a lane first writes it (rowToWrite)
        if (group.rows.size() < static_cast<std::size_t>(rows)) group.rows.resize(static_cast<std::size_t>(rows));
        group.rowCount = rows;
    }
    if (slotA != 0) last(slotA) = g;
    if (slotB != 0) last(slotB) = g;
    packed.joints.push_back(entry);
}
// [ch11-joint-groups]

void markPackedBuilt(PackedJointRows& packed, int entry, bool built, const Quat& turnA, const Quat& turnB) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    JointLaneGroup& group = packed.groups[static_cast<std::size_t>(joint.group)];
    const unsigned bit = 1u << joint.lane;
    group.builtLanes = built ? group.builtLanes | bit : group.builtLanes & ~bit;
    if (!built) return;
    const auto put = [lane = joint.lane](PackQuat<kWideLanes>& to, const Quat& q) {
        to.x[lane] = q.x();
        to.y[lane] = q.y();
        to.z[lane] = q.z();
        to.w[lane] = q.w();
    };
    put(group.builtA, turnA);
    put(group.builtB, turnB);
}

PackedJointRow packedRowOf(const PackedJointRows& packed, int entry, int k) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    const JointLaneGroup& group = packed.groups[static_cast<std::size_t>(joint.group)];
    PackedJointRow row = loadRow(group.rows[static_cast<std::size_t>(k)], joint.lane);
    row.slotA = group.slotA[joint.lane];
    row.slotB = group.slotB[joint.lane];
    return row;
}

void storePackedRow(PackedJointRows& packed, int entry, int k, const PackedJointRow& row) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    storeRow(packed.groups[static_cast<std::size_t>(joint.group)].rows[static_cast<std::size_t>(k)], joint.lane, row,
             joint.keepable);
}

PackedPointBlock packedBlockOf(const PackedJointRows& packed, int entry) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    const JointLaneGroup& group = packed.groups[static_cast<std::size_t>(joint.group)];
    const JointBlockLanes& from = group.block;
    const int lane = joint.lane;
    PackedPointBlock block;
    block.slotA = group.slotA[lane];
    block.slotB = group.slotB[lane];
    block.armA = loadVec(from.armA, lane);
    block.armB = loadVec(from.armB, lane);
    block.mass = loadMat(from.mass, lane);
    block.inverseMassA = from.inverseMassA[lane];
    block.inverseMassB = from.inverseMassB[lane];
    block.inverseInertiaA = loadMat(from.inverseInertiaA, lane);
    block.inverseInertiaB = loadMat(from.inverseInertiaB, lane);
    block.bias = loadVec(from.bias, lane);
    block.impulse = loadVec(from.impulse, lane);
    block.error = loadVec(from.error, lane);
    block.soft = Softness{from.biasRate[lane], from.massScale[lane], from.impulseScale[lane]};
    for (int axis = 0; axis < 3; ++axis) block.fedBack[axis] = from.fedBack[axis][lane] != 0;
    return block;
}

namespace {

// Row k of the group, for a lane to write: the rows past those in use hold the last frame's, so the
// sweeps' reach grows over zeroed rows.
JointRowLanes& rowToWrite(JointLaneGroup& group, int k) {
    for (; group.rowsInUse <= k; ++group.rowsInUse) group.rows[static_cast<std::size_t>(group.rowsInUse)] = JointRowLanes{};
    return group.rows[static_cast<std::size_t>(k)];
}

// Joint `entry`'s rows from `from` on, and its block unless `keepBlock`, zero: what a joint built
// again with fewer rows, or left out, leaves behind.
void clearFrom(PackedJointRows& packed, int entry, int from, bool keepBlock) {
    PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    JointLaneGroup& group = packed.groups[static_cast<std::size_t>(joint.group)];
    for (int k = from; k < joint.rowCount; ++k) zeroRow(group.rows[static_cast<std::size_t>(k)], joint.lane);
    if (joint.hasBlock && !keepBlock) zeroBlock(group.block, joint.lane);
}

}  // namespace

bool writePackedJoint(const JointRowBatch& batch, const std::vector<SolverBody>& bodies,
                      const std::vector<int>& slotOfEntry, PackedJointRows& packed, int entry) {
    PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    const int begin = batch.set.pointBlock ? 3 : 0;
    if (batch.count - begin > joint.rowRoom || (batch.set.pointBlock && !joint.blockRoom)) {
        emptyPackedJoint(packed, entry);
        return false;
    }
    JointLaneGroup& group = packed.groups[static_cast<std::size_t>(joint.group)];
    const int rowsBefore = joint.rowCount;
    const bool blockBefore = joint.hasBlock;
    joint.slotCount = batch.count;
    joint.hasBlock = batch.set.pointBlock;
    if (joint.hasBlock) {
        PackedPointBlock block;
        packBlock(batch, bodies, slotOfEntry, block);
        storeBlock(group.block, joint.lane, block);
    } else if (blockBefore) {
        zeroBlock(group.block, joint.lane);
    }
    joint.rowCount = 0;
    for (int slot = begin; slot < batch.count; ++slot) {
        if (!batch.used[slot]) continue;
        PackedJointRow row;
        packRow(batch.rows[slot], batch.softness[slot], batch.fedBack[slot], batch.kind[slot], batch.error[slot], slot,
                bodies, slotOfEntry, row);
        if (row.effectiveMass == 0) continue;  // chapter 8's sweep skips it too
        storeRow(rowToWrite(group, joint.rowCount), joint.lane, row, joint.keepable);
        ++joint.rowCount;
    }
    for (int k = joint.rowCount; k < rowsBefore; ++k) zeroRow(group.rows[static_cast<std::size_t>(k)], joint.lane);
    return true;
}

// [ch11-distance-row]
bool writeDistanceJoint(const JointDesc& joint, const JointFrame& frame, int entryA, int entryB, Real h,
                        const JointFeedback& feedback, Real& carried, const std::vector<SolverBody>& bodies,
                        const std::vector<int>& slotOfEntry, PackedJointRows& packed, int entry) {
    PackedJoint& packedJoint = packed.joints[static_cast<std::size_t>(entry)];
    if (packedJoint.rowRoom < 1) {
        emptyPackedJoint(packed, entry);
        return false;
    }
    PackedJointRow row;
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
    if (finite != 0) {
        emptyPackedJoint(packed, entry);
        return false;
    }
    row.lower = -kRealMax;
    row.upper = kRealMax;
    row.impulse = std::isfinite(carried) ? std::clamp(carried, row.lower, row.upper) : Real(0);
    row.slot = 0;
    row.slotA = slotOfEntry[static_cast<std::size_t>(entryA)];
    row.slotB = slotOfEntry[static_cast<std::size_t>(entryB)];
    setMoves(bodies[static_cast<std::size_t>(entryA)], bodies[static_cast<std::size_t>(entryB)], row);
    carried = row.impulse;
    if (row.effectiveMass == 0) {  // chapter 8's sweep skips a row without mass too
        emptyPackedJoint(packed, entry);
        packedJoint.slotCount = 1;
        return true;
    }
    packedJoint.slotCount = 1;
    storeRow(rowToWrite(packed.groups[static_cast<std::size_t>(packedJoint.group)], 0), packedJoint.lane, row,
             packedJoint.keepable);
    packedJoint.rowCount = 1;
    return true;
}
// [ch11-distance-row]

void emptyPackedJoint(PackedJointRows& packed, int entry) {
    clearFrom(packed, entry, 0, /*keepBlock=*/false);
    PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    joint.hasBlock = false;
    joint.rowCount = 0;
    joint.slotCount = 0;
}

void refreshPackedFeedback(PackedJointRows& packed, int entry, const JointFeedback& feedback, Real h) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    JointLaneGroup& group = packed.groups[static_cast<std::size_t>(joint.group)];
    const int lane = joint.lane;
    if (joint.hasBlock) {
        JointBlockLanes& block = group.block;
        Softness soft{block.biasRate[lane], block.massScale[lane], block.impulseScale[lane]};
        for (int axis = 0; axis < 3; ++axis) {
            bool fedBack = block.fedBack[axis][lane] != 0;
            jointRowFeedback(at(block.bias, axis, lane), soft, fedBack, JointRowKind::Equality, at(block.error, axis, lane),
                             /*movesPoints=*/true, feedback, h);
            block.fedBack[axis][lane] = fedBack ? 1 : 0;
        }
        block.biasRate[lane] = soft.biasRate;
        block.massScale[lane] = soft.massScale;
        block.impulseScale[lane] = soft.impulseScale;
    }
    for (int k = 0; k < joint.rowCount; ++k) {
        JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
        Softness soft{row.biasRate[lane], row.massScale[lane], row.impulseScale[lane]};
        bool fedBack = row.fedBack[lane] != 0;
        jointRowFeedback(row.bias[lane], soft, fedBack, row.kind[lane], row.error[lane], !row.turnOnly[lane], feedback, h);
        row.fedBack[lane] = fedBack ? 1 : 0;
        row.biasRate[lane] = soft.biasRate;
        row.massScale[lane] = soft.massScale;
        row.impulseScale[lane] = soft.impulseScale;
    }
}

void keepPackedImpulsesOf(const PackedJointRows& packed, int entry, std::vector<JointImpulses>& carried) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    const JointLaneGroup& group = packed.groups[static_cast<std::size_t>(joint.group)];
    JointImpulses& impulses = carried[static_cast<std::size_t>(joint.joint)];
    if (joint.hasBlock)
        for (int axis = 0; axis < 3; ++axis) impulses.slot[axis] = at(group.block.impulse, axis, joint.lane);
    for (int k = 0; k < joint.rowCount; ++k) {
        const JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
        impulses.slot[row.slot[joint.lane]] = row.impulse[joint.lane];
    }
}

void keepPackedImpulses(const PackedJointRows& packed, std::vector<JointImpulses>& carried) {
    for (std::size_t entry = 0; entry < packed.joints.size(); ++entry)
        keepPackedImpulsesOf(packed, static_cast<int>(entry), carried);
}

void resetPackedImpulses(PackedJointRows& packed, std::vector<JointImpulses>& carried) {
    for (const PackedJoint& joint : packed.joints) {
        JointLaneGroup& group = packed.groups[static_cast<std::size_t>(joint.group)];
        if (joint.hasBlock)
            for (int axis = 0; axis < 3; ++axis) at(group.block.impulse, axis, joint.lane) = 0;
        for (int k = 0; k < joint.rowCount; ++k) group.rows[static_cast<std::size_t>(k)].impulse[joint.lane] = 0;
        for (int slot = 0; slot < joint.slotCount; ++slot) carried[static_cast<std::size_t>(joint.joint)].slot[slot] = 0;
    }
}

}  // namespace stepwise
