// Run reports (docs/scene-format.md, "Run report"). Two runs of the same scene must give the
// same bytes outside timing_ms, so other tools can diff reports: keys keep the contract's
// order (ordered_json), every Real prints as the shortest decimal that reads back to the same
// value, and arrays of numbers stay on one line so a body's state reads like the scene file.

#include "world/report.h"

#include "world/json_reader.h"
#include "world/pipeline.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <type_traits>

namespace stepwise {
namespace {

/// The shortest decimal that reads back as the same Real (json_reader.h). Non-finite values
/// become null (JSON has no NaN), and the report adds a warning for them.
Json number(Real value) {
    if (!std::isfinite(value)) return nullptr;
    return tidyNumber(value);
}

/// Statistics that are double already (energies): as is, but finite or null.
Json statistic(double value) { return std::isfinite(value) ? Json(value == 0 ? 0.0 : value) : Json(nullptr); }

/// Timings in ms, rounded to 0.1 microsecond: more digits would be noise.
Json milliseconds(double value) { return std::isfinite(value) ? std::round(value * 1e4) / 1e4 : 0.0; }

Json vec3(const Vec3& v) { return Json::array({number(v.x()), number(v.y()), number(v.z())}); }
Json quat(const Quat& q) { return Json::array({number(q.x()), number(q.y()), number(q.z()), number(q.w())}); }

bool isScalar(const Json& value) { return !value.is_object() && !value.is_array(); }

/// Like dump(2), but an array of scalars stays on one line: "position": [0, 0.5, 0].
void print(const Json& value, int indent, std::string& out) {
    const bool isObject = value.is_object();
    if (isScalar(value)) {
        out += value.dump();
        return;
    }
    if (value.empty()) {
        out += isObject ? "{}" : "[]";
        return;
    }
    if (!isObject && std::all_of(value.begin(), value.end(), isScalar)) {
        out += "[";
        for (auto it = value.begin(); it != value.end(); ++it) out += (it == value.begin() ? "" : ", ") + it->dump();
        out += "]";
        return;
    }
    const std::string inner(std::size_t(indent + 2), ' ');
    out += isObject ? "{\n" : "[\n";
    bool first = true;
    for (const auto& item : value.items()) {
        out += (first ? "" : ",\n") + inner;
        if (isObject) out += Json(item.key()).dump() + ": ";
        print(item.value(), indent + 2, out);
        first = false;
    }
    out += "\n" + std::string(std::size_t(indent), ' ') + (isObject ? "}" : "]");
}

Json energyJson(const Energy& initial, const Energy& final) {
    Json energy;
    energy["initial"] = statistic(initial.total());
    energy["final"] = statistic(final.total());
    // Extension: the parts, so a reader can tell a spring losing energy from a body falling.
    energy["kinetic_initial"] = statistic(initial.kinetic);
    energy["kinetic_final"] = statistic(final.kinetic);
    energy["gravity_initial"] = statistic(initial.gravity);
    energy["gravity_final"] = statistic(final.gravity);
    energy["springs_initial"] = statistic(initial.springs);
    energy["springs_final"] = statistic(final.springs);
    return energy;
}

Json bodyJson(const World& world, std::size_t index) {
    const Body& body = world.bodies[index];
    const Motion* motion = world.motionOf(int(index));
    Json out;
    out["name"] = body.name;
    out["position"] = vec3(body.transform.position);
    out["orientation"] = quat(body.transform.rotation);
    out["velocity"] = vec3(motion ? motion->linearVelocity : Vec3::Zero());
    out["angular_velocity"] = vec3(motion ? motion->angularVelocity : Vec3::Zero());
    return out;
}

}  // namespace

double median(std::vector<double> values) {
    if (values.empty()) return 0;
    const std::size_t middle = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(middle), values.end());
    const double upper = values[middle];
    if (values.size() % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + std::ptrdiff_t(middle));
    return 0.5 * (lower + upper);
}

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const double rank = std::ceil(std::clamp(p, 0.0, 1.0) * static_cast<double>(values.size()));
    const std::size_t index = std::min(values.size() - 1, static_cast<std::size_t>(std::max(1.0, rank)) - 1);
    return values[index];
}

namespace {

std::string numberText(Real value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", double(value));
    return text;
}

}  // namespace

std::string planReasonText(PlanReason reason, const PlanThresholds& thresholds) {
    const std::string ratio = numberText(thresholds.plainMassRatio);
    switch (reason) {
        case PlanReason::SceneCount: return "the scene's solver_iterations";
        case PlanReason::NothingTouches: return "nothing touches: substeps of free flight";
        case PlanReason::RestsOnWorld: return "bodies rest on the world alone";
        case PlanReason::SlidesOnWorld: return "bodies slide on the world alone";
        case PlanReason::Bounce: return "something arrives bouncing: the scene's count";
        case PlanReason::MassRatio: return "a body rests on one over " + ratio + " times lighter: the square-root law";
        case PlanReason::LikeStack: return "a stack of like masses: the depth law";
        case PlanReason::ShockSweep: return "a stack of like masses: the depth law with a shock sweep";
        case PlanReason::UnlikeStack:
            return "a stack of unlike masses: the square-root law on its load-path ratio where shallow (at least " +
                   std::to_string(thresholds.fewestUnlikeSubsteps) + "), the scene's count where deep";
        case PlanReason::HangingChain: return "bodies hang by joints: the sag law";
        case PlanReason::JointedBodies: return "bodies joined to bodies: the sag law by their depth, the scene's count in the air";
    }
    return "unknown";
}

std::string describeIterationPlan(const World& world) {
    const IterationPlan& plan = world.step.iterationPlan;
    if (plan.mostIterations <= 0) return "";
    const std::string most = std::to_string(plan.mostIterations);
    const std::string ratio = numberText(plan.largestRatio);
    const std::string plainRatio = numberText(plan.thresholds.plainMassRatio);
    if (!world.settings.planIterations) return most + ": the scene's solver_iterations";
    // Chapter 10's shock sweep (a stack of like masses with nothing bouncing into it).
    const std::string shock = plan.shockFrames > 0 ? "; a shock sweep up the stack (" + std::to_string(plan.deepestStack) +
                                                         " deep) ended " + std::to_string(plan.shockFrames) + " frame(s)"
                                                   : "";
    if (plan.mostIterations > std::max(1, plan.plainIterations)) {
        // What asked for more: a body resting on a much lighter one (through the bodies between:
        // chapter 12's load paths), a deep stack, or both.
        const bool deep = plan.deepestStack > plan.thresholds.plainStackDepth;
        const bool heavy = plan.largestRatio > plan.thresholds.plainMassRatio || !deep;
        std::string why = heavy ? "masses resting on lighter ones up to " + ratio + " to 1" : "";
        if (deep) why += std::string(heavy ? " and " : "") + "a stack " + std::to_string(plan.deepestStack) + " bodies deep";
        return "auto: up to " + most + ", for " + why + " (over " + plainRatio + " to 1, or a deep stack, asks for more)" + shock;
    }
    // Chapter 12's iteration_plan.h: the scene's count where something bounces or masses
    // differ in a deep heap, the square-root law in a shallow one, a count by depth for a stack
    // of like masses, substeps of 1/60 or 1/120 s where
    // bodies rest or slide on the world alone or nothing touches.
    const std::string plain = std::to_string(plan.plainIterations);
    const std::string range =
        plan.fewestIterations < plan.mostIterations ? std::to_string(plan.fewestIterations) + " to " + most : most;
    return "auto: " + range + " by what touches (" + plain +
           " where bodies bounce or rest on unlike masses in a deep heap, by the square root of the mass ratio in a "
           "shallow one, by depth where like masses carry one another, fewer where they rest on the world alone or "
           "nothing touches), masses resting on lighter ones at most " + ratio + " to 1 (up to " + plainRatio +
           " to 1 solve at " + plain + " or fewer)" + shock;
}

namespace {

Json timingJson(const RunStats& stats) {
    double sum = 0;
    double slowest = 0;
    for (double ms : stats.stepMs) sum += ms, slowest = std::max(slowest, ms);
    Json timing;
    timing["step_mean"] = milliseconds(stats.stepMs.empty() ? 0.0 : sum / double(stats.stepMs.size()));
    timing["step_median"] = milliseconds(median(stats.stepMs));
    timing["step_max"] = milliseconds(slowest);
    timing["stages"] = Json::object();
    for (const auto& [group, ms] : stats.stageMeanMs) timing["stages"][group] = milliseconds(ms);
    return timing;
}

/// The fast solve's substep count and why, with a tally per rule (chapter 10 on).
Json solverIterationsJson(const World& world) {
    Json out = {{"most", world.step.iterationPlan.mostIterations}, {"plan", describeIterationPlan(world)}};
    Json counts = Json::array();
    for (int k = 0; k < kPlanReasonCount; ++k) {
        const PlanReasonTally& tally = world.step.iterationPlan.reasons[static_cast<std::size_t>(k)];
        if (tally.frames == 0) continue;
        counts.push_back({{"why", planReasonText(static_cast<PlanReason>(k), world.step.iterationPlan.thresholds)},
                          {"frames", tally.frames},
                          {"fewest", tally.fewest},
                          {"most", tally.most}});
    }
    if (!counts.empty()) out["counts"] = counts;
    return out;
}

/// The extensions a later chapter's pipeline adds: the broadphase and why (chapter 5 on), what
/// continuous collision did (chapter 7 on), the substep plan (chapter 10 on), and the bodies
/// asleep at the end where the pipeline planned sleeping.
void addExtensions(const World& world, const RunStats& stats, Json& report) {
    if (world.broadphase.used != BroadphaseMode::Auto) {
        report["broadphase"] = {{"used", toString(world.broadphase.used)},
                                {"reason", world.broadphase.reason},
                                {"candidate_pairs", world.candidatePairs.size()}};
    }
    const CcdState& ccd = world.step.ccd;
    const auto ccdNote = stats.planNotes.find(stage_group::kCcd);
    if (ccdNote != stats.planNotes.end()) {
        report["ccd"] = {{"ran", ccd.stepsRun > 0},
                         {"plan", ccdNote->second},
                         {"toi_events", ccd.totalToiEvents},
                         {"steps_event_bound_hit", ccd.stepsBoundHit}};
    }
    if (world.step.iterationPlan.mostIterations > 0) report["solver_iterations"] = solverIterationsJson(world);
    if (stats.planNotes.count(stage_group::kSleep) > 0) {
        int sleeping = 0;
        for (const Motion& motion : world.motions)
            if (motion.asleep && world.bodies[std::size_t(motion.bodyIndex)].type == BodyType::Dynamic) ++sleeping;
        report["sleeping_bodies"] = sleeping;
    }
}

}  // namespace

std::string reportToJson(const World& world, const RunStats& stats, const std::string& engineVersion) {
    Json report;
    report["format"] = "stepwise-report";
    report["version"] = 1;
    report["scene"] = world.name;
    report["engine"] = engineVersion;
    report["frames"] = stats.frames;
    report["dt"] = number(world.settings.dt);
    report["pipeline"] = stats.pipeline;
    report["timing_ms"] = timingJson(stats);
    report["max_penetration"] = statistic(stats.maxPenetration);
    report["penetration_measured"] = stats.penetrationMeasured;
    report["max_contacts"] = stats.maxContacts;
    addExtensions(world, stats, report);
    report["energy"] = energyJson(stats.initialEnergy, stats.finalEnergy);

    std::vector<std::string> warnings = stats.warnings;
    const CcdState& ccd = world.step.ccd;
    if (ccd.stepsBoundHit > 0)
        warnings.push_back("ccd: the bound on time-of-impact events was hit in " + std::to_string(ccd.stepsBoundHit) +
                           " step(s); the bodies it stopped wait at their last time of impact");
    Json bodies = Json::array();
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        bodies.push_back(bodyJson(world, i));
        const Motion* motion = world.motionOf(int(i));
        const Transform& pose = world.bodies[i].transform;
        const bool finite = isFinite(pose.position) && pose.rotation.coeffs().allFinite() &&
                            (!motion || (isFinite(motion->linearVelocity) && isFinite(motion->angularVelocity)));
        if (!finite)
            warnings.push_back("body \"" + world.bodies[i].name + "\" ended with a non-finite state (written as null)");
    }
    report["bodies"] = bodies;
    report["warnings"] = warnings;

    std::string text;
    print(report, 0, text);
    return text + "\n";
}

void writeReport(const std::string& path, const World& world, const RunStats& stats, const std::string& engineVersion) {
    const std::string text = reportToJson(world, stats, engineVersion);
    std::ofstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot write report file " + path);
    file << text;
    file.close();
    if (!file) throw std::runtime_error("cannot write report file " + path);
}

}  // namespace stepwise
