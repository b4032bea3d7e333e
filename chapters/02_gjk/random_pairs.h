#pragma once
// Seeded random box pairs: one definition for the chapter 2 tests and `stepwise bench gjk`.
// std::mt19937 is specified bit for bit by the standard; the uniform mapping below is ours
// (std::uniform_real_distribution differs between standard libraries), so every platform sees
// the same pairs.

#include "math/math.h"

#include <cstdint>
#include <random>

namespace stepwise {

class PairRandom {
public:
    explicit PairRandom(std::uint32_t seed) : engine_(seed) {}
    /// Uniform in [0, 1) with 32 random bits.
    double uniform() { return static_cast<double>(engine_()) * (1.0 / 4294967296.0); }
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    /// Uniform over rotations (Shoemake, "Uniform random rotations", Graphics Gems III, 1992).
    Quat rotation();
    /// Uniform over the unit sphere.
    Vec3 unitVector();

private:
    std::mt19937 engine_;
};

struct BoxPair {
    Vec3 halfExtentsA = Vec3::Ones();
    Vec3 halfExtentsB = Vec3::Ones();
    Transform poseA;
    Transform poseB;
    /// nearContactBoxPair only: the exact signed distance (m) of the pair as stored, computed in
    /// double; > 0 separated, < 0 overlapping.
    double exactGap = 0;
};

/// Two randomly sized (edge lengths minSize..maxSize m) and oriented boxes; B's centre lies in a
/// random direction from A's, at up to 1.2 times the sum of their bounding radii, so about half
/// the pairs overlap. Everything is shifted by `origin`.
BoxPair randomBoxPair(PairRandom& random, double minSize, double maxSize, const Vec3& origin = Vec3::Zero());

/// A pair whose signed distance is `gap` by construction: A axis aligned, B randomly rotated and
/// smaller, placed so its lowest corner along +X sits `gap` beyond A's +X face, well inside the
/// face. The sign of the distance is then known exactly (exactGap is recomputed from the rounded
/// pose), which is what counting false positives and negatives needs.
BoxPair nearContactBoxPair(PairRandom& random, double gap);

}  // namespace stepwise
