#pragma once
// Record a run, replay it exactly. A recording is the scene as the run began (the scene format
// itself), the chapter whose pipeline ran it, the hand edits with their frames, one state hash
// per frame, and the run report at the end. The engine is deterministic (docs/reliability.md),
// so a replay that loads the scene, applies the same edits at the same frames and steps the same
// pipeline must meet every hash; the first frame that does not is where the two runs part.

#include "09_debug/body_edit.h"
#include "app/registry.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stepwise {

class DebugSession;

/// One body's state to the bit: what the scene format, written for people, rounds (a rotation is
/// renormalised when read, a hull's inertia summed again from its vertices), the recording keeps
/// exactly, so a replay starts from the very bits the recorded run did.
struct ExactBodyState {
    Transform transform;
    Vec3 linearVelocity = Vec3::Zero();
    Vec3 angularVelocity = Vec3::Zero();
    Real mass = 0, inverseMass = 0;
    Vec3 localCenter = Vec3::Zero();
    Mat3 inertiaLocal = Mat3::Zero(), inverseInertiaLocal = Mat3::Zero();
};

// [ch09-recording]
struct Recording {
    int chapter = 0;                          // the pipeline: registry.makePipeline(scene, chapter)
    std::string sceneJson;                    // the scene at the start (saveSceneToString)
    std::vector<ExactBodyState> start;        // every body's exact state at the start
    std::vector<BodyEdit> edits;              // in frame order
    std::vector<std::uint64_t> frameHashes;   // stateHash after each frame, frame 1 first
    std::vector<std::vector<std::uint32_t>> bodyHashes;  // per frame, bodyStateHash of each body
                                                         // (optional: the demo's recordings leave it empty)
    std::string reportJson;                   // the run report (may be empty: the demo's recordings)
};
// [ch09-recording]

/// The recording of a debug session's live frames so far.
Recording recordingOf(const DebugSession& session, int chapter);

/// Runs a scene (file or built-in name) for `frames` frames through the chapter's pipeline and
/// records it, report included.
Recording recordRun(const Registry& registry, const std::string& sceneNameOrPath, int chapter, long frames);

/// JSON text ("format": "stepwise-recording", docs/scene-format.md) and back. readRecording throws
/// SceneError naming the JSON path of anything malformed.
std::string recordingToJson(const Recording& recording);
Recording recordingFromJson(const std::string& text, const std::string& source = "recording");
Recording readRecordingFile(const std::string& path);
void writeRecordingFile(const std::string& path, const Recording& recording);

/// The world a recording starts from: its scene loaded, then every body set to its exact state.
World startingWorld(const Registry& registry, const Recording& recording);

struct ReplayResult {
    long frames = 0;                 // frames replayed
    long firstMismatch = -1;         // first frame whose hash differs (1-based), -1: all met
    std::uint64_t expectedHash = 0;  // at firstMismatch
    std::uint64_t actualHash = 0;
    int firstBody = -1;              // at firstMismatch, the first body whose state differs (when
                                     // the recording has body hashes), -1: none or not known
    std::string reportJson;          // the replay's own report
    bool reportMatches = false;      // equal to the recording's report, timings and notes aside
};

/// Loads the recording's scene, steps it through its chapter's pipeline applying its edits, and
/// checks every frame's hash. Throws SceneError when the scene or an edit is invalid.
ReplayResult replay(const Registry& registry, const Recording& recording);

/// A report without the parts that differ between identical runs (timing_ms) and between
/// programs (plan notes are the same; engine version kept): what record and replay compare.
std::string comparableReport(const std::string& reportJson);

}  // namespace stepwise
