#pragma once
// A candidate point of a manifold, before reduction to four: what clipping and the closed forms
// produce.

#include "math/math.h"

#include <cstdint>
#include <vector>

namespace stepwise {

struct ManifoldPoint {
    Vec3 pointA = Vec3::Zero();  // on A's surface, world frame
    Vec3 pointB = Vec3::Zero();  // on B's surface; pointA - pointB = depth * normal
    Real depth = 0;              // > 0 overlapping, < 0 a gap (speculative)
    std::uint32_t featureId = 0; // makeFeatureId(feature of A, feature of B)
};

/// The candidates of one pair: one normal (unit, from A towards B) for all of them.
struct ManifoldCandidates {
    Vec3 normal = Vec3::UnitY();
    std::vector<ManifoldPoint> points;
    const char* kind = "none";   // "face_a", "face_b", "edge_edge", "single", "round"
    int referenceSide = 0;       // 1: clipped against A's face, 2: against B's, 0: neither
};

}  // namespace stepwise
