#include "app/runner.h"

#include "world/scene.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>

#ifdef _WIN32
#include <io.h>
#define STEPWISE_ISATTY _isatty
#define STEPWISE_FILENO _fileno
#else
#include <unistd.h>
#define STEPWISE_ISATTY isatty
#define STEPWISE_FILENO fileno
#endif

namespace stepwise {

std::string engineVersion() {
#ifdef STEPWISE_DOUBLE
    return std::string("stepwise ") + STEPWISE_VERSION + " (double)";
#else
    return std::string("stepwise ") + STEPWISE_VERSION + " (float)";
#endif
}

static bool stateIsFinite(const World& world, std::string& badBody) {
    for (const Motion& motion : world.motions) {
        const Body& body = world.bodies[motion.bodyIndex];
        if (!body.transform.position.allFinite() || !body.transform.rotation.coeffs().allFinite() ||
            !motion.linearVelocity.allFinite() || !motion.angularVelocity.allFinite()) {
            badBody = body.name;
            return false;
        }
    }
    return true;
}

RunStats runHeadless(World& world, Pipeline& pipeline, const Registry& registry, const RunOptions& options) {
    RunStats stats;
    stats.pipeline = pipeline.enabledStageNames();
    stats.initialEnergy = computeEnergy(world);
    const PenetrationProbe* probe = registry.penetrationProbe(options.maxChapter);
    stats.penetrationMeasured = probe != nullptr;
    if (!world.joints.empty() && !pipeline.find("joints"))
        stats.warnings.push_back("the scene has " + std::to_string(world.joints.size()) +
                                 " joint(s) but no stage of this engine solves joints yet (chapter 8, to come); they are ignored");
    const int chapterInUse = std::min(options.maxChapter, registry.lastChapter());
    for (const SettingUse& use : settingUses())
        if (use.chapter > chapterInUse)
            stats.unusedSettings.push_back(std::string(use.key) + " (chapter " + std::to_string(use.chapter) +
                                           (use.chapter > registry.lastChapter() ? ", to come)" : ")"));
    const bool showProgress = options.progress && STEPWISE_ISATTY(STEPWISE_FILENO(stderr));
    std::map<std::string, double> stageTotals;
    for (long frame = 0; frame < options.frames; ++frame) {
        pipeline.step(world);
        stats.stepMs.push_back(pipeline.lastStepMs());
        for (const Stage& stage : pipeline.stages())
            if (stage.enabled) stageTotals[stageGroup(stage.name)] += stage.lastMs;
        ++stats.frames;
        if (probe) stats.maxPenetration = std::max(stats.maxPenetration, static_cast<double>(probe->measure(world)));
        int contactPoints = 0;
        for (const Contact& contact : world.contacts) contactPoints += contact.pointCount;
        stats.maxContacts = std::max(stats.maxContacts, contactPoints);
        std::string badBody;
        if (!stateIsFinite(world, badBody)) {
            stats.warnings.push_back("frame " + std::to_string(frame + 1) + ": body '" + badBody +
                                     "' became non-finite; the run stopped (the step is unstable for this scene)");
            break;
        }
        if (showProgress && (frame % 50 == 0 || frame + 1 == options.frames))
            std::fprintf(stderr, "\r  frame %ld/%ld", frame + 1, options.frames);
    }
    if (showProgress) std::fprintf(stderr, "\n");
    for (const auto& [group, total] : stageTotals) stats.stageMeanMs[group] = stats.frames ? total / stats.frames : 0;
    stats.finalEnergy = computeEnergy(world);
    return stats;
}

void printSummary(std::ostream& out, const World& world, const RunStats& stats) {
    out << "scene      " << world.name << " (" << world.bodies.size() << " bodies, " << world.dynamicBodyCount()
        << " dynamic)\n";
    out << "frames     " << stats.frames << " at dt " << world.settings.dt << " s\n";
    out << "step       " << std::fixed << std::setprecision(4) << median(stats.stepMs) << " ms median\n";
    out << "stages     ";
    for (size_t i = 0; i < stats.pipeline.size(); ++i) out << (i ? ", " : "") << stats.pipeline[i];
    out << "\n";
    if (stats.penetrationMeasured)
        out << "max depth  " << std::setprecision(6) << stats.maxPenetration << " m\n";
    else
        out << "max depth  not measured (no collision stage in this chapter)\n";
    out << "energy     " << std::setprecision(6) << stats.initialEnergy.total() << " J -> " << stats.finalEnergy.total()
        << " J\n";
    out.unsetf(std::ios::floatfield);
    if (!stats.unusedSettings.empty()) {
        out << "not used   ";
        for (size_t i = 0; i < stats.unusedSettings.size(); ++i) out << (i ? ", " : "") << stats.unusedSettings[i];
        out << "\n";
    }
    for (const std::string& warning : stats.warnings) out << "warning    " << warning << "\n";
}

static bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

World loadSceneOrBuiltin(const Registry& registry, const std::string& nameOrPath) {
    if (const SceneEntry* entry = registry.findScene(nameOrPath)) {
        World world = entry->build();
        world.name = entry->name;
        return world;
    }
    if (endsWith(nameOrPath, ".json") || std::ifstream(nameOrPath).good()) return loadSceneFile(nameOrPath);
    throw SceneError("", "'" + nameOrPath + "' is neither a scene file nor a built-in scene (see `stepwise scenes`)");
}

}  // namespace stepwise
