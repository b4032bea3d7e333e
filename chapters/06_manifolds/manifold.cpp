// The narrowphase stage of chapter 6: manifolds, matched against last step's.
#include "06_manifolds/manifold.h"

#include "03_epa/chapter.h"
#include "06_manifolds/persistence.h"
#include "06_manifolds/polytope_faces.h"
#include "06_manifolds/polytope_manifold.h"
#include "06_manifolds/reduction.h"
#include "06_manifolds/round_manifolds.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace stepwise {

Real manifoldMargin(const World& world, int bodyA, int bodyB, Real lookAhead) {
    if (!(lookAhead > 0)) return 0;
    return manifoldMarginOf(world, speedBound(world, bodyA), speedBound(world, bodyB), lookAhead);
}

Real manifoldMarginOf(const World& world, Real speedA, Real speedB, Real lookAhead) {
    if (!(lookAhead > 0)) return 0;
    return lookAhead * speculativeMarginOf(world, speedA, speedB, 1);
}

Real pointSlack(const World& world) { return std::max(Real(0), world.settings.slop); }

namespace {

bool isValidRealPose(const Transform& transform) {
    return isFinite(transform.position) && transform.rotation.coeffs().allFinite() && transform.rotation.norm() > kEpsilon;
}

Transform shifted(const Transform& transform, const Vec3& origin) {
    return Transform{transform.position - origin, transform.rotation.normalized()};
}

}  // namespace

// [ch06-build-manifold]
bool buildManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, const ContactQuery& query,
                   Real keepDistance, const ManifoldOptions& options, Contact& contact, const Contact* previous) {
    contact.pointCount = 0;
    contact.referenceSide = 0;
    if (query.routine == std::string("invalid") || !isValidRealPose(ta) || !isValidRealPose(tb)) return false;
    if (!isFinite(keepDistance)) return false;
    // Work in a frame centred on A, as chapter 3's collideShapes does: far from the origin, world
    // coordinates would eat the float mantissa before the small differences are formed.
    const Vec3 origin = ta.position;
    const Transform localA = shifted(ta, origin), localB = shifted(tb, origin);
    ContactQuery local = query;
    local.pointA -= origin;
    local.pointB -= origin;

    // The candidates' points keep their room from call to call (one record per thread; nothing in
    // it outlives the call): a rebuilt pair allocates nothing.
    thread_local ManifoldCandidates candidates;
    candidates.normal = Vec3::UnitY();
    candidates.points.clear();
    candidates.kind = "none";
    candidates.referenceSide = 0;
    bool found = false;
    if (options.multiPoint && isPolytope(a) && isPolytope(b)) {
        ReferenceSide preferred = ReferenceSide::None;
        if (previous && previous->referenceSide == 1) preferred = ReferenceSide::A;
        if (previous && previous->referenceSide == 2) preferred = ReferenceSide::B;
        found = polytopeManifold(a, localA, b, localB, local, keepDistance, candidates, preferred);
    } else if (options.multiPoint) {
        found = roundManifold(a, localA, b, localB, local, keepDistance, candidates);
    }
    if (!found) {
        // One point per pair (chapter 3), also when no face or edge pair explains the query
        // (a corner on a corner).
        if (!(-local.depth <= keepDistance)) return false;
        candidates.normal = local.normal;
        candidates.kind = "single";
        candidates.points.assign(1, singlePoint(local));
    }

    int chosen[kMaxManifoldPoints];
    const int count = reduceManifold(candidates.points, candidates.normal, chosen);
    contact.normal = candidates.normal;
    contact.referenceSide = candidates.referenceSide;
    for (int i = 0; i < count; ++i) {
        const ManifoldPoint& candidate = candidates.points[static_cast<std::size_t>(chosen[i])];
        if (!isFinite(candidate.pointA) || !isFinite(candidate.pointB) || !isFinite(candidate.depth)) continue;
        ContactPoint& point = contact.points[contact.pointCount++];
        point = ContactPoint{};
        point.pointA = candidate.pointA + origin;
        point.pointB = candidate.pointB + origin;
        point.localAnchorA = ta.applyInverse(point.pointA);
        point.localAnchorB = tb.applyInverse(point.pointB);
        point.depth = candidate.depth;
        point.featureId = candidate.featureId;
    }
    if (!isFinite(contact.normal)) contact.pointCount = 0;
    return contact.pointCount > 0;
}
// [ch06-build-manifold]

bool collideManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, Real keepDistance,
                     Contact& contact, const ManifoldOptions& options, const Contact* previous) {
    CollideOptions collide;
    collide.separationDistance = keepDistance > 0;
    const ContactQuery query = collideShapes(a, ta, b, tb, collide);
    if (!query.intersect && !(keepDistance > 0)) {
        contact.pointCount = 0;
        return false;
    }
    return buildManifold(a, ta, b, tb, query, keepDistance, options, contact, previous);
}

namespace {

/// A pair's record into World::contacts: the manifold just built, matched to last step's, or, for
/// a pair out of reach this search whose bounds still overlap, last step's record a few searches
/// more, its points riding on their bodies, so a contact that opens for a step does not lose what
/// it carried (no flicker).
void keepManifold(World& world, const BodyPair& pair, bool built, bool intersect, const Contact* old, Contact& contact,
                  const ManifoldOptions& options, Real measuredGap = -1) {
    if (built) {
        if (intersect) world.pairs.push_back(pair);
        if (old) matchContactPoints(contact, *old, options.matchDistance);
        world.contacts.push_back(contact);
        return;
    }
    if (old && keepsMissedRecord(*old, options.keepSteps)) {
        Contact kept = *old;
        ++kept.missedSteps;
        refreshFromAnchors(kept, world.bodies[static_cast<std::size_t>(pair.bodyA)],
                           world.bodies[static_cast<std::size_t>(pair.bodyB)]);
        // The search just measured the shapes `measuredGap` apart (< 0: not measured, or they
        // overlap), and no point of theirs is closer than that. A point clipped onto a face's
        // plane rides with its body past the face's edge, and its depth along the old normal can
        // read centimetres closer than the shapes are: a speculative row that stops a fast body
        // short of what it never reaches.
        if (measuredGap >= 0)
            for (int i = 0; i < kept.pointCount; ++i) kept.points[i].depth = std::min(kept.points[i].depth, -measuredGap);
        world.contacts.push_back(kept);
    }
}

}  // namespace

// [ch06-update-manifolds]
int updateManifolds(World& world, Real lookAhead, const ManifoldOptions& options) {
    const auto [ordered, previous] = beginContactSearch(world, world.candidatePairs);
    // Every pair is asked for its gap, not only the moving ones: a box resting exactly on another
    // (gap 0, no speed, so no speculative margin) is "not intersecting" to GJK, and whether it
    // counts as touching would otherwise hang on the last bit of its height (float and double
    // disagreed, and the stack above it with them).
    CollideOptions collide;
    collide.separationDistance = true;
    const int bodyCount = static_cast<int>(world.bodies.size());
    int queries = 0;
    for (const BodyPair& pair : ordered) {
        if (pair.bodyA < 0 || pair.bodyB >= bodyCount || pair.bodyA >= pair.bodyB) continue;
        const Body& bodyA = world.bodies[static_cast<std::size_t>(pair.bodyA)];
        const Body& bodyB = world.bodies[static_cast<std::size_t>(pair.bodyB)];
        if (!canCollide(bodyA, bodyB)) continue;
        ++queries;
        const Contact* old = findContact(previous, pair);
        Contact contact;
        contact.bodyA = pair.bodyA;
        contact.bodyB = pair.bodyB;
        // A later chapter's shapes first: its manifold, kept and matched as chapter 3's are.
        const PairManifold custom = options.pairManifold
                                        ? options.pairManifold(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform,
                                                               manifoldMargin(world, pair.bodyA, pair.bodyB, lookAhead) +
                                                                   pointSlack(world),
                                                               old, contact)
                                        : PairManifold{};
        if (custom.handled) {
            keepManifold(world, pair, custom.built, custom.intersect, old, contact, options);
            continue;
        }
        const ContactQuery query = options.query
                                       ? options.query(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform, collide)
                                       : collideShapes(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform, collide);
        if (query.routine == std::string("invalid")) continue;  // nothing to keep of a broken pair
        const Real margin = manifoldMargin(world, pair.bodyA, pair.bodyB, lookAhead);
        const Real keepDistance = margin + pointSlack(world);
        const bool close = query.intersect || -query.depth < keepDistance;
        const bool built = close && buildManifold(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform, query,
                                                  keepDistance, options, contact, old);
        keepManifold(world, pair, built, query.intersect, old, contact, options,
                     query.intersect ? Real(-1) : std::max(Real(0), -query.depth));
    }
    return queries;
}
// [ch06-update-manifolds]

ManifoldStats countManifolds(const World& world) {
    ManifoldStats stats;
    for (const Contact& contact : world.contacts) {
        ++stats.contacts;
        if (contact.missedSteps > 0) ++stats.keptRecords;
        for (int i = 0; i < std::min(std::max(contact.pointCount, 0), 4); ++i) {
            ++stats.points;
            if (contact.points[i].persisted) ++stats.persistedPoints;
            if (contact.points[i].depth < 0) ++stats.speculativePoints;
        }
    }
    return stats;
}

namespace {

std::string featureLabel(std::uint32_t feature) {
    const std::uint32_t kind = (feature >> 13) & 7u, index = feature & kFeatureIndexMask;
    switch (static_cast<FeatureKind>(kind)) {
        case FeatureKind::Vertex: return "v" + std::to_string(index);
        case FeatureKind::Edge: return "e" + std::to_string(index / 128) + "-" + std::to_string(index % 128);
        case FeatureKind::Face: return "f" + std::to_string(index);
        case FeatureKind::Core: return "c" + std::to_string(index);
        case FeatureKind::None: break;
    }
    return "?";
}

}  // namespace

std::string featureIdLabel(std::uint32_t featureId) {
    return featureLabel(featureId >> 16) + "/" + featureLabel(featureId & 0xFFFFu);
}

}  // namespace stepwise
