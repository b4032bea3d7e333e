// Runs of a reference scene by the engine and by the Bullet peer, recorded frame by frame for
// the metrics (runs.h). The recording is outside the timed step in both.
#include "engine/runs.h"

#include "app/registry.h"
#include "world/report.h"

#ifdef STEPWISE_HAVE_BULLET
#include "peers/bullet_peer.h"
#endif

#include <algorithm>
#include <cmath>

namespace stepwise::engine_bench {

namespace {

std::vector<Transform> posesOf(const World& world) {
    std::vector<Transform> poses;
    poses.reserve(world.bodies.size());
    for (const Body& body : world.bodies) poses.push_back(body.transform);
    return poses;
}

bool finite(const std::vector<Transform>& poses) {
    return std::all_of(poses.begin(), poses.end(), [](const Transform& pose) {
        return pose.position.allFinite() && pose.rotation.coeffs().allFinite();
    });
}

/// The deepest overlap left at the end, by the latest chapter's probe (the same for both
/// engines, so Bullet's piles are measured as the engine's are).
double finalPenetration(const World& world) {
    const PenetrationProbe* probe = chapterRegistry().penetrationProbe();
    return probe ? double(probe->measure(world)) : -1.0;
}

double total(const std::vector<double>& values) {
    double sum = 0;
    for (double value : values) sum += value;
    return sum;
}

/// A run's time: its mean step (the whole run, settling and sleeping included: what the user waits for).
double meanStep(const std::vector<double>& stepMs) {
    return total(stepMs) / double(std::max<std::size_t>(1, stepMs.size()));
}

}  // namespace

long framesFor(const World& world, double seconds) {
    return std::max(1L, std::lround(seconds / double(world.settings.dt)));
}

World withKnobs(const World& scene, const EngineKnobs& knobs) {
    World world = scene;
    Settings& s = world.settings;
    if (knobs.dt) s.dt = *knobs.dt;
    if (knobs.substeps) s.substeps = *knobs.substeps;
    if (knobs.iterations) {  // a sweep's count is used as it stands, not planned around
        s.solverIterations = *knobs.iterations;
        s.planIterations = false;
    }
    if (knobs.stabilisation) s.stabilisation = *knobs.stabilisation;
    if (knobs.solver) s.solver = *knobs.solver;
    if (knobs.warmStarting) s.warmStarting = *knobs.warmStarting;
    if (knobs.ccd) s.ccd = *knobs.ccd;
    return world;
}

RunResult runEngine(const World& scene, double seconds) {
    RunResult result;
    World world = scene;
    Pipeline pipeline = chapterRegistry().makePipeline(world);  // plans from the scene, `auto` settings decided here
    result.frames = framesFor(world, seconds);
    result.trajectory.dt = double(world.settings.dt);
    result.trajectory.start = world;
    result.trajectory.poses.reserve(std::size_t(result.frames) + 1);
    result.trajectory.poses.push_back(posesOf(world));
    std::vector<double> stepMs;
    for (long frame = 0; frame < result.frames; ++frame) {
        pipeline.step(world);
        stepMs.push_back(pipeline.lastStepMs());
        result.trajectory.poses.push_back(posesOf(world));
        if (!finite(result.trajectory.poses.back())) {
            result.failure = "blew up: a body became non-finite at frame " + std::to_string(frame + 1);
            break;
        }
    }
    result.trajectory.end = world;
    result.timedRuns.push_back(meanStep(stepMs));
    if (result.failure.empty()) result.trajectory.finalPenetration = finalPenetration(world);
    return result;
}

double timeEngine(const World& scene, long frames) {
    World world = scene;
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    double ms = 0;
    for (long frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        ms += pipeline.lastStepMs();
    }
    return ms / double(std::max(1L, frames));
}

#ifdef STEPWISE_HAVE_BULLET
namespace {
peers::BulletOptions bulletOptions(const PeerKnobs& knobs) {
    peers::BulletOptions options;
    options.solverIterations = knobs.iterations;
    options.substeps = knobs.substeps;
    options.sleeping = true;  // Bullet's own default (the peer's program turns it off to time every body)
    return options;
}
}  // namespace

bool havePeer() { return true; }
std::string peerName() { return peers::bulletVersion(); }

RunResult runPeer(const World& scene, double seconds, const PeerKnobs& knobs) {
    RunResult result;
    result.frames = framesFor(scene, seconds);
    result.trajectory.dt = double(scene.settings.dt);
    result.trajectory.start = scene;
    result.trajectory.poses.push_back(posesOf(scene));
    try {
        const peers::BulletRun run = peers::runBullet(scene, result.frames, bulletOptions(knobs),
                                                      [&](long, const std::vector<Transform>& poses) {
                                                          result.trajectory.poses.push_back(poses);
                                                      });
        result.trajectory.end = peers::worldAfterRun(scene, run);
        result.timedRuns.push_back(meanStep(run.stepMs));
    } catch (const peers::BulletUnsupported& refused) {
        result.failure = std::string("refused: ") + refused.what();
        return result;
    }
    for (const std::vector<Transform>& poses : result.trajectory.poses)
        if (!finite(poses)) {
            result.failure = "blew up: a body became non-finite";
            return result;
        }
    result.trajectory.finalPenetration = finalPenetration(result.trajectory.end);
    return result;
}

double timePeer(const World& scene, long frames, const PeerKnobs& knobs) {
    return meanStep(peers::runBullet(scene, frames, bulletOptions(knobs)).stepMs);
}
#else
bool havePeer() { return false; }
std::string peerName() { return ""; }
RunResult runPeer(const World&, double, const PeerKnobs&) {
    RunResult result;
    result.failure = "refused: this program was built without the Bullet peer";
    return result;
}
double timePeer(const World&, long, const PeerKnobs&) { return 0; }
#endif

}  // namespace stepwise::engine_bench
