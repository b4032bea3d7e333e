#pragma once
// Which listed joints keep last substep's rows: the joints that are not kept (JointPass::keptLanes)
// listed without visiting the kept ones, and whether a joint may keep what the last piece handed
// on (JointPass::handedLanes). joint_pass.cpp's buildJointRows uses them.

#include "11_wide_solve/joint_pass.h"

#include <cstddef>

namespace stepwise {

/// Whether listed joint i may keep the rows the last piece handed on (JointPass::handedLanes).
bool handedJoint(const JointPass& pass, std::size_t i);

/// The joints that do not keep their rows this substep, in list order, into pass.notKept; the
/// kept ones (with `mayKeep`, those of JointPass::keptLanes) are counted into pass.rowCount and
/// pass.jointsKept a lane group at a time.
void listJointsNotKept(JointPass& pass, bool mayKeep);

/// The lane build's queue, a group's lanes each, for the piece's layout.
void sizeLaneQueue(JointPass& pass);

}  // namespace stepwise
