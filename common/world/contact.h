#pragma once
// What the narrowphase remembers about touching pairs. A Contact joins two bodies along one
// normal and holds up to four points (chapter 6 fills more than one). The contacts live in
// World::contacts from step to step, one per touching pair, sorted by pair: a cache keyed by the
// body pair, apart from the solver's rows (Jolt keeps its manifold cache apart from its contact
// constraints; Box3D keeps anchors, a feature id and a "persisted" flag per manifold point).
// Points are stored on each body (anchors), so a later substep can see how far the bodies have
// moved since the points were found, and carry feature ids and impulses, so the next step can
// tell which points are the same and start from what they carried.

#include "math/math.h"

#include <cstdint>
#include <vector>

namespace stepwise {

/// Two bodies by index, bodyA < bodyB in every list the engine builds.
struct BodyPair {
    int bodyA = -1;
    int bodyB = -1;
    bool operator==(const BodyPair& other) const { return bodyA == other.bodyA && bodyB == other.bodyB; }
    bool operator!=(const BodyPair& other) const { return !(*this == other); }
    /// The canonical order of pair lists: by bodyA, then bodyB. Whatever found the pairs (all
    /// pairs, a broadphase), the narrowphase sees them in this order, so results never depend
    /// on which one ran.
    bool operator<(const BodyPair& other) const {
        return bodyA != other.bodyA ? bodyA < other.bodyA : bodyB < other.bodyB;
    }
};

// [common-feature-id]
/// Which feature of a shape a contact point came from. A point's feature id names one feature of
/// each shape, so it stays the same while the same corner touches the same face, whatever the
/// exact coordinates (Box3D packs its ids the same way, owner and index of two features).
enum class FeatureKind : std::uint32_t { None = 0, Vertex = 1, Edge = 2, Face = 3, Core = 4 };

/// 16 bits per shape: 3 for the kind, 13 for the index. 0 means "unknown" (no kind on either side).
constexpr std::uint32_t kFeatureIndexMask = 0x1FFF;
constexpr std::uint32_t makeFeature(FeatureKind kind, std::uint32_t index) {
    return (static_cast<std::uint32_t>(kind) << 13) | (index & kFeatureIndexMask);
}
constexpr std::uint32_t makeFeatureId(std::uint32_t featureA, std::uint32_t featureB) {
    return (featureA << 16) | (featureB & 0xFFFF);
}
/// The same id seen with A and B swapped.
constexpr std::uint32_t swappedFeatureId(std::uint32_t featureId) {
    return (featureId << 16) | (featureId >> 16);
}
// [common-feature-id]

struct ContactPoint {
    Vec3 pointA = Vec3::Zero();        // deepest point of A inside B, world frame, when found
    Vec3 pointB = Vec3::Zero();        // deepest point of B inside A, world frame, when found
    Vec3 localAnchorA = Vec3::Zero();  // pointA in A's body frame
    Vec3 localAnchorB = Vec3::Zero();  // pointB in B's body frame
    Real depth = 0;                    // > 0 overlapping, < 0 a gap (a speculative point), m
    std::uint32_t featureId = 0;       // touching features (makeFeatureId), 0 when unknown
    bool persisted = false;            // matched a point of the pair's previous record
    Real normalImpulse = 0;            // accumulated in the last solve, N s
    Real tangentImpulse[2] = {0, 0};   // in tangentBasis(normal), N s
    Real normalMass = 0;               // effective mass of the last solve's normal row, kg; 0: no row
};

struct Contact {
    int bodyA = -1;
    int bodyB = -1;
    Vec3 normal = Vec3::UnitY();       // unit, from A towards B
    ContactPoint points[4];
    int pointCount = 0;
    int missedSteps = 0;               // searches since the narrowphase last found the pair close
                                       // enough; chapter 6 keeps a record a few searches more
    int referenceSide = 0;             // chapter 6: whose face the points were clipped against,
                                       // 1 A's, 2 B's, 0 neither (kept next step while nearly as good)
    // Chapter 10's contact cache: where B was in A's frame, and the normal in A's frame, when the
    // manifold was last built from the shapes. A pair that has barely moved since reuses it.
    bool builtPoseKnown = false;
    Vec3 builtRelativePosition = Vec3::Zero();
    Quat builtRelativeRotation = Quat::Identity();
    Vec3 builtLocalNormal = Vec3::UnitY();

    BodyPair pair() const { return BodyPair{bodyA, bodyB}; }
};

/// Chapter 10: a candidate pair found apart (no record in World::contacts), and where B stood in
/// A's frame then. Until B has moved, in A's frame, by more than the gap minus what the pair may
/// close this frame, the shapes cannot be close enough for a contact and are not queried again.
struct PairGap {
    BodyPair pair;
    Real gap = 0;                                  // distance between the shapes, m
    Real radiusB = 0;                              // B's bounding radius about its origin, m
    Vec3 builtRelativePosition = Vec3::Zero();     // B's origin in A's frame
    Quat builtRelativeRotation = Quat::Identity(); // B's rotation in A's frame
};

/// The two friction directions of a contact, from its normal alone: t1 = anyPerpendicular(n),
/// t2 = n x t1. The same normal always gives the same basis, so a friction impulse stored in it
/// means the same thing next step.
inline void tangentBasis(const Vec3& normal, Vec3& tangent1, Vec3& tangent2) {
    tangent1 = anyPerpendicular(normal);
    tangent2 = normal.cross(tangent1);
}

/// The pair's record in a list sorted by pair, or nullptr.
const Contact* findContact(const std::vector<Contact>& contacts, const BodyPair& pair);

}  // namespace stepwise
