#pragma once
// A run report without what may rightly differ between two runs of the same scene: the timings,
// and the planners' notes (a later chapter adds its own). What is left must be bit-identical.

#include "world/report.h"

#include <string>

namespace stepwise::test {

inline std::string reportWithoutTimingsAndNotes(const World& world, RunStats stats) {
    stats.planNotes.clear();
    stats.stepMs.assign(stats.stepMs.size(), 0);
    stats.stageMeanMs.clear();
    return reportToJson(world, stats, "test");
}

}  // namespace stepwise::test
