#pragma once
// Seeded random box pairs: one definition for the chapter 2 and 3 tests and the benches.

#include "math/random.h"

namespace stepwise {

struct BoxPair {
    Vec3 halfExtentsA = Vec3::Ones();
    Vec3 halfExtentsB = Vec3::Ones();
    Transform poseA;
    Transform poseB;
    /// nearContactBoxPair and overlappingBoxPair only: the exact signed distance (m) of the pair
    /// as stored, computed in double; > 0 separated, < 0 overlapping.
    double exactGap = 0;
};

/// Two randomly sized (edge lengths minSize..maxSize m) and oriented boxes; B's centre lies in a
/// random direction from A's, at up to 1.2 times the sum of their bounding radii, so about half
/// the pairs overlap. Everything is shifted by `origin`.
BoxPair randomBoxPair(Random& random, double minSize, double maxSize, const Vec3& origin = Vec3::Zero());

/// Two randomly sized (half extents 0.05..1 m) and oriented boxes that overlap by at least
/// `minDepthFraction` of the smallest half extent (a relative depth error means little at a
/// depth of a few ulps), drawn until one does. A's centre is uniform in a cube of half side
/// `centreSpread` around the origin; B's lies in a random direction from A's, within the sum of
/// their bounding radii. exactGap is minus the exact (SAT, double) depth.
BoxPair overlappingBoxPair(Random& random, double minDepthFraction, double centreSpread = 0);

/// A pair whose signed distance is `gap` by construction: A axis aligned, B randomly rotated and
/// smaller, placed so its lowest corner along +X sits `gap` beyond A's +X face, well inside the
/// face. The sign of the distance is then known exactly (exactGap is recomputed from the rounded
/// pose), which is what counting false positives and negatives needs.
BoxPair nearContactBoxPair(Random& random, double gap);

}  // namespace stepwise
