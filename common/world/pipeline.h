#pragma once
// A step is an ordered list of stages. Each chapter's makePipeline() returns the previous
// chapter's list plus its own stage, so a demo can switch the new stage off and compare.

#include "world/world.h"

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace stepwise {

class DebugDraw;

// [foundation-stage-names]
/// The stage groups. A stage is named "group:variant" ("broadphase:sap"); the group keys the
/// timings of run reports and is how chapters find each other's stages, always through these
/// constants, never through a string spelled again.
namespace stage_group {
constexpr const char* kIntegrate = "integrate";
constexpr const char* kBroadphase = "broadphase";
constexpr const char* kNarrowphase = "narrowphase";
constexpr const char* kSolve = "solve";
constexpr const char* kContacts = "contacts";   // contact-cache upkeep after the solves
constexpr const char* kCcd = "ccd";             // continuous collision: times of impact (chapter 7)
constexpr const char* kJoints = "joints";       // joint upkeep: which jointed pairs collide (chapter 8)
constexpr const char* kKinematic = "kinematic"; // kinematic bodies driven along paths (chapter 8)
constexpr const char* kSleep = "sleep";         // islands at rest sleep, touched ones wake (chapter 10)
constexpr const char* kPlan = "plan";           // the frame's substeps, right before the solve (chapters 11, 12)
constexpr const char* kWorldShapes = "worlds";  // contacts with compounds, meshes and height fields (chapter 13)
}  // namespace stage_group

/// "group:variant".
std::string stageName(const char* group, const std::string& variant);
// [foundation-stage-names]

// [foundation-stage-frequency]
/// How often a stage runs when a frame is split into substeps. Collision detection looks at
/// where the bodies are, which only substeps' integration changes: finding contacts once per
/// frame and letting the substeps follow the points on their bodies (anchors) costs one
/// narrowphase instead of n (Box2D v3's soft step does the same). The solve and the
/// integration must run every substep: that is what substepping is. Cache upkeep decides what
/// the next frame remembers, after the last substep's solve.
enum class StageFrequency {
    EverySubstep,   // integration, the solve
    FrameStart,     // once, in the first substep, at its place in the list: collision detection
    FrameEnd,       // once, in the last substep, at its place in the list: cache upkeep
};
// [foundation-stage-frequency]

struct Stage {
    std::string name;      // "group:variant", e.g. "broadphase:sap"; the group keys timings
    std::function<void(World& world, Real dt)> run;
    StageFrequency frequency = StageFrequency::EverySubstep;
    bool enabled = true;
    double lastMs = 0;     // time in the last timed frame (all substeps); see timeStagesEvery
    double totalMs = 0;    // over the timed frames since the pipeline was made
    long runs = 0;         // timed frames in which the stage was enabled
};

/// The part of a stage name before ':' ("narrowphase:gjk" -> "narrowphase").
std::string stageGroup(const std::string& stageName);

class Pipeline {
public:
    void add(Stage stage);
    /// Inserts before the first stage of the given group; appends when there is none.
    void insertBefore(const std::string& group, Stage stage);
    /// Replaces the first stage of the stage's group; appends when there is none.
    void replaceOrAdd(Stage stage);
    /// The first stage whose full name or group matches; nullptr when absent.
    Stage* find(const std::string& nameOrGroup);
    const Stage* find(const std::string& nameOrGroup) const;
    bool remove(const std::string& nameOrGroup);

    /// Advances the world by one frame of settings.dt, in settings.substeps passes.
    void step(World& world);

    std::vector<Stage>& stages() { return stages_; }
    const std::vector<Stage>& stages() const { return stages_; }
    std::vector<std::string> enabledStageNames() const;
    /// Why the planner put a stage in or left it out, by stage group ("ccd" -> "off: no body ..."),
    /// for the run report (plan from the scene, and say so).
    void setPlanNote(const std::string& group, std::string note) { planNotes_[group] = std::move(note); }
    const std::map<std::string, std::string>& planNotes() const { return planNotes_; }
    double lastStepMs() const { return lastStepMs_; }

    /// Every frame is timed whole (lastStepMs), its stages one frame in `frames` (1: every
    /// frame; the default is kStageTimingPeriod). Reading the clock around every stage costs
    /// about 25 ns a read, a sixth of the step of one flying body, so a step measured for speed
    /// should not pay it; the mean time of a stage over the sampled frames is as good a mean.
    void timeStagesEvery(int frames) { stageTimingPeriod_ = std::max(1, frames); }
    /// Whether the last step timed its stages (set Stage::lastMs).
    bool lastStepTimedStages() const { return lastStepTimedStages_; }
    static constexpr int kStageTimingPeriod = 8;

private:
    std::vector<Stage> stages_;
    std::map<std::string, std::string> planNotes_;
    double lastStepMs_ = 0;
    int stageTimingPeriod_ = kStageTimingPeriod;
    long stepsTaken_ = 0;
    bool lastStepTimedStages_ = false;
};

}  // namespace stepwise
