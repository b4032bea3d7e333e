#include "08_joints/chapter.h"

#include "04_pgs/chapter.h"
#include "08_joints/kinematic.h"

#include <algorithm>
#include <memory>
#include <string>

namespace stepwise {

Pipeline makeChapter08Pipeline(const World& world) { return makeChapter08Pipeline(world, JointOptions{}); }

Pipeline makeChapter08Pipeline(const World& world, const JointOptions& options) {
    return makeChapter08Pipeline(world, options, makeChapter07Pipeline(world));
}

std::vector<BodyPair> jointedPairs(const World& world) {
    std::vector<BodyPair> jointed;
    for (const JointDesc& joint : world.joints)
        if (!joint.collideConnected)
            jointed.push_back({std::min(joint.bodyA, joint.bodyB), std::max(joint.bodyA, joint.bodyB)});
    std::sort(jointed.begin(), jointed.end());
    return jointed;
}

Real measureDeepestCollidingPenetration(const World& world) {
    const std::vector<BodyPair> jointed = jointedPairs(world);
    if (jointed.empty()) return measureDeepestPenetration(world);
    return measureDeepestPenetrationAmong(world, [&](int bodyA, int bodyB) {
        return !std::binary_search(jointed.begin(), jointed.end(), BodyPair{bodyA, bodyB});
    });
}

void dropJointedPairs(World& world) {
    const std::vector<BodyPair> jointed = jointedPairs(world);
    if (jointed.empty()) return;
    std::vector<BodyPair>& pairs = world.candidatePairs;
    pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                               [&](const BodyPair& pair) {
                                   const BodyPair key{std::min(pair.bodyA, pair.bodyB), std::max(pair.bodyA, pair.bodyB)};
                                   return std::binary_search(jointed.begin(), jointed.end(), key);
                               }),
                pairs.end());
}

// [ch08-pipeline]
Pipeline makeChapter08Pipeline(const World& world, const JointOptions& options, Pipeline chapter7) {
    Pipeline pipeline = std::move(chapter7);
    if (world.joints.empty()) {
        pipeline.setPlanNote(stage_group::kJoints, "off: the scene has no joints");
    } else {
        pipeline.setPlanNote(stage_group::kJoints, "on: " + std::to_string(world.joints.size()) +
                                                       " joint(s) solved with the contacts, " + toString(options.order));
        // Jointed bodies overlap at their joints by design: their pairs leave the candidates
        // before the narrowphase sees them.
        Stage connected;
        connected.name = stageName(stage_group::kJoints, "connected_pairs");
        connected.run = [](World& stepWorld, Real) { dropJointedPairs(stepWorld); };
        if (const Stage* narrowphase = pipeline.find(stage_group::kNarrowphase)) connected.frequency = narrowphase->frequency;
        pipeline.insertBefore(stage_group::kNarrowphase, std::move(connected));
        // The solve now carries the joints' rows beside the contacts'.
        if (Stage* solve = pipeline.find(stage_group::kSolve)) {
            const bool split = chooseStepOrder(world) == StepOrder::SplitIntegration;
            // One JointConstraints for every frame: rebuilt from the World at each prepare, it
            // carries nothing between frames (a copied World steps the same); its rows keep their room.
            solve->run = [split, joints = std::make_shared<JointConstraints>(options.order, options.feedback,
                                                                              options.relaxOnBiasedRows)](
                             World& stepWorld, Real dt) { solveWithJoints(stepWorld, dt, split, *joints); };
        }
    }
    if (world.kinematicPaths.empty()) {
        pipeline.setPlanNote(stage_group::kKinematic, "off: no kinematic body follows a path");
    } else {
        pipeline.setPlanNote(stage_group::kKinematic,
                             "on: " + std::to_string(world.kinematicPaths.size()) + " kinematic path(s)");
        Stage drive;
        drive.name = stageName(stage_group::kKinematic, "paths");
        drive.run = [](World& stepWorld, Real dt) { driveKinematicPaths(stepWorld, dt); };
        std::vector<Stage>& stages = pipeline.stages();
        stages.insert(stages.begin(), std::move(drive));
    }
    return pipeline;
}
// [ch08-pipeline]

}  // namespace stepwise
