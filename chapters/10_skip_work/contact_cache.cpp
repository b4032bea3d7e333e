#include "10_skip_work/contact_cache.h"

#include "03_epa/chapter.h"
#include "03_epa/narrowphase.h"
#include "06_manifolds/persistence.h"
#include "10_skip_work/follow_corners.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

bool restsWithoutMotion(const World& world, int bodyIndex) {
    const Motion* motion = world.motionOf(bodyIndex);
    return !motion || motion->asleep;
}

bool touching(const Contact& contact) {
    for (int i = 0; i < contact.pointCount; ++i)
        if (contact.points[i].depth > 0) return true;
    return false;
}

/// Whether B has turned, relative to A, no more than the rule allows since the manifold was built:
/// the angle between two rotations q1 and q2 is 2 acos(|q1 . q2|).
bool turnedWithin(const Contact& contact, const Quat& relativeRotation, const ContactCacheRule& rule) {
    const Real cosHalfAngle = std::abs(relativeRotation.coeffs().dot(contact.builtRelativeRotation.coeffs()));
    return cosHalfAngle >= math::cos(Real(0.5) * rule.maxRotation);
}


/// The face of a box that a direction (world frame) leaves: its axis in the box's frame, the side
/// (+1 or -1), and how nearly the direction is the face's normal (1: exactly).
struct BoxFace {
    int axis = 0;
    Real side = 1;
    Real alignment = 0;
};
BoxFace faceLeftBy(const Body& box, const Vec3& direction) {
    const Vec3 local = box.transform.rotateInverse(direction);
    BoxFace face;
    local.cwiseAbs().maxCoeff(&face.axis);
    face.side = local[face.axis] < 0 ? Real(-1) : Real(1);
    face.alignment = std::abs(local[face.axis]);
    return face;
}

}  // namespace

// [ch10-cache-rule]
bool manifoldStillValid(const Contact& contact, const Transform& transformA, const Transform& transformB,
                        const ContactCacheRule& rule) {
    if (!contact.builtPoseKnown) return false;
    const Quat inverseA = transformA.rotation.conjugate();
    const Vec3 relativePosition = inverseA * (transformB.position - transformA.position);
    if ((relativePosition - contact.builtRelativePosition).squaredNorm() > rule.maxTranslation * rule.maxTranslation)
        return false;
    return turnedWithin(contact, inverseA * transformB.rotation, rule);
}
// [ch10-cache-rule]

// [ch10-turn-swing]
Real turnSwing(const Contact& contact, const Body& bodyA, const Body& bodyB) {
    if (bodyB.shape.type == ShapeType::Sphere) return 0;
    // A turn by theta moves a point r from the axis 2 r sin(theta / 2), and sin(theta / 2) is the
    // length of the turn's quaternion's vector part: no arc cosine, whose float argument near 1
    // would round a turn of a few hundredths of a degree to nothing or to 0.04 degrees.
    const Quat turn = bodyA.transform.rotation.conjugate() * bodyB.transform.rotation * contact.builtRelativeRotation.conjugate();
    return 2 * turn.vec().norm() * boundingRadius(bodyB.shape);
}
// [ch10-turn-swing]

// [ch10-cache-slide]
bool faceContactSlides(const Contact& contact, const Body& bodyA, const Body& bodyB, const ContactCacheRule& rule) {
    if (!contact.builtPoseKnown || contact.referenceSide == 0 || contact.pointCount <= 0) return false;
    if (bodyA.shape.type != ShapeType::Box || bodyB.shape.type != ShapeType::Box) return false;
    const Quat inverseA = bodyA.transform.rotation.conjugate();
    const Vec3 moved = inverseA * (bodyB.transform.position - bodyA.transform.position) - contact.builtRelativePosition;
    if (std::abs(moved.dot(contact.builtLocalNormal)) > rule.maxTranslation) return false;
    if (!turnedWithin(contact, inverseA * bodyB.transform.rotation, rule)) return false;
    // The reference face: the box face whose outward normal is the contact normal (A's face
    // points along it, B's against it).
    const bool referenceIsA = contact.referenceSide == 1;
    const Body& reference = referenceIsA ? bodyA : bodyB;
    const Body& incident = referenceIsA ? bodyB : bodyA;
    const Vec3 normal = bodyA.transform.rotation * contact.builtLocalNormal;
    const BoxFace face = faceLeftBy(reference, referenceIsA ? normal : Vec3(-normal));
    if (face.alignment < Real(0.999)) return false;  // not a face's normal
    const Vec3& halfExtents = reference.shape.halfExtents;
    for (int i = 0; i < contact.pointCount; ++i) {
        const ContactPoint& point = contact.points[i];
        const Vec3 corner = reference.transform.applyInverse(
            incident.transform.apply(referenceIsA ? point.localAnchorB : point.localAnchorA));
        for (int side = 0; side < 3; ++side)
            if (side != face.axis && std::abs(corner[side]) > halfExtents[side] - rule.maxTranslation) return false;
    }
    return true;
}

void slideFaceContact(Contact& contact, const Body& bodyA, const Body& bodyB) {
    // Depths are read across the reference face, so along its own normal: a normal tilted from the
    // face by an angle t reads a corner that slid s along it s sin(t) off (a box may turn 2 degrees
    // relative to the other before the rule sends the pair to be built again).
    const bool referenceIsA = contact.referenceSide == 1;
    const Body& reference = referenceIsA ? bodyA : bodyB;
    const BoxFace face = faceLeftBy(reference, referenceIsA ? contact.normal : Vec3(-contact.normal));
    const Vec3 faceNormal = reference.transform.rotate(face.side * Vec3::Unit(face.axis));
    contact.normal = referenceIsA ? faceNormal : Vec3(-faceNormal);
    followContact(bodyA, bodyB, contact);  // the incident corners where their body is, the depths
    for (int i = 0; i < contact.pointCount; ++i) {
        ContactPoint& point = contact.points[i];
        if (referenceIsA) {
            point.pointA = point.pointB + point.depth * contact.normal;
            point.localAnchorA = bodyA.transform.applyInverse(point.pointA);
        } else {
            point.pointB = point.pointA - point.depth * contact.normal;
            point.localAnchorB = bodyB.transform.applyInverse(point.pointB);
        }
    }
}
// [ch10-cache-slide]

// [ch10-pair-gap]
namespace {

/// At least the turn 2 acos(c) for c in [0, 1]: with s = sin(turn / 2) = sqrt((1 - c)(1 + c)), the
/// half turn is at most tan(half turn) = s / c. 1 - c is exact for c above a half, so s keeps its
/// few roundings even for tiny turns, and the factor covers them and the arc cosine's.
Real turnBound(Real cosHalfAngle) {
    constexpr Real kRoundingCover = Real(1.001);
    if (!(cosHalfAngle > Real(0.5))) return kPi;  // 120 degrees and more: at most a half turn
    const Real sine = std::sqrt((1 - cosHalfAngle) * (1 + cosHalfAngle));
    return 2 * kRoundingCover * sine / cosHalfAngle;
}

}  // namespace

bool stillApart(const PairGap& gap, const Transform& transformA, const Transform& transformB, Real keepDistance) {
    const Quat inverseA = transformA.rotation.conjugate();
    const Vec3 relativePosition = inverseA * (transformB.position - transformA.position);
    const Quat relativeRotation = inverseA * transformB.rotation;
    const Real cosHalfAngle = std::min(Real(1), std::abs(relativeRotation.coeffs().dot(gap.builtRelativeRotation.coeffs())));
    const Real moved = (relativePosition - gap.builtRelativePosition).norm();
    const Real gjkAllowance = Real(0.001);
    const auto apart = [&](Real turned) { return gap.gap - (moved + turned * gap.radiusB) - gjkAllowance >= keepDistance; };
    // The answer without the arc cosine where bounds settle it (most pairs, every frame), the
    // same answer: the test only falls as the turn grows, and float rounding keeps that order.
    if (!apart(0)) return false;
    if (apart(turnBound(cosHalfAngle))) return true;
    return apart(2 * math::acos(cosHalfAngle));
}
// [ch10-pair-gap]

void markBuiltPose(Contact& contact, const Transform& transformA, const Transform& transformB) {
    const Quat inverseA = transformA.rotation.conjugate();
    contact.builtPoseKnown = contact.pointCount > 0 && contact.missedSteps == 0;
    contact.builtRelativePosition = inverseA * (transformB.position - transformA.position);
    contact.builtRelativeRotation = inverseA * transformB.rotation;
    contact.builtLocalNormal = inverseA * contact.normal;
}

// [ch10-anchors-reproduce]
bool anchorsReproduce(const Contact& contact, const Body& bodyA, const Body& bodyB) {
    if (!isRound(bodyA.shape) && !isRound(bodyB.shape)) return true;  // material points: exact
    Contact followed = contact;
    refreshFromAnchors(followed, bodyA, bodyB);
    for (int i = 0; i < contact.pointCount; ++i)
        if (std::abs(followed.points[i].depth - contact.points[i].depth) > kAnchorTolerance) return false;
    return true;
}
// [ch10-anchors-reproduce]

namespace {

/// Chapter 6's manifoldMargin of a pair, each body's speed bound made once a frame, when a pair of
/// it first asks (a body has a dozen candidate pairs; pairs of sleeping bodies never ask).
Real pairMargin(const World& world, const BodyPair& pair, Real lookAhead, ContactCacheScratch& scratch) {
    if (!(lookAhead > 0)) return 0;
    const auto bound = [&](int body) {
        Real& speed = scratch.speedBounds[static_cast<std::size_t>(body)];
        if (!(speed >= 0)) speed = speedBound(world, body);
        return speed;
    };
    return manifoldMarginOf(world, bound(pair.bodyA), bound(pair.bodyB), lookAhead);
}

/// A pair without a record: apart (or new). Known apart and unable to have closed the gap: nothing
/// to do. Otherwise its distance is measured as chapter 6 would, and the pair goes to chapter 6
/// (true) only if it is close enough for a contact; else its gap is recorded.
bool measureApartPair(World& world, const BodyPair& pair, Real lookAhead, const ManifoldOptions& options,
                      std::size_t& nextGap, ContactCacheScratch& scratch, ContactCacheStats& stats) {
    const Body& bodyA = world.bodies[static_cast<std::size_t>(pair.bodyA)];
    const Body& bodyB = world.bodies[static_cast<std::size_t>(pair.bodyB)];
    if (!canCollide(bodyA, bodyB)) return false;
    while (nextGap < world.pairGaps.size() && world.pairGaps[nextGap].pair < pair) ++nextGap;
    const PairGap* known =
        nextGap < world.pairGaps.size() && world.pairGaps[nextGap].pair == pair ? &world.pairGaps[nextGap] : nullptr;
    const Real keepDistance = pairMargin(world, pair, lookAhead, scratch) + pointSlack(world);
    if (known && stillApart(*known, bodyA.transform, bodyB.transform, keepDistance)) {
        scratch.gaps.push_back(*known);
        ++stats.apart;
        return false;
    }
    CollideOptions collide;
    collide.separationDistance = true;
    // The box-box query's gap is a lower bound of the distance: kept, it only asks sooner.
    const ContactQuery query = options.query
                                   ? options.query(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform, collide)
                                   : collideShapes(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform, collide);
    ++stats.measured;
    if (query.routine == std::string("invalid") || query.intersect || -query.depth < keepDistance) return true;
    const Quat inverseA = bodyA.transform.rotation.conjugate();
    PairGap gap;
    gap.pair = pair;
    gap.gap = -query.depth;
    gap.radiusB = boundingRadius(bodyB.shape);
    gap.builtRelativePosition = inverseA * (bodyB.transform.position - bodyA.transform.position);
    gap.builtRelativeRotation = inverseA * bodyB.transform.rotation;
    scratch.gaps.push_back(gap);
    return false;
}

/// Carries last frame's record of a touching pair into this frame when the pair has not moved
/// beyond the rule (or slid along a box face): its points ride on their bodies, the normal turns
/// with A. A point that has drifted farther apart than the margin chapter 6 keeps points within
/// (the bodies slowed, so the margin shrank) sends the pair back to chapter 6, which keeps only
/// what is in reach. Returns whether it was carried; a record not carried goes to chapter 6 with
/// its points where they now are (its feature ids and impulses are what chapter 6 matches).
bool carryRecord(World& world, const BodyPair& pair, Contact& record, const ContactCacheRule& rule, Real lookAhead,
                 ContactCacheScratch& scratch, ContactCacheStats& stats) {
    const Body& bodyA = world.bodies[static_cast<std::size_t>(pair.bodyA)];
    const Body& bodyB = world.bodies[static_cast<std::size_t>(pair.bodyB)];
    const bool still = manifoldStillValid(record, bodyA.transform, bodyB.transform, rule);
    const bool slides = !still && faceContactSlides(record, bodyA, bodyB, rule);
    if (!still && !slides) return false;
    if (turnSwing(record, bodyA, bodyB) > rule.maxTranslation) return false;
    record.normal = (bodyA.transform.rotation * record.builtLocalNormal).normalized();
    if (slides)
        slideFaceContact(record, bodyA, bodyB);
    else
        followCorners(bodyA, bodyB, record);  // chapter 6's refreshFromAnchors, four points at once
    Real shallowest = 0;  // the margin is asked for only where a point lies apart (most carry none)
    for (int i = 0; i < record.pointCount; ++i) shallowest = std::min(shallowest, record.points[i].depth);
    if (shallowest < 0 && -shallowest > pairMargin(world, pair, lookAhead, scratch) + pointSlack(world))
        return false;
    for (int i = 0; i < record.pointCount; ++i) record.points[i].persisted = true;
    stats.slid += slides ? 1 : 0;
    ++stats.reused;
    return true;
}

/// Chapter 6 builds the pairs the cache could not answer, then its records and the carried ones
/// (both sorted by pair) are merged. Chapter 6 reads last frame's records of the pairs it is given
/// (for matching points), so it gets only those: the full list's buffer stays here, to take the
/// merge, and a steady scene moves no large buffer in or out of the allocator.
void buildMissesAndMerge(World& world, Real lookAhead, const ManifoldOptions& options, ContactCacheScratch& scratch) {
    scratch.previous.swap(world.contacts);
    scratch.merged.swap(world.contacts);  // the buffer of the frame before last takes the result
    world.contacts.swap(scratch.missedRecords);
    world.candidatePairs.swap(scratch.misses);  // the full list waits in scratch.misses
    updateManifolds(world, lookAhead, options);
    world.candidatePairs.swap(scratch.misses);
    for (Contact& contact : world.contacts) {
        const Body& bodyA = world.bodies[static_cast<std::size_t>(contact.bodyA)];
        const Body& bodyB = world.bodies[static_cast<std::size_t>(contact.bodyB)];
        markBuiltPose(contact, bodyA.transform, bodyB.transform);
        if (contact.builtPoseKnown && !anchorsReproduce(contact, bodyA, bodyB)) contact.builtPoseKnown = false;
    }
    scratch.merged.clear();
    scratch.merged.reserve(world.contacts.size() + scratch.kept.size());
    std::size_t rebuilt = 0;
    for (const int index : scratch.kept) {
        const Contact& carried = scratch.previous[static_cast<std::size_t>(index)];
        while (rebuilt < world.contacts.size() && world.contacts[rebuilt].pair() < carried.pair())
            scratch.merged.push_back(world.contacts[rebuilt++]);
        scratch.merged.push_back(carried);
    }
    scratch.merged.insert(scratch.merged.end(), world.contacts.begin() + static_cast<std::ptrdiff_t>(rebuilt),
                          world.contacts.end());
    world.contacts.swap(scratch.merged);
    scratch.mergedPairs.clear();
    std::merge(world.pairs.begin(), world.pairs.end(), scratch.keptPairs.begin(), scratch.keptPairs.end(),
               std::back_inserter(scratch.mergedPairs));
    world.pairs.swap(scratch.mergedPairs);
}

}  // namespace

// [ch10-cached-narrowphase]
ContactCacheStats updateManifoldsCached(World& world, Real lookAhead, const ManifoldOptions& options,
                                        const ContactCacheRule& rule, ContactCacheScratch& scratch) {
    ContactCacheStats stats;
    std::vector<BodyPair>& candidates = scratch.candidates;
    candidates = world.candidatePairs;
    if (!std::is_sorted(candidates.begin(), candidates.end())) std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());

    // Walk the candidates and last frame's records (both sorted by pair) side by side: a record
    // that is still good is kept (refreshed where it lies), every other pair goes to chapter 6's
    // narrowphase.
    std::vector<Contact>& previous = world.contacts;
    scratch.kept.clear();
    scratch.keptPairs.clear();
    scratch.misses.clear();
    scratch.missedRecords.clear();
    scratch.gaps.clear();
    scratch.speedBounds.assign(world.bodies.size(), Real(-1));  // none made yet this frame
    std::size_t next = 0, nextGap = 0;
    const int bodyCount = static_cast<int>(world.bodies.size());
    for (const BodyPair& pair : candidates) {
        while (next < previous.size() && previous[next].pair() < pair) ++next;
        Contact* old = next < previous.size() && previous[next].pair() == pair ? &previous[next] : nullptr;
        const bool valid = pair.bodyA >= 0 && pair.bodyB < bodyCount && pair.bodyA < pair.bodyB;
        if (valid && restsWithoutMotion(world, pair.bodyA) && restsWithoutMotion(world, pair.bodyB)) {
            // Neither body moved since the last search (both asleep, or asleep and static): whatever
            // was found then is still exactly right, a record or no contact at all.
            ++stats.asleep;
            if (!old) continue;
        } else if (rule.enabled && valid && !old) {
            if (measureApartPair(world, pair, lookAhead, options, nextGap, scratch, stats)) scratch.misses.push_back(pair);
            continue;
        } else if (!rule.enabled || !valid || !old || !old->builtPoseKnown || old->pointCount <= 0 ||
                   old->missedSteps > 0 || !carryRecord(world, pair, *old, rule, lookAhead, scratch, stats)) {
            scratch.misses.push_back(pair);
            if (old) scratch.missedRecords.push_back(*old);
            continue;
        }
        scratch.kept.push_back(static_cast<int>(next));
        if (touching(previous[next])) scratch.keptPairs.push_back(pair);
    }
    world.pairGaps.swap(scratch.gaps);
    stats.rebuilt = static_cast<int>(scratch.misses.size());
    world.step.manifoldsReused = stats.reused + stats.asleep;
    world.step.manifoldsRebuilt = stats.rebuilt;
    buildMissesAndMerge(world, lookAhead, options, scratch);
    return stats;
}
// [ch10-cached-narrowphase]

}  // namespace stepwise
