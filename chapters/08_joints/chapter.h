#pragma once
// Chapter 8's pipeline: chapter 7's, with the scene's joints solved together with the contacts
// (joint_solver.h), the pairs a joint connects kept out of the narrowphase (unless the joint says
// they collide), and kinematic bodies driven along their paths (kinematic.h). A scene without
// joints or paths gets chapter 7's pipeline, and the run report says why.

#include "07_ccd/chapter.h"
#include "08_joints/joint_solver.h"
#include "world/pipeline.h"

namespace stepwise {

struct JointOptions {
    JointOrder order = kDefaultJointOrder;
    JointFeedback::Kind feedback = JointFeedback::Kind::Soft;   // Baumgarte: the rigid rows the page measures
    bool relaxOnBiasedRows = false;   // JointConstraints' option (chapter 10 turns it on)
};

Pipeline makeChapter08Pipeline(const World& world);
Pipeline makeChapter08Pipeline(const World& world, const JointOptions& options);
/// The same on a chapter 7 pipeline made with other options.
Pipeline makeChapter08Pipeline(const World& world, const JointOptions& options, Pipeline chapter7);

/// Removes from World::candidatePairs the pairs a joint holds together without collide_connected:
/// they overlap at their joints by design, and never collide.
void dropJointedPairs(World& world);

/// Chapter 3's deepest overlap, over the pairs that can collide: the run report's max_penetration.
Real measureDeepestCollidingPenetration(const World& world);

}  // namespace stepwise
