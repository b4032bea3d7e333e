#pragma once
// The engine's one seeded random source, for scenes, tests and benches. std::mt19937 is specified
// bit for bit by the standard; the mappings below are ours (std::uniform_real_distribution
// differs between standard libraries), so every platform draws the same numbers.

#include "math/math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

namespace stepwise {

class Random {
public:
    explicit Random(std::uint32_t seed) : engine_(seed) {}

    /// Uniform in [0, 1) with 32 random bits.
    double uniform() { return static_cast<double>(engine_()) * (1.0 / 4294967296.0); }
    double uniform(double low, double high) { return low + (high - low) * uniform(); }

    /// Uniform in [low, high) from 24 random bits: the unit draw is exact in float, so the float
    /// and double builds lay a scene out from the same numbers.
    Real uniformReal(Real low, Real high) {
        const Real unit = static_cast<Real>(engine_() >> 8) * Real(1.0 / 16777216.0);
        return low + (high - low) * unit;
    }

    // [common-uniform-rotation]
    /// Uniform over rotations (Shoemake, "Uniform random rotations", Graphics Gems III, 1992):
    /// a unit quaternion from three uniform numbers, as two circles weighted by sqrt(1 - u1)
    /// and sqrt(u1).
    Quat rotation() {
        const double u1 = uniform();
        const double u2 = uniform() * 2 * 3.14159265358979323846;
        const double u3 = uniform() * 2 * 3.14159265358979323846;
        const double a = std::sqrt(1 - u1);
        const double b = std::sqrt(u1);
        Quat q(Real(b * math::cos(u3)), Real(a * math::sin(u2)), Real(a * math::cos(u2)), Real(b * math::sin(u3)));
        q.normalize();
        return q;
    }
    // [common-uniform-rotation]

    /// Uniform over the unit sphere (Archimedes: z is uniform on [-1, 1]).
    Vec3 unitVector() {
        const double z = uniform(-1, 1);
        const double angle = uniform() * 2 * 3.14159265358979323846;
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        return Vec3(Real(r * math::cos(angle)), Real(r * math::sin(angle)), Real(z));
    }

private:
    std::mt19937 engine_;
};

}  // namespace stepwise
