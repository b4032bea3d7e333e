#pragma once
// Headless runs: step a world through a pipeline, collect RunStats, print a summary.
// Used by `stepwise run`, the headless chNN_demo programs, tests and benchmarks.

#include "app/registry.h"
#include "world/report.h"

#include <functional>
#include <iosfwd>
#include <string>

namespace stepwise {

struct RunOptions {
    long frames = 600;
    int maxChapter = 99;           // use the pipeline of this chapter (default: the latest)
    bool progress = false;         // progress line on stderr (only when it is a terminal)
    /// Called before each frame's step and after it (chapter 9's recordings apply hand edits
    /// before a frame and hash the state after it). A throw from either ends the run.
    std::function<void(World& world)> beforeFrame;
    std::function<void(World& world)> afterFrame;
};

/// Runs `frames` frames and measures them. The world is advanced in place.
RunStats runHeadless(World& world, Pipeline& pipeline, const Registry& registry, const RunOptions& options);

/// Prints the short summary: frames, median ms/step, stages, max penetration, energy.
void printSummary(std::ostream& out, const World& world, const RunStats& stats);

/// Resolves "<file.json>" or a built-in scene name. Throws SceneError when neither.
World loadSceneOrBuiltin(const Registry& registry, const std::string& nameOrPath);

/// True when standard error is a terminal: progress lines are for people, not for logs.
bool stderrIsTerminal();

/// "stepwise 0.1.0 (float)".
std::string engineVersion();

}  // namespace stepwise
