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
    int shard = 0, shards = 1;                // only scenes whose index % shards == shard
};

/// The built-in scenes in registry order, then the scene files of `sceneFolder` by name.
std::vector<GoldenRun> runGoldenScenes(const Registry& registry, const std::string& sceneFolder,
                                       const GoldenSelection& selection = {});

/// Runs one scene for `frames` frames through the pipeline of the latest chapter up to
/// `maxChapter` and returns its final state hash.
std::uint64_t finalHash(const Registry& registry, World world, long frames, int maxChapter = 99);

}  // namespace stepwise::reliability
