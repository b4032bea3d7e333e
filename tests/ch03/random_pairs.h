#pragma once
// Seeded random poses for the chapter 3 suites. std::mt19937 with our own mapping to [0, 1):
// std::uniform_real_distribution differs between standard libraries, these numbers do not.

#include "math/math.h"
#include "02_gjk/box_oracle.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace stepwise::test {

constexpr double kTwoPi = 6.283185307179586;

class Random {
public:
    explicit Random(unsigned seed) : engine_(seed) {}
    double unit() { return engine_() / 4294967296.0; }                 // [0, 1)
    double range(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// A uniformly distributed rotation (Shoemake, "Uniform random rotations", Graphics Gems III).
    Quat rotation() {
        const double u1 = unit(), u2 = kTwoPi * unit(), u3 = kTwoPi * unit();
        const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
        return Quat(Real(a * std::sin(u2)), Real(a * std::cos(u2)), Real(b * std::sin(u3)), Real(b * std::cos(u3)))
            .normalized();
    }
    /// A uniformly distributed unit vector.
    Vec3 direction() {
        const double z = range(-1, 1), phi = kTwoPi * unit(), r = std::sqrt(std::max(0.0, 1 - z * z));
        return Vec3(Real(r * std::cos(phi)), Real(r * std::sin(phi)), Real(z));
    }

private:
    std::mt19937 engine_;
};

/// Signed distance from a point to a box's surface (negative inside), in double.
inline double boxSurfaceDistance(const Vec3& point, const Vec3& halfExtents, const Transform& pose) {
    const oracle::OracleBox box = oracle::makeOracleBox(halfExtents, pose);
    const Eigen::Vector3d local = box.axes.transpose() * (point.cast<double>() - box.center);
    const Eigen::Vector3d outside = (local.cwiseAbs() - box.halfExtents).cwiseMax(0.0);
    if (outside.squaredNorm() > 0) return outside.norm();
    return (local.cwiseAbs() - box.halfExtents).maxCoeff();
}

/// How far two boxes overlap along a unit axis (their projections' overlap), in double.
inline double boxOverlapAlong(const Vec3& axis, const Vec3& halfA, const Transform& poseA, const Vec3& halfB,
                              const Transform& poseB) {
    const oracle::OracleBox a = oracle::makeOracleBox(halfA, poseA), b = oracle::makeOracleBox(halfB, poseB);
    const Eigen::Vector3d n = axis.cast<double>().normalized();
    const double radiusA = (a.axes.transpose() * n).cwiseAbs().dot(a.halfExtents);
    const double radiusB = (b.axes.transpose() * n).cwiseAbs().dot(b.halfExtents);
    return radiusA + radiusB - std::abs(n.dot(b.center - a.center));
}

/// The value below which a fraction p of the sample lies (nearest rank).
inline double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    const std::size_t rank = std::min(values.size() - 1, static_cast<std::size_t>(std::ceil(p * values.size())) - 1);
    return values[rank];
}

}  // namespace stepwise::test
