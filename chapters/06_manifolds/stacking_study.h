#pragma once
// Measuring a stack: run a stacking scene for some seconds and record how far its boxes moved
// sideways (drift), how far they sank below their start compared with the slop per contact
// beneath them (sag), the deepest overlap, and the time the steps took. The tests, the bench
// and the page all read these numbers.

#include "06_manifolds/manifold.h"
#include "world/world.h"

#include <optional>

namespace stepwise {

/// What to change in a scene's settings and pipeline for one run (unset: the scene's own).
struct StackingConfig {
    ManifoldOptions manifold;
    std::optional<int> iterations;
    std::optional<int> substeps;
    std::optional<bool> warmStarting;
    std::optional<Stabilisation> stabilisation;
};

struct StackingMeasure {
    double maxDrift = 0;          // largest horizontal distance of a box from its start, m
    double maxSink = 0;           // largest drop of a box below its start, m
    double maxSinkPerContact = 0; // largest drop divided by the contacts beneath the box, m
    double maxSinkExcess = -1;    // largest drop minus slop x contacts beneath, m (<= 0: within the slop)
    double maxPenetration = 0;    // deepest overlap of any two bodies after the first second, m
    double topHeightEnd = 0;      // the highest box's centre at the end, m
    double topHeightStart = 0;
    double stepMs = 0;            // mean wall time of a step, ms
    bool stood = true;            // no box drifted more than half a box or fell half a box
};

/// The contacts beneath a unit box: 1 on the ground, one more per box below (the box's bottom
/// height in metres, rounded, plus 1).
int contactsBeneath(const Body& body);

/// Applies the config's settings to a world.
void applyStackingConfig(World& world, const StackingConfig& config);

/// Runs `world` (changed by `config`) through chapter 6's pipeline for `seconds` and measures.
StackingMeasure measureStacking(World world, const StackingConfig& config, double seconds);

}  // namespace stepwise
