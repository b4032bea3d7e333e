// Which listed joints keep last substep's rows (joint_kept_lanes.h).
#include "11_wide_solve/joint_kept_lanes.h"

#include <algorithm>

namespace stepwise {

bool handedJoint(const JointPass& pass, std::size_t i) {
    const PackedJoint& joint = pass.packed.joints[i];
    return (pass.handedLanes[static_cast<std::size_t>(joint.group)] >> joint.lane & 1u) != 0;
}

// The joints that do not keep their rows this substep, in list order, into pass.notKept; the kept
// ones, most of them, are counted a lane group at a time, not visited one by one (their biases
// are made again with the other kept joints of their group: refreshPackedFeedbackLanes). The
// layout gives every listed joint one lane (layOutPackedJoints), so the groups cover the list.
void listJointsNotKept(JointPass& pass, bool mayKeep) {
    pass.notKept.clear();
    if (!mayKeep) {  // every joint is built
        for (std::size_t i = 0; i < pass.joints.size(); ++i) pass.notKept.push_back(static_cast<int>(i));
        return;
    }
    for (int g = 0; g < pass.packed.groupCount; ++g) {
        const JointLaneGroup& group = pass.packed.groups[static_cast<std::size_t>(g)];
        const unsigned keptLanes = pass.keptLanes[static_cast<std::size_t>(g)];
        for (int lane = 0; lane < group.lanes; ++lane) {
            const int i = group.entry[lane];
            if (keptLanes >> lane & 1u) {
                pass.rowCount += pass.packed.joints[static_cast<std::size_t>(i)].slotCount;
                ++pass.jointsKept;
            } else {
                pass.notKept.push_back(i);
            }
        }
    }
    std::sort(pass.notKept.begin(), pass.notKept.end());
}

void sizeLaneQueue(JointPass& pass) {
    const auto groups = static_cast<std::size_t>(pass.packed.groupCount);
    pass.lanesToBuild.assign(groups, 0u);
    pass.laneJoints.resize(groups * kWideLanes);
}

}  // namespace stepwise
