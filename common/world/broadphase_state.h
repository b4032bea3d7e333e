#pragma once
// What the broadphase keeps from one step to the next, and what its last run did. Plain data
// held by the World (never by a stage), so a copy of the world carries it and steps on exactly
// like the original. Chapter 5 (sweep and prune) fills it; earlier chapters leave it empty.

#include "math/math.h"
#include "world/settings.h"

#include <string>
#include <vector>

namespace stepwise {

/// One end of a body's interval on the sweep axis. Sorted by (value, lower end first, body):
/// a total order, so a full sort and an incremental one give the same sequence, and an interval
/// that ends exactly where another starts still counts as overlapping.
struct SweepEndpoint {
    Real value = 0;        // coordinate on the sweep axis, m
    int body = -1;
    bool isUpper = false;  // the interval's upper end (max), else its lower end (min)
};

struct BroadphaseState {
    // Kept from step to step (temporal coherence).
    int axis = -1;                          // sweep axis of the last step: 0 x, 1 y, 2 z; -1 none yet
    std::vector<SweepEndpoint> endpoints;   // two per body, sorted along `axis` as of the last step
    std::vector<Aabb> bounds;               // this step's bounds, one per body, grown by the motion
    std::vector<char> dynamic;              // this step's body types, one per body: 1 for dynamic

    // What the last run did: for tests, the demo panel and the run report.
    BroadphaseMode used = BroadphaseMode::Auto;  // Sap or Brute once a broadphase ran; Auto: none ran
    std::string reason;                     // why `used`, in words, for the run report
    Vec3 centreVariance = Vec3::Zero();     // of the bounds' centres per axis, m^2
    bool fullSort = false;                  // the last sweep sorted from scratch
    long sortMoves = 0;                     // endpoints the insertion sort moved past another
    long axisOverlaps = 0;                  // pairs whose intervals overlap on the sweep axis
};

}  // namespace stepwise
