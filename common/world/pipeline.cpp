#include "world/pipeline.h"

#include <algorithm>
#include <chrono>

namespace stepwise {

std::string stageName(const char* group, const std::string& variant) { return std::string(group) + ":" + variant; }

std::string stageGroup(const std::string& stageName) {
    return stageName.substr(0, stageName.find(':'));
}

static bool matches(const Stage& stage, const std::string& nameOrGroup) {
    return stage.name == nameOrGroup || stageGroup(stage.name) == nameOrGroup;
}

void Pipeline::add(Stage stage) { stages_.push_back(std::move(stage)); }

void Pipeline::insertBefore(const std::string& group, Stage stage) {
    auto at = std::find_if(stages_.begin(), stages_.end(), [&](const Stage& s) { return matches(s, group); });
    stages_.insert(at, std::move(stage));
}

void Pipeline::replaceOrAdd(Stage stage) {
    if (Stage* existing = find(stageGroup(stage.name)))
        *existing = std::move(stage);
    else
        add(std::move(stage));
}

Stage* Pipeline::find(const std::string& nameOrGroup) {
    for (Stage& stage : stages_)
        if (matches(stage, nameOrGroup)) return &stage;
    return nullptr;
}

const Stage* Pipeline::find(const std::string& nameOrGroup) const {
    return const_cast<Pipeline*>(this)->find(nameOrGroup);
}

bool Pipeline::remove(const std::string& nameOrGroup) {
    auto at = std::find_if(stages_.begin(), stages_.end(), [&](const Stage& s) { return matches(s, nameOrGroup); });
    if (at == stages_.end()) return false;
    stages_.erase(at);
    return true;
}

// [foundation-pipeline-step]
void Pipeline::step(World& world) {
    using Clock = std::chrono::steady_clock;
    const int substeps = std::max(1, world.settings.substeps);
    const Real dt = world.settings.dt / static_cast<Real>(substeps);
    const bool timeStages = stepsTaken_++ % stageTimingPeriod_ == 0;
    if (timeStages)
        for (Stage& stage : stages_) stage.lastMs = 0;
    const auto frameStart = Clock::now();
    // One clock read per stage: a stage's time runs from the previous one's end.
    auto stageStart = frameStart;
    world.step.substepCount = substeps;
    for (int substep = 0; substep < substeps; ++substep) {
        world.step.substep = substep;
        for (Stage& stage : stages_) {
            if (!stage.enabled) continue;
            if (stage.frequency == StageFrequency::FrameStart && substep != 0) continue;
            if (stage.frequency == StageFrequency::FrameEnd && substep != substeps - 1) continue;
            stage.run(world, dt);
            if (!timeStages) continue;
            const auto stageEnd = Clock::now();
            stage.lastMs += std::chrono::duration<double, std::milli>(stageEnd - stageStart).count();
            stageStart = stageEnd;
        }
    }
    if (timeStages) {
        for (Stage& stage : stages_) {
            if (!stage.enabled) continue;
            stage.totalMs += stage.lastMs;
            ++stage.runs;
        }
    }
    lastStepTimedStages_ = timeStages;
    world.step.substep = 0;
    lastStepMs_ = std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
    world.time += world.settings.dt;
    ++world.frame;
}
// [foundation-pipeline-step]

std::vector<std::string> Pipeline::enabledStageNames() const {
    std::vector<std::string> names;
    for (const Stage& stage : stages_)
        if (stage.enabled) names.push_back(stage.name);
    return names;
}

}  // namespace stepwise
