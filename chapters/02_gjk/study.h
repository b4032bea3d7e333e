#pragma once
// Measurements the chapter's bench prints and its tests assert on (one definition, two users):
// how often GJK misjudges a box pair that nearly touches, per box support map.

#include "02_gjk/gjk.h"

#include <cstdint>
#include <vector>

namespace stepwise {

/// The GJK variants compared: the two box support maps, and the extents map with the textbook
/// face point (FacePoint::BarycentricSum) instead of the projection.
enum GjkVariant { kExtents = 0, kVertices = 1, kExtentsBarycentricSum = 2, kVariantCount = 3 };
const char* variantName(int variant);

/// Box pairs at one signed gap (m) from contact, and how each variant judged them.
struct GapClassification {
    double gap = 0;                        // > 0 separated by this much, < 0 overlapping this deep
    int pairs = 0;
    double touchingTolerance = 0;          // m, mean over the pairs (GjkTolerances::touching)
    int wrong[kVariantCount] = {};         // false positives (gap > 0) or false negatives (gap < 0)
    int nonCleanExits[kVariantCount] = {}; // exits other than Intersect / Separated
    int newestDropped[kVariantCount] = {}; // queries where the newest support point was not kept
};

/// Builds `pairsPerGap` near-contact box pairs (nearContactBoxPair) at each gap and runs the
/// boolean GJK variants on each. The truth is the pair's exact gap sign.
std::vector<GapClassification> classifyNearContact(std::uint32_t seed, const std::vector<double>& gaps, int pairsPerGap);

/// The gaps the bench and the tests use: +-1e-7 .. +-1e-2 m.
std::vector<double> nearContactGaps();

}  // namespace stepwise
