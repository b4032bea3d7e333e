// The runs of `stepwise bench joints` (joints_runs.h): a chain or a ragdoll pile built, stepped by
// chapter 8's pipeline with the configuration's solve, and measured frame by frame. Step times are
// the thread's CPU time.
#include "08_joints/joints_runs.h"

#include "06_manifolds/chapter.h"
#include "08_joints/chapter.h"
#include "08_joints/scenes.h"
#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stepwise::joints_bench {

const char* caseName(Case which) {
    switch (which) {
        case Case::Hanging: return "hanging_chain";
        case Case::Swinging: return "swinging_chain";
        case Case::HeavyEnd: return "heavy_end_chain";
        case Case::HeavyEndSwinging: return "heavy_end_swinging";
        case Case::RagdollPile: return "ragdoll_pile";
    }
    return "?";
}

const char* feedbackName(const Config& config) {
    if (config.feedback == JointFeedback::Kind::Baumgarte) return "baumgarte";
    return config.hertzPerRate == kJointHertzPerStepRate ? "soft" : "soft_half_rate";
}

namespace {

// [ch08-bench-variants]
/// Chapter 8's joint passes (JointConstraints, joint_solver.cpp) with the two knobs the engine
/// fixes and the bench varies: how many times each iteration sweeps the joint rows, and the soft
/// rows' frequency as a fraction of the (sub)step rate.
class VariedJoints final : public ExtraConstraints {
public:
    explicit VariedJoints(const Config& config) : config_(config) {}
    bool active(const World& world) const override { return !world.joints.empty(); }
    void prepare(const World& world, const std::vector<SolverBody>& bodies, Real h, bool positionFeedback) override {
        rows_ = JointRows{};  // prepared again for every (sub)step and pass
        JointFeedback feedback = jointFeedback(world.settings, h, config_.feedback);
        feedback.soft = makeSoftness(config_.hertzPerRate / h, kJointDampingRatio, h);
        if (!positionFeedback) feedback.kind = JointFeedback::Kind::None;
        const bool carry = !positionFeedback || world.settings.warmStarting;
        for (int joint : jointSolveOrder(world, config_.order)) appendJointRows(rows_, world, joint, bodies, h, feedback, carry);
    }
    void warmStart(std::vector<SolverBody>& bodies) override {
        for (const ConstraintRow& row : rows_.rows)
            if (row.impulse != 0) applyRowImpulse(row, row.impulse, bodies);
    }
    void iterate(std::vector<SolverBody>& bodies) override {
        for (int sweep = 0; sweep < config_.sweeps; ++sweep)
            for (const JointRowSet& set : rows_.joints) solveJointRows(rows_, set, bodies);
    }
    void store(World& world) const override {
        world.jointImpulses.resize(world.joints.size());
        for (const JointRowSet& set : rows_.joints)
            for (int slot = 0; slot < set.rowCount && slot < JointImpulses::kSlots; ++slot)
                world.jointImpulses[static_cast<std::size_t>(set.joint)].slot[slot] =
                    rows_.rows[static_cast<std::size_t>(set.firstRow + slot)].impulse;
    }

private:
    Config config_;
    JointRows rows_;
};

/// The chapter's pipeline; a varied configuration swaps its solve for one with VariedJoints.
Pipeline pipelineFor(const World& world, const Config& config) {
    Pipeline pipeline = makeChapter08Pipeline(world, JointOptions{config.order, config.feedback});
    if (config.sweeps == 1 && config.hertzPerRate == kJointHertzPerStepRate) return pipeline;
    const bool split = chooseStepOrder(world) == StepOrder::SplitIntegration;
    if (Stage* solve = pipeline.find(stage_group::kSolve))
        solve->run = [split, config](World& stepWorld, Real dt) {
            VariedJoints joints(config);
            runStabilisedSolve(stepWorld, dt, split, &joints);
        };
    return pipeline;
}
// [ch08-bench-variants]

// [ch08-bench-sag]
/// How long soft joints hold a hanging chain at rest, whatever the solver: at rest each row is a
/// spring of stiffness m_eff w^2 (Box2D's soft constraint, w = 2 pi hertz) carrying the weight
/// below it, so it is longer by that weight over m_eff w^2. Summed over the joints, as a fraction
/// of the rest length.
double restingSag(const World& world, const Chain& chain, const Config& config) {
    const double h = double(world.settings.dt) / (config.iterations * config.substeps);
    const double omega = 2 * double(kPi) * double(config.hertzPerRate) / h;
    const auto inverseMass = [&](int body) {
        const Motion* motion = world.motionOf(body);
        return motion ? double(motion->inverseMass) : 0.0;
    };
    double below = 0, sag = 0;  // N of weight below the joint; m
    for (auto joint = chain.joints.rbegin(); joint != chain.joints.rend(); ++joint) {
        const JointDesc& desc = world.joints[static_cast<std::size_t>(*joint)];
        below += double(world.settings.gravity.norm()) / inverseMass(desc.bodyB);
        sag += below * (inverseMass(desc.bodyA) + inverseMass(desc.bodyB)) / (omega * omega);
    }
    return sag / double(chain.restLength);
}
// [ch08-bench-sag]

}  // namespace

// [ch08-bench-run]
/// One case through one configuration for `seconds` of 60 Hz frames.
Outcome run(Case which, const Config& config, double seconds, int ragdolls) {
    World world;
    Chain chain;
    std::vector<int> joints;
    if (which == Case::RagdollPile) {
        world = buildRagdollPile(ragdolls);
        for (int i = 0; i < static_cast<int>(world.joints.size()); ++i) joints.push_back(i);
    } else {
        ChainSpec spec;
        spec.links = (which == Case::Hanging || which == Case::Swinging) ? 20 : 10;
        spec.endMass = (which == Case::HeavyEnd || which == Case::HeavyEndSwinging) ? 10 : 0;
        if (which == Case::Swinging || which == Case::HeavyEndSwinging) spec.direction = Vec3(1, 0, 0);
        chain = addChain(world, spec);
        joints = chain.joints;
    }
    world.settings.solverIterations = config.iterations;
    world.settings.substeps = config.substeps;
    world.settings.warmStarting = config.warm;
    Outcome outcome;
    if (which == Case::Hanging || which == Case::HeavyEnd) outcome.restingSag = restingSag(world, chain, config);
    Pipeline pipeline = pipelineFor(world, config);
    const int frames = static_cast<int>(std::lround(seconds / double(world.settings.dt)));
    const int measuredFrom = which == Case::RagdollPile ? frames - static_cast<int>(std::lround(1 / double(world.settings.dt))) : 0;
    double cpu = 0;
    int frame = 0;
    for (; frame < frames; ++frame) {
        ThreadStopwatch clock;
        pipeline.step(world);
        cpu += clock.seconds();
        if (frame >= measuredFrom) {
            const JointErrorSummary error = largestJointError(world, joints);
            outcome.error.position = std::max(outcome.error.position, error.position);
            outcome.error.angle = std::max(outcome.error.angle, error.angle);
        }
        if (which == Case::RagdollPile) continue;
        const double stretch = double(chainStretch(world, chain));
        outcome.finalStretch = stretch;
        outcome.largestStretch = std::isnan(outcome.largestStretch) ? stretch : std::max(outcome.largestStretch, stretch);
        if (!std::isfinite(stretch) || stretch > 1) {  // diverged: the rest would measure nothing
            ++frame;
            break;
        }
    }
    outcome.seconds = frame * double(world.settings.dt);
    outcome.stepMs = 1e3 * cpu / std::max(1, frame);
    return outcome;
}
// [ch08-bench-run]

}  // namespace stepwise::joints_bench
