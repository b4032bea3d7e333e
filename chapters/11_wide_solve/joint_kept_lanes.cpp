// Which listed joints keep last substep's rows (joint_kept_lanes.h).
#include "11_wide_solve/joint_kept_lanes.h"

#include <algorithm>

namespace stepwise {

namespace {

// Whether listed joint i's lane is set in `masks` (a bit per lane, a mask per lane group).
bool laneSet(const JointPass& pass, const std::vector<unsigned>& masks, std::size_t i) {
    const PackedJoint& joint = pass.packed.joints[i];
    return (masks[static_cast<std::size_t>(joint.group)] >> joint.lane & 1u) != 0;
}

}  // namespace

bool keptLane(const JointPass& pass, std::size_t i) { return laneSet(pass, pass.keptLanes, i); }

bool handedJoint(const JointPass& pass, std::size_t i) { return laneSet(pass, pass.handedLanes, i); }

// The joints that do not keep their rows this substep, in list order, into pass.notKept; the kept
// ones, most of them, are counted a lane group at a time, not visited one by one (their biases
// are made again with the other kept joints of their group: refreshPackedFeedbackLanes).
void listJointsNotKept(JointPass& pass, bool mayKeep) {
    pass.notKept.clear();
    const std::size_t listed = pass.joints.size();
    if (mayKeep) {
        int kept = 0, rows = 0;
        for (int g = 0; g < pass.packed.groupCount; ++g) {
            const JointLaneGroup& group = pass.packed.groups[static_cast<std::size_t>(g)];
            const unsigned keptLanes = pass.keptLanes[static_cast<std::size_t>(g)];
            for (int lane = 0; lane < group.lanes; ++lane) {
                const int i = group.entry[lane];
                if (keptLanes >> lane & 1u) {
                    rows += pass.packed.joints[static_cast<std::size_t>(i)].slotCount;
                    ++kept;
                } else {
                    pass.notKept.push_back(i);
                }
            }
        }
        if (pass.notKept.size() + static_cast<std::size_t>(kept) == listed) {  // the lanes hold every listed joint
            std::sort(pass.notKept.begin(), pass.notKept.end());
            pass.rowCount += rows;
            pass.jointsKept += kept;
            return;
        }
        pass.notKept.clear();
    }
    for (std::size_t i = 0; i < listed; ++i) {  // joint by joint
        if (mayKeep && keptLane(pass, i)) {
            pass.rowCount += pass.packed.joints[i].slotCount;
            ++pass.jointsKept;
        } else {
            pass.notKept.push_back(static_cast<int>(i));
        }
    }
}

void sizeLaneQueue(JointPass& pass) {
    const auto groups = static_cast<std::size_t>(pass.packed.groupCount);
    pass.lanesToBuild.assign(groups, 0u);
    pass.laneJoints.resize(groups * kWideLanes);
}

}  // namespace stepwise
