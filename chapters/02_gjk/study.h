#pragma once
// Measurements the chapter's bench prints and its tests assert on (one definition, two users):
// how often GJK misjudges a box pair that nearly touches, per box support map.

#include "02_gjk/gjk.h"

#include <cstdint>
#include <vector>

namespace stepwise {

/// Box pairs at one signed gap (m) from contact, and how each support map judged them.
struct GapClassification {
    double gap = 0;                  // > 0 separated by this much, < 0 overlapping this deep
    int pairs = 0;
    int wrong[2] = {0, 0};           // [Extents, Vertices]: false positives (gap > 0) or negatives
    int nonCleanExits[2] = {0, 0};   // exits other than Intersect / Separated
    int newestDropped[2] = {0, 0};   // queries where the newest support point was not kept
};

/// Builds `pairsPerGap` near-contact box pairs (nearContactBoxPair) at each gap and runs the
/// boolean GJK with both box support maps on each. The truth is the pair's exact gap sign.
std::vector<GapClassification> classifyNearContact(std::uint32_t seed, const std::vector<double>& gaps, int pairsPerGap);

/// The gaps the bench and the tests use: +-1e-7 .. +-1e-2 m.
std::vector<double> nearContactGaps();

}  // namespace stepwise
