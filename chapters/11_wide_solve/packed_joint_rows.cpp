#include "11_wide_solve/packed_joint_rows.h"

#include "11_wide_solve/joint_lane_storage.h"

#include "06_manifolds/stabilisation.h"
#include "11_wide_solve/lanes.h"

#include <algorithm>
#include <cstdint>
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

namespace {

// A fresh, empty group after the frame's last.
int openGroup(PackedJointRows& packed) {
    const int g = packed.groupCount++;
    if (packed.groups.size() <= static_cast<std::size_t>(g)) packed.groups.emplace_back();
    JointLaneGroup& fresh = packed.groups[static_cast<std::size_t>(g)];
    fresh.lanes = 0;
    fresh.blocks = false;
    fresh.rowCount = 0;
    fresh.rowsInUse = 0;
    fresh.keepableLanes = fresh.builtLanes = 0;
    for (int lane = 0; lane < kWideLanes; ++lane) fresh.slotA[lane] = fresh.slotB[lane] = 0;
    return g;
}

// Joint `entry` into the next lane of group g, with the room it asks for.
void placeJoint(PackedJointRows& packed, int g, int entry, const JointRoom& room) {
    JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
    PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    joint = PackedJoint{};
    joint.joint = room.joint;
    joint.keepable = room.keepable;
    joint.group = g;
    joint.lane = group.lanes++;
    joint.rowRoom = room.rows;
    joint.blockRoom = room.block;
    group.slotA[joint.lane] = room.slotA;
    group.slotB[joint.lane] = room.slotB;
    group.entry[joint.lane] = entry;
    if (room.block && !group.blocks) group.block = JointBlockLanes{};  // every lane zero until its joint writes it
    group.blocks = group.blocks || room.block;
    if (room.keepable) group.keepableLanes |= 1u << joint.lane;
    if (room.rows > group.rowCount) {  // room only: a row is zeroed when a lane first writes it (rowToWrite)
        if (group.rows.size() < static_cast<std::size_t>(room.rows)) group.rows.resize(static_cast<std::size_t>(room.rows));
        group.rowCount = room.rows;
    }
}

}  // namespace

// [ch11-joint-groups]
void layOutPackedJoints(PackedJointRows& packed, const std::vector<JointRoom>& rooms) {
    packed.clear();
    const std::size_t count = rooms.size();
    packed.joints.resize(count);
    // Each joint's colour: the first that holds neither of its moving bodies (slot 0 does not
    // move, and any number of joints may read it), a bit per colour per body. A joint of a body
    // whose 64 colours are all taken (a hub) gets a colour of its own.
    int slots = 1;
    for (const JointRoom& room : rooms) slots = std::max({slots, room.slotA + 1, room.slotB + 1});
    std::vector<std::uint64_t>& taken = packed.coloursOfSlot;
    taken.assign(static_cast<std::size_t>(slots), 0);
    std::vector<int>& colour = packed.colourOfJoint;
    colour.resize(count);
    int colours = 0, overflow = kMaskedColours;
    for (std::size_t i = 0; i < count; ++i) {
        const JointRoom& room = rooms[i];
        const std::uint64_t held = (room.slotA ? taken[static_cast<std::size_t>(room.slotA)] : 0) |
                                   (room.slotB ? taken[static_cast<std::size_t>(room.slotB)] : 0);
        int c = overflow;
        if (~held != 0) {
            c = 0;
            while (held >> c & 1u) ++c;
            for (const int slot : {room.slotA, room.slotB})
                if (slot != 0) taken[static_cast<std::size_t>(slot)] |= std::uint64_t(1) << c;
        } else {
            ++overflow;
        }
        colour[i] = c;
        colours = std::max(colours, c + 1);
    }
    // The groups: each colour's joints in their order, kWideLanes to a group, colour after colour.
    // The joints of a colour touch different bodies, so however a width cuts a colour into groups
    // the sweep gives the same numbers: the layout's answer does not depend on the lanes.
    std::vector<int>& start = packed.colourStart;
    start.assign(static_cast<std::size_t>(colours) + 1, 0);
    for (const int c : colour) ++start[static_cast<std::size_t>(c) + 1];
    for (int c = 0; c < colours; ++c) start[static_cast<std::size_t>(c) + 1] += start[static_cast<std::size_t>(c)];
    std::vector<int>& order = packed.colourOrder;
    order.resize(count);
    std::vector<int>& fill = packed.colourFill;
    fill.assign(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < count; ++i) order[static_cast<std::size_t>(fill[static_cast<std::size_t>(colour[i])]++)] = static_cast<int>(i);
    int group = -1, groupColour = -1;
    for (const int entry : order) {
        const int c = colour[static_cast<std::size_t>(entry)];
        if (group < 0 || c != groupColour || packed.groups[static_cast<std::size_t>(group)].lanes == kWideLanes) {
            group = openGroup(packed);
            groupColour = c;
        }
        placeJoint(packed, group, entry, rooms[static_cast<std::size_t>(entry)]);
    }
}
// [ch11-joint-groups]

void reservePackedJoint(PackedJointRows& packed, int joint, int rows, bool block, bool keepable, int slotA, int slotB) {
    const int entry = static_cast<int>(packed.joints.size());
    packed.joints.emplace_back();
    placeJoint(packed, openGroup(packed), entry, JointRoom{joint, rows, block, keepable, slotA, slotB});
}

JointRowLanes& rowToWrite(JointLaneGroup& group, int k) {
    for (; group.rowsInUse <= k; ++group.rowsInUse) group.rows[static_cast<std::size_t>(group.rowsInUse)] = JointRowLanes{};
    return group.rows[static_cast<std::size_t>(k)];
}

namespace {

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
            jointRowFeedback(laneComponent(block.bias, axis, lane), soft, fedBack, JointRowKind::Equality, laneComponent(block.error, axis, lane),
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
        for (int axis = 0; axis < 3; ++axis) impulses.slot[axis] = laneComponent(group.block.impulse, axis, joint.lane);
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
            for (int axis = 0; axis < 3; ++axis) laneComponent(group.block.impulse, axis, joint.lane) = 0;
        for (int k = 0; k < joint.rowCount; ++k) group.rows[static_cast<std::size_t>(k)].impulse[joint.lane] = 0;
        for (int slot = 0; slot < joint.slotCount; ++slot) carried[static_cast<std::size_t>(joint.joint)].slot[slot] = 0;
    }
}

}  // namespace stepwise
