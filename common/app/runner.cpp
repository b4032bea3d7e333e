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

// The precision and, where the build calls the C library's sin, exp, ... (the option
// STEPWISE_CROSS_PLATFORM_DETERMINISM off), that too; never the compiler or the platform: every
// build of one precision gives the same bits (docs/reliability.md), so a recording made by one
// replays on another.
std::string engineVersion() {
    const std::string precision = sizeof(Real) == sizeof(double) ? "double" : "float";
    const std::string functions = math::kCrossPlatformDeterminism ? "" : ", C library math";
    return std::string("stepwise ") + STEPWISE_VERSION + " (" + precision + functions + ")";
}

bool stderrIsTerminal() { return STEPWISE_ISATTY(STEPWISE_FILENO(stderr)) != 0; }

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

// Energy of the bodies on each integrator, and of the springs they hang on: what chapter 1's
// side-by-side scene is for (which method keeps its swing). Empty unless the bodies use more
// than one integrator.
static std::vector<RunStats::GroupEnergy> energyByIntegrator(const World& world) {
    const auto integratorOf = [&](int bodyIndex) -> const char* {
        const Motion* motion = world.motionOf(bodyIndex);
        if (!motion || world.bodies[std::size_t(bodyIndex)].type != BodyType::Dynamic) return nullptr;
        return toString(motion->integrator.value_or(world.settings.integrator));
    };
    std::map<std::string, double> energy;
    for (const Motion& motion : world.motions) {
        const char* group = integratorOf(motion.bodyIndex);
        if (!group) continue;
        const Body& body = world.bodies[std::size_t(motion.bodyIndex)];
        const Vec3 angularLocal = body.transform.rotation.toRotationMatrix().transpose() * motion.angularVelocity;
        energy[group] += 0.5 * motion.mass * motion.linearVelocity.squaredNorm() +
                         0.5 * angularLocal.dot(motion.inertiaLocal * angularLocal) -
                         motion.mass * world.settings.gravity.dot(body.transform.apply(motion.localCenter));
    }
    if (energy.size() < 2) return {};
    for (const Spring& spring : world.springs) {
        const char* group = integratorOf(spring.bodyA);
        if (!group) continue;
        const Vec3 endA = world.bodies[std::size_t(spring.bodyA)].transform.apply(spring.localAnchorA);
        const Vec3 endB =
            spring.bodyB < 0 ? spring.anchorB : world.bodies[std::size_t(spring.bodyB)].transform.apply(spring.anchorB);
        const double stretch = (endB - endA).norm() - spring.restLength;
        energy[group] += 0.5 * spring.stiffness * stretch * stretch;
    }
    std::vector<RunStats::GroupEnergy> groups;
    for (const auto& [name, joules] : energy) groups.push_back({name, joules, 0});
    return groups;
}

RunStats runHeadless(World& world, Pipeline& pipeline, const Registry& registry, const RunOptions& options) {
    RunStats stats;
    stats.pipeline = pipeline.enabledStageNames();
    stats.planNotes = pipeline.planNotes();
    stats.initialEnergy = computeEnergy(world);
    const PenetrationProbe* probe = registry.penetrationProbe(options.maxChapter);
    stats.penetrationMeasured = probe != nullptr;
    if (!world.joints.empty() && !pipeline.find(stage_group::kJoints))
        stats.warnings.push_back("the scene has " + std::to_string(world.joints.size()) +
                                 " joint(s) but no stage of this engine solves joints yet (chapter 8" +
                                 (registry.lastChapter() < 8 ? ", to come" : "") + "); they are ignored");
    // Compounds, meshes and height fields are not one convex set: before chapter 13 no stage
    // collides them, and bodies pass through them.
    if (!pipeline.find(stage_group::kWorldShapes))
        for (std::size_t i = 0; i < world.bodies.size(); ++i) {
            const ShapeType type = world.bodies[i].shape.type;
            if (type != ShapeType::Compound && type != ShapeType::Mesh && type != ShapeType::HeightField) continue;
            stats.warnings.push_back("bodies[" + std::to_string(i) + "] (\"" + world.bodies[i].name + "\") is a " +
                                     toString(type) + " but no stage of this engine collides one yet (chapter 13" +
                                     (registry.lastChapter() < 13 ? ", to come" : "") + "); nothing touches it");
        }
    // The settings no stage of the run's chapter reads. A registry without chapters (a probe
    // alone) cannot say which chapter runs, so it lists none rather than every one as to come.
    const int chapterInUse = std::min(options.maxChapter, registry.lastChapter());
    for (const SettingUse& use : settingUses())
        if (chapterInUse > 0 && use.chapter > chapterInUse)
            stats.unusedSettings.push_back(std::string(use.key) + " (chapter " + std::to_string(use.chapter) +
                                           (use.chapter > registry.lastChapter() ? ", to come)" : ")"));
    stats.energyByIntegrator = energyByIntegrator(world);
    for (const Stage& stage : pipeline.stages())
        if (stage.enabled && stageGroup(stage.name) == stage_group::kNarrowphase) stats.overlapsMeasured = true;
    const bool showProgress = options.progress && stderrIsTerminal();
    std::map<std::string, double> stageTotals;
    long stageTimedFrames = 0;
    for (long frame = 0; frame < options.frames; ++frame) {
        if (options.beforeFrame) options.beforeFrame(world);
        pipeline.step(world);
        if (options.afterFrame) options.afterFrame(world);
        stats.stepMs.push_back(pipeline.lastStepMs());
        if (pipeline.lastStepTimedStages()) {  // one frame in Pipeline::kStageTimingPeriod
            for (const Stage& stage : pipeline.stages())
                if (stage.enabled) stageTotals[stageGroup(stage.name)] += stage.lastMs;
            ++stageTimedFrames;
        }
        ++stats.frames;
        if (probe) stats.maxPenetration = std::max(stats.maxPenetration, static_cast<double>(probe->measure(world)));
        if (!world.pairs.empty()) ++stats.framesWithOverlap;
        stats.maxOverlappingPairs = std::max(stats.maxOverlappingPairs, int(world.pairs.size()));
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
    for (const auto& [group, total] : stageTotals)
        stats.stageMeanMs[group] = stageTimedFrames ? total / static_cast<double>(stageTimedFrames) : 0;
    stats.finalEnergy = computeEnergy(world);
    const std::vector<RunStats::GroupEnergy> finalGroups = energyByIntegrator(world);
    for (std::size_t i = 0; i < stats.energyByIntegrator.size() && i < finalGroups.size(); ++i)
        stats.energyByIntegrator[i].final = finalGroups[i].initial;
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
    // What the collision stages measured: overlaps from chapter 2's narrowphase on, depth from
    // chapter 3's.
    if (stats.overlapsMeasured)
        out << "overlaps   " << stats.framesWithOverlap << " of " << stats.frames
            << " frames had an overlapping pair (most at once: " << stats.maxOverlappingPairs << ")\n";
    if (stats.penetrationMeasured)
        out << "max depth  " << std::setprecision(6) << stats.maxPenetration << " m\n";
    else if (stats.overlapsMeasured)
        out << "max depth  not measured (this chapter's narrowphase finds whether shapes overlap, not how deep)\n";
    else
        out << "max depth  not measured (no collision stage in this chapter)\n";
    if (world.broadphase.used != BroadphaseMode::Auto)
        out << "broadphase " << toString(world.broadphase.used) << " (" << world.broadphase.reason << "), "
            << world.candidatePairs.size() << " candidate pairs in the last step\n";
    if (const auto ccd = stats.planNotes.find(stage_group::kCcd); ccd != stats.planNotes.end())
        out << "ccd        " << ccd->second << "; " << world.step.ccd.totalToiEvents << " times of impact resolved\n";
    if (const std::string plan = describeIterationPlan(world); !plan.empty()) out << "substeps   " << plan << "\n";
    out << "energy     " << std::setprecision(6) << stats.initialEnergy.total() << " J -> " << stats.finalEnergy.total()
        << " J" << (stats.energyByIntegrator.empty() ? "" : "; by integrator (its bodies and their springs):") << "\n";
    for (const RunStats::GroupEnergy& group : stats.energyByIntegrator)
        out << "  " << group.name << std::string(group.name.size() < 20 ? 20 - group.name.size() : 1, ' ')
            << std::setprecision(6) << group.initial << " J -> " << group.final << " J (" << std::showpos
            << std::setprecision(3) << group.final - group.initial << std::noshowpos << " J)\n";
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
    if (endsWith(nameOrPath, ".json") || std::ifstream(nameOrPath).good()) return loadSceneFile(nameOrPath, registry.sceneGenerators());
    throw SceneError("", "'" + nameOrPath + "' is neither a scene file nor a built-in scene (see `stepwise scenes`)");
}

}  // namespace stepwise
