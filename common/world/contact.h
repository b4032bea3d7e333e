#pragma once
// What the narrowphase tells the solver. A contact joins two bodies along one normal and holds
// up to four points (chapter 6 fills more than one); feature ids let chapter 6 match points
// across frames, and the impulses live here so warm starting can carry them over.

#include "math/math.h"

#include <cstdint>

namespace stepwise {

struct BodyPair {
    int bodyA = -1;
    int bodyB = -1;
    bool operator==(const BodyPair& other) const { return bodyA == other.bodyA && bodyB == other.bodyB; }
};

struct ContactPoint {
    Vec3 pointA = Vec3::Zero();   // deepest point of A inside B, world frame
    Vec3 pointB = Vec3::Zero();   // deepest point of B inside A, world frame
    Real depth = 0;               // > 0 when overlapping, m
    std::uint32_t featureId = 0;  // stable id of the touching features, 0 when unknown
    Real normalImpulse = 0;       // accumulated, N s
    Real tangentImpulse[2] = {0, 0};
};

struct Contact {
    int bodyA = -1;
    int bodyB = -1;
    Vec3 normal = Vec3::UnitY();  // unit, from A towards B
    ContactPoint points[4];
    int pointCount = 0;
};

}  // namespace stepwise
