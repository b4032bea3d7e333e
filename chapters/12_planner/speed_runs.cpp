// The runs of `stepwise bench speed` (speed_runs.h): chapter 12's step frame by frame on a copy of
// a scene, measuring poses, contacts and joints as it goes, alone or beside the peer.
#include "12_planner/speed_runs.h"

#include "12_planner/contact_truth.h"
#include "app/peer.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace stepwise::speed_bench {

namespace {

Real horizontalMove(const Transform& from, const Transform& to) {
    const Vec3 moved = to.position - from.position;
    return math::hypot(moved.x(), moved.z());
}

void measurePoses(const World& start, const std::vector<Transform>& poses, Measurement& measured) {
    measured.lowest = kRealMax;
    for (std::size_t i = 0; i < start.bodies.size(); ++i) {
        if (start.bodies[i].type != BodyType::Dynamic) continue;
        measured.maxSideways = std::max(measured.maxSideways, horizontalMove(start.bodies[i].transform, poses[i]));
        measured.lowest = std::min(measured.lowest, poses[i].position.y());
    }
}

/// Frames after which a scene counts as landed: five seconds.
constexpr long kSettledFrom = 300;
/// The bench's scenes step at 60 Hz.
constexpr long kFramesASecond = 60;

/// Chapter 12 stepping a copy of `start` one frame at a time (so that the peer's frames can
/// alternate with its own, runBeside), measuring as it goes.

class EngineRun {
public:
    /// `profile`: the fast solve reads the clock between its phases (solvePhases), a few times a
    /// substep, which costs a small scene's frame several percent: the timed runs leave it off.
    EngineRun(const World& start, SpeedOptions options, long frames, long timedFrom, bool profile = false)
        : start_(start), world_(start), options_(profile ? withProfile(options) : options), pipeline_(makeChapter12Pipeline(world_, options_)),
          timedFrom_(timedFrom), lastFrame_(frames - 1), allJoints_(start.joints.size()) {
        std::iota(allJoints_.begin(), allJoints_.end(), 0);
    }

    void step(long frame) {
        if (frame == timedFrom_ && options_.profile) *options_.profile = FastSolveStats{};
        pipeline_.step(world_);
        ++frames_;
        if (!world_.joints.empty()) {
            const JointErrorSummary error = largestJointError(world_, allJoints_);
            // Each second's largest gap: a swinging chain parts most while it swings hardest, and
            // its last second alone is one draw of a chaotic swing (bench/results/joint-damping.txt).
            const auto second = static_cast<std::size_t>(frame / kFramesASecond);
            if (secondGaps_.size() <= second) secondGaps_.resize(second + 1, 0);
            secondGaps_[second] = std::max(secondGaps_[second], error.position);
            if (frame + kFramesASecond >= lastFrame_) {  // the last second: settled joints
                measured_.jointError.position = std::max(measured_.jointError.position, error.position);
                measured_.jointError.angle = std::max(measured_.jointError.angle, error.angle);
            }
        }
        // The deepest contact from the fifth second on (the last frame of a shorter run): what is
        // left once a pile has landed.
        if (frame >= std::min(kSettledFrom, lastFrame_))
            for (const Contact& contact : world_.contacts)
                for (int i = 0; i < contact.pointCount; ++i)
                    measured_.maxPenetration = std::max(measured_.maxPenetration, contact.points[i].depth);
        if (frame < timedFrom_) return;
        measured_.jointsBuilt += world_.step.solver.jointsBuilt;
        measured_.jointsKept += world_.step.solver.jointsKept;
        stepMs_.push_back(pipeline_.lastStepMs());
        if (!pipeline_.lastStepTimedStages()) return;  // stages are timed one frame in eight
        for (const Stage& stage : pipeline_.stages()) measured_.stageMs[stageGroup(stage.name)] += stage.lastMs;
        ++stageTimedFrames_;
    }

    Measurement finish() {
        const double timed = static_cast<double>(std::max<std::size_t>(1, stepMs_.size()));
        for (auto& [group, ms] : measured_.stageMs) ms /= static_cast<double>(std::max<long>(1, stageTimedFrames_));
        FastSolveStats& phases = measured_.solvePhases;
        if (options_.profile) phases = *options_.profile;
        for (double& ms : phases.phaseMs) ms /= timed;
        measured_.stepMs = spreadOf(stepMs_);
        measured_.frames = frames_;
        std::vector<Transform> poses;
        for (const Body& body : world_.bodies) poses.push_back(body.transform);
        measurePoses(start_, poses, measured_);
        for (const Motion& motion : world_.motions) measured_.sleeping += motion.asleep ? 1 : 0;
        if (!secondGaps_.empty()) {
            Real sum = 0;
            for (const Real gap : secondGaps_) sum += gap;
            measured_.jointGapMean = sum / static_cast<Real>(secondGaps_.size());
        }
        return measured_;
    }

private:
    static SpeedOptions withProfile(SpeedOptions options) {
        options.profile = std::make_shared<FastSolveStats>();
        return options;
    }
    const World& start_;
    World world_;
    SpeedOptions options_;
    Pipeline pipeline_;
    long timedFrom_;
    long lastFrame_;
    std::vector<int> allJoints_;
    long frames_ = 0;
    long stageTimedFrames_ = 0;
    std::vector<double> stepMs_;
    std::vector<Real> secondGaps_;  // m, the largest anchor gap in each second of the run so far
    Measurement measured_;
};

Measurement peerMeasurement(const World& start, const PeerRun& run, long frames, long timedFrom) {
    Measurement measured;
    std::vector<double> stepMs(run.stepMs.begin() + std::min<long>(timedFrom, static_cast<long>(run.stepMs.size())),
                               run.stepMs.end());
    measured.stepMs = spreadOf(stepMs);
    measured.frames = frames;
    measurePoses(start, run.finalPoses, measured);
    return measured;
}

/// Chapter 10 and the peer on the same scene, taking turns of kFramesATurn frames: each engine's
/// frames are timed alone, and the other's turn runs between two of its turns. A shared host's
/// speed wanders by a fifth and more within minutes, and two whole runs one after the other
/// measured the host as much as the engines; taking turns, both meet it alike. Frame by frame
/// would not do: each engine would start every frame with the other's data in the caches, which
/// cost chapter 10, whose frame touches every contact record, 15% and Bullet nothing measurable.
constexpr long kFramesATurn = 30;

}  // namespace

Measurement runEngine(const World& start, const SpeedOptions& options, long frames, long timedFrom, bool profile) {
    EngineRun run(start, options, frames, timedFrom, profile);
    for (long frame = 0; frame < frames; ++frame) run.step(frame);
    return run.finish();
}

/// Frames until every dynamic body of `start` sleeps, stepped by chapter 12 with sleeping on; at
/// most `most`.
long framesUntilAsleep(const World& start, long most) {
    World world = start;
    Pipeline pipeline = makeChapter12Pipeline(world, SpeedOptions{});
    const int bodies = world.dynamicBodyCount();
    for (long frame = 1; frame <= most; ++frame) {
        pipeline.step(world);
        int asleep = 0;
        for (const Motion& motion : world.motions) asleep += motion.asleep ? 1 : 0;
        if (asleep == bodies) return frame;
    }
    return most;
}



std::pair<Measurement, Measurement> runBeside(const World& start, const SpeedOptions& options, long frames, long timedFrom) {
    EngineRun engine(start, options, frames, timedFrom);
    long engineFrames = 0;
    const PeerRun peer = peerEngine().run(start, frames, [&](long peerFrame, const std::vector<Transform>&) {
        if ((peerFrame + 1) % kFramesATurn != 0 && peerFrame + 1 != frames) return;
        while (engineFrames <= peerFrame) engine.step(engineFrames++);
    });
    return {engine.finish(), peerMeasurement(start, peer, frames, timedFrom)};
}

}  // namespace stepwise::speed_bench
