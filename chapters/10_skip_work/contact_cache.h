#pragma once
// Chapter 10's narrowphase: chapter 6's manifolds, built from the shapes only when a pair has
// moved. A pair whose relative pose changed less than a small tolerance since its manifold was
// built keeps the manifold: its points ride on their bodies (anchors), the normal turns with body
// A, and no GJK, EPA or clipping runs (Jolt's body-pair cache: 1 mm and 2 degrees; here B's
// farthest point, too, may swing no more than the 1 mm, since a corner the manifold does not hold
// would sink unseen). A pair of two
// sleeping (or static) bodies keeps its record untouched. A pair without a record is asked for
// its distance once, and not again while it cannot have closed it (PairGap).

#include "06_manifolds/manifold.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

/// How far a pair may move relative to itself before its manifold is built again.
struct ContactCacheRule {
    bool enabled = true;
    Real maxTranslation = Real(0.001);  // m, of B in A's frame; also the most B's farthest point may swing
    Real maxRotation = 2 * kDegree;     // rad, of B relative to A
};

struct ContactCacheStats {
    int reused = 0;     // manifolds carried on their anchors
    int slid = 0;       // of those, face contacts of two boxes that slid (faceContactSlides)
    int rebuilt = 0;    // pairs sent to chapter 6's narrowphase
    int asleep = 0;     // pairs of sleeping or static bodies, kept as they were
    int apart = 0;      // pairs known apart (World::pairGaps), not queried
    int measured = 0;   // pairs without a record whose distance was measured here
};

/// Whether a pair found `gap.gap` apart is still farther apart than `keepDistance`: B's points
/// have moved in A's frame by at most |change of B's origin| + (angle turned) x radiusB, and the
/// gap shrinks by no more than that (less a 1 mm allowance for GJK's tolerance).
bool stillApart(const PairGap& gap, const Transform& transformA, const Transform& transformB, Real keepDistance);

/// Buffers reused from frame to frame; nothing in them outlives a call.
struct ContactCacheScratch {
    std::vector<BodyPair> candidates, misses;
    std::vector<int> kept;                        // indices into last frame's records
    std::vector<Contact> previous, missedRecords, merged;
    std::vector<PairGap> gaps;
    std::vector<BodyPair> keptPairs, mergedPairs;
    std::vector<Real> speedBounds;  // per body, this frame (chapter 3's speedBound; -1: not made yet)
};

/// Whether B's pose in A's frame is within the rule of the pose the manifold was built at.
bool manifoldStillValid(const Contact& contact, const Transform& transformA, const Transform& transformB,
                        const ContactCacheRule& rule);

/// How far B's turn relative to A since the record was built has moved B's farthest point in A's
/// frame, m: the chord of the turn at B's bounding radius (zero for a sphere, which turning about
/// its centre leaves the same). A corner that is not among the record's points moves that much towards
/// A unseen: two degrees would let a unit box's far corner sink 3 cm into its neighbour. A record
/// is carried only while this is within the rule's translation.
Real turnSwing(const Contact& contact, const Body& bodyA, const Body& bodyB);

/// Whether a face contact of two boxes may be carried although its boxes slid apart along the
/// face: turned no more than the rule allows, moved no more than its translation along the normal,
/// and every point of the incident face still inside the reference face by that much. The clip
/// that built the manifold then cuts nothing now either, and the same corners touch at the same
/// depths: the incident corners ride on their body, the reference points slide to face them.
bool faceContactSlides(const Contact& contact, const Body& bodyA, const Body& bodyB, const ContactCacheRule& rule);

/// Carries a sliding face contact (faceContactSlides): each incident corner where its body took it,
/// its reference point moved along the face to face it, the depth unchanged by the slide.
void slideFaceContact(Contact& contact, const Body& bodyA, const Body& bodyB);

/// How far a round body's surface point, found again along the manifold's normal, may lie from the
/// point the manifold was built with: a tenth of a millimetre, well under the 1 mm the cache rule
/// lets a pair move, and well over float round-off at a few metres.
constexpr Real kAnchorTolerance = Real(1e-4);

/// Whether the manifold's points, followed on their anchors at the pose they were built at, give
/// back their own depths. A sphere's or capsule's point is found again as its surface along the
/// normal (chapter 3's followContactPoint); where GJK ended within round-off of touching, its normal
/// can be off by degrees, and carrying such a record would read a round body centimetres deep
/// where it only touches. Such a record is built again next frame instead of carried.
bool anchorsReproduce(const Contact& contact, const Body& bodyA, const Body& bodyB);

/// Records where the manifold was built (the pose the rule compares against).
void markBuiltPose(Contact& contact, const Transform& transformA, const Transform& transformB);

/// The narrowphase stage: World::candidatePairs in, World::contacts and World::pairs out, as
/// updateManifolds does, with the cache in front of it.
ContactCacheStats updateManifoldsCached(World& world, Real lookAhead, const ManifoldOptions& options,
                                        const ContactCacheRule& rule, ContactCacheScratch& scratch);

}  // namespace stepwise
