#pragma once
// One run of a reference scene, by the engine or by the Bullet peer, recorded for the metrics
// (reference.h) and timed: the knobs a run changes, and what it gives back.

#include "engine/reference.h"

#include <optional>
#include <string>
#include <vector>

namespace stepwise::engine_bench {

/// The engine's knobs that trade time for accuracy, as scene settings; unset: the scene's own.
struct EngineKnobs {
    std::optional<Real> dt;
    std::optional<int> substeps;
    std::optional<int> iterations;
    std::optional<Stabilisation> stabilisation;
    std::optional<SolverKind> solver;
    std::optional<bool> warmStarting;
    std::optional<CcdMode> ccd;
};

/// Bullet's knobs (docs/peers.md); 0: the scene's settings.
struct PeerKnobs {
    int iterations = 0;
    int substeps = 0;
};

struct RunResult {
    Trajectory trajectory;
    double msPerStep = 0;        // the median of timedRuns (set by the bench once the runs have taken their turns)
    std::vector<double> timedRuns;  // each timed run's mean ms per step: the recorded run's, then those timed in turns
    long frames = 0;
    std::string failure;         // non-empty: the run could not be scored (a refusal, a blow-up)
};

/// Frames that cover `seconds` at the world's dt (at least one).
long framesFor(const World& world, double seconds);

/// The scene with the knobs applied to its settings.
World withKnobs(const World& scene, const EngineKnobs& knobs);

/// Steps `scene` with the latest chapter's pipeline (what `stepwise run` does) for `seconds`,
/// recording every frame; the run's time is timedRuns' first.
RunResult runEngine(const World& scene, double seconds);
/// One more run of `frames` frames for its time alone (nothing recorded): its mean ms per step.
double timeEngine(const World& scene, long frames);

/// Whether this program has the Bullet peer (libbullet-dev was found at build time).
bool havePeer();
/// "bullet 3.24", or "" without the peer.
std::string peerName();
/// Steps `scene` with Bullet; failure holds the peer's refusal (a distance joint, ...) verbatim.
RunResult runPeer(const World& scene, double seconds, const PeerKnobs& knobs);
/// timeEngine's twin for the peer (0 without it).
double timePeer(const World& scene, long frames, const PeerKnobs& knobs);

}  // namespace stepwise::engine_bench
