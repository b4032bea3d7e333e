#pragma once
// A step is an ordered list of stages. Each chapter's makePipeline() returns the previous
// chapter's list plus its own stage, so a demo can switch the new stage off and compare.

#include "world/world.h"

#include <functional>
#include <string>
#include <vector>

namespace stepwise {

class DebugDraw;

struct Stage {
    std::string name;      // "group:variant", e.g. "broadphase:sap"; the group keys timings
    std::function<void(World& world, Real dt)> run;
    bool enabled = true;
    double lastMs = 0;     // time of the last frame (all substeps)
    double totalMs = 0;    // since the pipeline was made
    long runs = 0;
};

/// The part of a stage name before ':' ("narrowphase:gjk" -> "narrowphase").
std::string stageGroup(const std::string& stageName);

class Pipeline {
public:
    void add(Stage stage);
    /// Inserts before the first stage of the given group; appends when there is none.
    void insertBefore(const std::string& group, Stage stage);
    /// The first stage whose full name or group matches; nullptr when absent.
    Stage* find(const std::string& nameOrGroup);
    const Stage* find(const std::string& nameOrGroup) const;
    bool remove(const std::string& nameOrGroup);

    /// Advances the world by one frame of settings.dt, in settings.substeps passes.
    void step(World& world);

    std::vector<Stage>& stages() { return stages_; }
    const std::vector<Stage>& stages() const { return stages_; }
    std::vector<std::string> enabledStageNames() const;
    double lastStepMs() const { return lastStepMs_; }

private:
    std::vector<Stage> stages_;
    double lastStepMs_ = 0;
};

}  // namespace stepwise
