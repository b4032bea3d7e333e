#pragma once
// The runs that golden hashes pin: every built-in scene through the pipeline of its own chapter
// (a later chapter's stages do not change what an earlier chapter's scenes pin), and every scene
// file of scenes/ through the latest chapter's pipeline, for a fixed number of frames.

#include "app/registry.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stepwise::reliability {

constexpr long kGoldenFrames = 240;  // 4 s at 60 Hz: long enough for stacks to settle, bounces to land

struct GoldenRun {
    std::string scene;      // built-in name, or "scenes/<file>.json"
    std::uint64_t hash = 0; // stateHash after kGoldenFrames frames
    std::string skipped;    // why the scene was not run (no hash); empty: it ran
};

/// Which scenes a run covers; the others are listed as skipped.
struct GoldenSelection {
    std::size_t maxBodies = std::size_t(-1);  // more bodies: skipped
    int fromChapter = 0;                      // built-in scenes of earlier chapters: skipped
    int shard = 0, shards = 1;                // only the scenes goldenShards gives to `shard`
    double maxSeconds = -1;                   // >= 0: scenes whose goldenSceneSeconds is above: skipped,
                                              // and the shards dealt from the others
};

/// The built-in scenes in registry order, then the scene files of `sceneFolder` by name.
std::vector<GoldenRun> runGoldenScenes(const Registry& registry, const std::string& sceneFolder,
                                       const GoldenSelection& selection = {});

/// Which of `shards` shards runs each scene (by index in `scenes`): balanced by each scene's
/// measured cost under the sanitizers, longest first into the least loaded shard, so no shard
/// waits on a pile of slow scenes that round-robin dealing would give it. Deterministic.
std::vector<int> goldenShards(const std::vector<std::string>& scenes, int shards);

/// Seconds a scene's golden run took in the sanitizer build (golden_shards.cpp's table);
/// a scene missing from the table counts as a middling one.
double goldenSceneSeconds(const std::string& scene);

/// Runs one scene for `frames` frames through the pipeline of the latest chapter up to
/// `maxChapter` and returns its final state hash.
std::uint64_t finalHash(const Registry& registry, World world, long frames, int maxChapter = 99);

}  // namespace stepwise::reliability
