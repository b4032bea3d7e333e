#pragma once
// What the broadphase keeps from one step to the next, and what its last run did. Plain data
// held by the World (never by a stage), so a copy of the world carries it and steps on exactly
// like the original. Chapter 5 (sweep and prune) fills it; earlier chapters leave it empty.

#include "math/math.h"
#include "world/contact.h"
#include "world/settings.h"

#include <string>
#include <vector>

namespace stepwise {

/// A body's place on the sweep axis: the lower end of its interval. Sorted by (value, body): a
/// total order, so a full sort and an incremental one give the same sequence.
struct SweepEndpoint {
    Real value = 0;  // the lower end of the body's interval on the sweep axis, m
    int body = -1;
};

/// The boxes of one sweep laid out in sweep order, one array per bound: entry i is the body
/// whose lower end is i-th along the axis. The sweep reads them straight through. `count`
/// entries, then a few sentinels that overlap nothing, so a block read past the last box stays
/// inside the arrays.
struct SweepColumns {
    std::vector<Real> low, high;    // the boxes on the sweep axis
    std::vector<Real> lowA, highA;  // on the first other axis
    std::vector<Real> lowB, highB;  // on the second other axis
    std::vector<int> body;
    std::vector<char> dynamic;      // 1 for a dynamic body
    std::size_t count = 0;
};

/// Working memory of one broadphase run, rebuilt every step: kept in the state only so that a
/// step allocates nothing once the vectors have grown.
struct BroadphaseBuffers {
    SweepColumns columns;
    std::vector<BodyPair> pairs;   // the pairs half sorted
    std::vector<int> pairStarts;   // the counting sort's first slot per body
};

struct BroadphaseState {
    // Kept from step to step (temporal coherence).
    int axis = -1;                          // sweep axis of the last step: 0 x, 1 y, 2 z; -1 none yet
    std::vector<SweepEndpoint> endpoints;   // one per body, sorted along `axis` as of the last step
    std::vector<Aabb> bounds;               // this step's bounds, one per body, grown by the motion
    std::vector<char> dynamic;              // this step's body types, one per body: 1 for dynamic
    BroadphaseBuffers buffers;              // working memory, no state (see BroadphaseBuffers)
    // Chapter 10: the boxes of the last sweep, each grown by a margin, and the pairs the sweep found
    // among them. While every body's box stays inside its grown one, those pairs, kept where this
    // step's boxes overlap, are exactly the pairs a new sweep would find.
    std::vector<Aabb> enlargedBounds;
    std::vector<char> enlargedDynamic;
    std::vector<BodyPair> enlargedPairs;

    // What the last run did: for tests, the demo panel and the run report.
    BroadphaseMode used = BroadphaseMode::Auto;  // Sap or Brute once a broadphase ran; Auto: none ran
    std::string reason;                     // why `used`, in words, for the run report
    // What `reason` was written for: it changes only with the setting and the body count, and
    // writing it again every step would cost a one-body step a tenth of its time.
    BroadphaseMode reasonSetting = BroadphaseMode::Auto;
    std::size_t reasonBodyCount = 0;
    Vec3 centreVariance = Vec3::Zero();     // of the bounds' centres per axis, m^2
    bool fullSort = false;                  // the last sweep sorted from scratch
    long sortMoves = 0;                     // endpoints the insertion sort moved past another
    long axisOverlaps = 0;                  // pairs whose intervals overlap on the sweep axis
    bool sweepSkipped = false;              // chapter 10: no box left its grown box, no sweep ran
};

}  // namespace stepwise
