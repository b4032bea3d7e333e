#pragma once
// One lane of the joints' lane groups (packed_joint_rows.h) as one row or block: the scalar work
// (building, feedback, impulses back, tests) reads and writes a joint's lane through these; the
// sweeps read the lanes whole (packed_joint_sweep.cpp).

#include "11_wide_solve/packed_joint_rows.h"

namespace stepwise {

/// Component `axis` of lane `lane`.
Real& laneComponent(PackVec3<kWideLanes>& v, int axis, int lane);
Real laneComponent(const PackVec3<kWideLanes>& v, int axis, int lane);

/// Row `row` into lane `lane` (`keepable`: the substeps move its error), and back.
void storeRow(JointRowLanes& to, int lane, const PackedJointRow& row, bool keepable);
PackedJointRow loadRow(const JointRowLanes& from, int lane);
/// A row's kind into lane `lane`, with what its feedback's case and cap read of it: `turnOnly`, no
/// linear part; `keepable`, the substeps move its error.
void storeRowKind(JointRowLanes& to, int lane, JointRowKind kind, bool turnOnly, bool keepable);

/// A point block into lane `lane`.
void storeBlock(JointBlockLanes& to, int lane, const PackedPointBlock& block);

/// Row k of the group, for a lane to write: the rows past those in use hold the last frame's, so
/// the sweeps' reach grows over zeroed rows.
JointRowLanes& rowToWrite(JointLaneGroup& group, int k);

/// Every field of the lane zero: no mass, no Jacobian, no impulse; the sweeps change nothing by it.
void zeroRow(JointRowLanes& to, int lane);
void zeroBlock(JointBlockLanes& to, int lane);

}  // namespace stepwise
