// One lane of the joints' lane groups as one row or block (joint_lane_storage.h), and the
// accessors packed_joint_rows.h gives the scalar work and the tests.
#include "11_wide_solve/joint_lane_storage.h"

namespace stepwise {

Real& laneComponent(PackVec3<kWideLanes>& v, int axis, int lane) { return (axis == 0 ? v.x : axis == 1 ? v.y : v.z)[lane]; }
Real laneComponent(const PackVec3<kWideLanes>& v, int axis, int lane) { return (axis == 0 ? v.x : axis == 1 ? v.y : v.z)[lane]; }

namespace {

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

}  // namespace

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
    to.slot[lane] = row.slot;
    storeRowKind(to, lane, row.kind, row.turnOnly, keepable);
}

void storeRowKind(JointRowLanes& to, int lane, JointRowKind kind, bool turnOnly, bool keepable) {
    to.advances[lane] = keepable && kind != JointRowKind::Free ? 1 : 0;  // a motor's bias is a speed
    to.isSpring[lane] = kind == JointRowKind::Spring ? 1 : 0;
    to.isLimit[lane] = kind == JointRowKind::Limit ? 1 : 0;
    to.isEquality[lane] = kind == JointRowKind::Equality ? 1 : 0;
    to.pushCap[lane] = turnOnly ? kMaxJointPushOutTurn : kMaxJointPushOutSpeed;
    to.kind[lane] = kind;
    to.turnOnly[lane] = turnOnly;
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

void zeroRow(JointRowLanes& to, int lane) {
    storeRow(to, lane, PackedJointRow{}, false);
    to.massScale[lane] = 0;
}
void zeroBlock(JointBlockLanes& to, int lane) {
    storeBlock(to, lane, PackedPointBlock{});
    to.massScale[lane] = 0;
    to.present[lane] = 0;
}


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

}  // namespace stepwise
