#pragma once
// Run reports (docs/scene-format.md, "Run report"): what a headless run measured, and every
// body's final state. Byte-identical for identical runs except the timing_ms object.

#include "world/world.h"

#include <map>
#include <string>
#include <vector>

namespace stepwise {

struct RunStats {
    long frames = 0;
    std::vector<std::string> pipeline;            // stages that ran, in order
    std::vector<double> stepMs;                   // one per frame
    std::map<std::string, double> stageMeanMs;    // per stage group, mean per frame
    double maxPenetration = 0;                    // m, deepest overlap at the end of any step
    bool penetrationMeasured = false;             // false before a chapter can measure overlap
    int maxContacts = 0;
    Energy initialEnergy;
    Energy finalEnergy;
    std::vector<std::string> warnings;            // e.g. joints no stage handles yet
    std::vector<std::string> unusedSettings;      // "ccd (chapter 7, to come)": no stage reads them yet
    std::map<std::string, std::string> planNotes; // by stage group: why the planner put a stage in or left it out

    // For the run's printed summary only (reports leave them out):
    bool overlapsMeasured = false;                // a narrowphase stage ran
    long framesWithOverlap = 0;                   // frames whose narrowphase found an overlapping pair
    int maxOverlappingPairs = 0;
    struct GroupEnergy {
        std::string name;                         // the integrator the group's bodies use
        double initial = 0, final = 0;            // J, including the springs the group's bodies hang on
    };
    std::vector<GroupEnergy> energyByIntegrator;  // when the bodies use more than one integrator
};

/// The middle of a sample (the mean of the two middle values for an even count); 0 when empty.
double median(std::vector<double> values);

/// The value below which a fraction p of the sample lies (nearest rank); 0 when empty.
double percentile(std::vector<double> values, double p);

/// The report as JSON text (2-space indent, keys in contract order).
std::string reportToJson(const World& world, const RunStats& stats, const std::string& engineVersion);

/// How many substeps chapter 10's solve took at most, and why (solver_iterations "auto" or the
/// scene's number); empty when no stage planned them (chapters 1 to 9).
std::string describeIterationPlan(const World& world);

/// The rule behind a frame's substep count, in words (the report's solver_iterations "counts").
std::string planReasonText(PlanReason reason, const PlanThresholds& thresholds);

/// Writes the report; throws std::runtime_error naming the path when the file cannot be written.
void writeReport(const std::string& path, const World& world, const RunStats& stats,
                 const std::string& engineVersion);

}  // namespace stepwise
