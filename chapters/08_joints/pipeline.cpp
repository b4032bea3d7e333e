#include "08_joints/chapter.h"

#include "04_pgs/chapter.h"
#include "08_joints/kinematic.h"

#include <algorithm>
#include <array>
#include <memory>
#include <string>

namespace stepwise {

Pipeline makeChapter08Pipeline(const World& world) { return makeChapter08Pipeline(world, JointOptions{}); }

Pipeline makeChapter08Pipeline(const World& world, const JointOptions& options) {
    return makeChapter08Pipeline(world, options, makeChapter07Pipeline(world));
}

namespace {

// Per body, the bodies its joints hold it to without collision (CSR: partners of body b are
// partner[start[b]] to partner[start[b + 1]]). A candidate pair reads the shorter list, a few
// entries in a ragdoll, where a binary search among every joint's pair costs ten unpredictable
// branches a candidate.
struct JointedPartners {
    std::vector<int> start, partner;

    JointedPartners() = default;
    explicit JointedPartners(const World& world) {
        const auto count = static_cast<int>(world.bodies.size());
        const auto valid = [count](const JointDesc& joint) {
            return !joint.collideConnected && joint.bodyA >= 0 && joint.bodyB >= 0 && joint.bodyA < count &&
                   joint.bodyB < count;
        };
        start.assign(static_cast<std::size_t>(count) + 1, 0);
        for (const JointDesc& joint : world.joints)
            if (valid(joint)) {
                ++start[static_cast<std::size_t>(joint.bodyA) + 1];
                ++start[static_cast<std::size_t>(joint.bodyB) + 1];
            }
        for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
        partner.resize(static_cast<std::size_t>(start.back()));
        std::vector<int> next(start.begin(), start.end() - 1);
        for (const JointDesc& joint : world.joints)
            if (valid(joint)) {
                partner[static_cast<std::size_t>(next[static_cast<std::size_t>(joint.bodyA)]++)] = joint.bodyB;
                partner[static_cast<std::size_t>(next[static_cast<std::size_t>(joint.bodyB)]++)] = joint.bodyA;
            }
    }

    int degree(int body) const { return start[static_cast<std::size_t>(body) + 1] - start[static_cast<std::size_t>(body)]; }

    /// Whether a joint holds bodies a and b together (false for any index outside the World).
    bool joined(int a, int b) const {
        const auto bodies = static_cast<int>(start.size()) - 1;
        if (a < 0 || b < 0 || a >= bodies || b >= bodies) return false;
        if (degree(b) < degree(a)) std::swap(a, b);
        const auto first = partner.begin() + start[static_cast<std::size_t>(a)];
        return std::find(first, first + degree(a), b) != first + degree(a);
    }
};

}  // namespace

Real measureDeepestCollidingPenetration(const World& world) {
    const JointedPartners jointed(world);
    if (jointed.partner.empty()) return measureDeepestPenetration(world);
    return measureDeepestPenetrationAmong(world, [&](int bodyA, int bodyB) { return !jointed.joined(bodyA, bodyB); });
}

namespace {

/// The partners kept from frame to frame by the pipeline's stage: made again only where the
/// joints' pairs or the body count change, which one pass over the joints tells; making them
/// costs that pass twice and three allocations every frame of a ragdoll field.
class JointedPartnersCache {
public:
    const JointedPartners& of(const World& world) {
        if (!matches(world)) {
            bodyCount_ = world.bodies.size();
            pairs_.clear();
            for (const JointDesc& joint : world.joints) pairs_.push_back(keyOf(joint));
            partners_ = JointedPartners(world);
        }
        return partners_;
    }

private:
    using Key = std::array<int, 3>;  // the bodies, and whether the joint lets them collide
    static Key keyOf(const JointDesc& joint) { return {joint.bodyA, joint.bodyB, joint.collideConnected ? 1 : 0}; }
    bool matches(const World& world) const {
        if (world.bodies.size() != bodyCount_ || world.joints.size() != pairs_.size()) return false;
        for (std::size_t i = 0; i < pairs_.size(); ++i)
            if (keyOf(world.joints[i]) != pairs_[i]) return false;
        return true;
    }
    std::size_t bodyCount_ = 0;
    std::vector<Key> pairs_;
    JointedPartners partners_;
};

void dropPairsOf(World& world, const JointedPartners& jointed) {
    if (jointed.partner.empty()) return;
    std::vector<BodyPair>& pairs = world.candidatePairs;
    pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                               [&](const BodyPair& pair) { return jointed.joined(pair.bodyA, pair.bodyB); }),
                pairs.end());
}

}  // namespace

void dropJointedPairs(World& world) {
    if (world.joints.empty()) return;
    dropPairsOf(world, JointedPartners(world));
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
        connected.run = [partners = std::make_shared<JointedPartnersCache>()](World& stepWorld, Real) {
            if (!stepWorld.joints.empty()) dropPairsOf(stepWorld, partners->of(stepWorld));
        };
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
