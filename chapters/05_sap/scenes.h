#pragma once
// Chapter 5's demo scenes: the stress scene, sparse and dense, with what the broadphase did
// drawn over it (bounds, candidate pairs, the sweep axis and the intervals on it) and a panel
// to switch between sweep and prune and brute force and to regenerate the scene.

#include "05_sap/stress_scene.h"
#include "world/world.h"

namespace stepwise {

class DebugDraw;
class Panel;
class Registry;

/// What the overlay shows; the panel's checkboxes.
struct BroadphaseOverlay {
    bool bounds = true;            // the grown bounds of the moving bodies
    bool candidatePairs = true;    // a line between the bodies of each candidate pair
    bool intervals = true;         // the sweep axis and every body's interval on it
};

/// Draws what the last broadphase did: bounds (orange for bodies in a candidate pair with another
/// moving body, grey for the rest), those pairs (yellow lines), the sweep axis (an arrow beside
/// the bodies, named) and the intervals on it in a few lanes along it.
void drawBroadphase(const World& world, const BroadphaseOverlay& overlay, DebugDraw& draw);

/// The panel lines: which broadphase ran and why, candidate pairs against all pairs, the axis
/// and the variances, the last sort, the intervals overlapping on the axis.
void describeBroadphase(const World& world, Panel& panel);

/// Registers "sap-stress" (sparse) and "sap-stress-dense".
void addChapter05Scenes(Registry& registry);

/// The two demo scenes' parameters.
StressParams demoStressParams(StressDensity density);

}  // namespace stepwise
