#pragma once
// Exact box measures in double for the chapter 3 suites (random poses come from math/random.h).

#include "math/math.h"
#include "02_gjk/box_oracle.h"
#include "app/bench_util.h"
#include "math/random.h"
#include "03_epa/narrowphase.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace stepwise::test {

/// A query every number of which is finite, with a unit normal: what any input must get.
inline bool finiteQuery(const ContactQuery& query) {
    return isFinite(query.depth) && isFinite(query.normal) && isFinite(query.pointA) && isFinite(query.pointB) &&
           std::abs(query.normal.norm() - Real(1)) < Real(1e-4);
}

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

}  // namespace stepwise::test
