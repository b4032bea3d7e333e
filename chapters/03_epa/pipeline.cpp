// The narrowphase stage of chapter 3, the contact cache it keeps, and the penetration probe of
// run reports.
#include "03_epa/chapter.h"

#include "02_gjk/chapter.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace stepwise {

bool canCollide(const Body& a, const Body& b) {
    return a.type != BodyType::Static || b.type != BodyType::Static;
}

namespace {

std::vector<Aabb> bodyBounds(const World& world) {
    std::vector<Aabb> bounds(world.bodies.size());
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        bounds[i] = computeAabb(world.bodies[i].shape, world.bodies[i].transform);
    }
    return bounds;
}

}  // namespace

Real speedBound(const World& world, int bodyIndex) {
    const Motion* motion = world.motionOf(bodyIndex);
    if (!motion) return 0;
    const Real arm = std::max(maxLeverArm(world.bodies[bodyIndex].shape, motion->localCenter), shapeScale(world.bodies[bodyIndex].shape));
    return motion->linearVelocity.norm() + motion->angularVelocity.norm() * arm;
}

// [ch03-speculative-margin]
// A search once per frame is not repeated in the later substeps, so a pair must be found already
// when it could close during them: at the speed the bodies have plus what gravity adds over the
// frame. A search every substep looks ahead zero substeps and takes only overlapping pairs.
Real speculativeMargin(const World& world, int bodyA, int bodyB, int lookAhead) {
    if (lookAhead <= 0) return 0;  // a search every substep: no bound to make
    return speculativeMarginOf(world, speedBound(world, bodyA), speedBound(world, bodyB), lookAhead);
}

Real speculativeMarginOf(const World& world, Real speedA, Real speedB, int lookAhead) {
    if (lookAhead <= 0) return 0;
    const Real substep = world.settings.dt / static_cast<Real>(std::max(1, world.settings.substeps));
    const Real gravityGain = world.settings.gravity.norm() * world.settings.dt;
    return static_cast<Real>(lookAhead) * substep * (speedA + speedB + 2 * gravityGain);
}
// [ch03-speculative-margin]

int substepsAhead(const World& world, ContactSearch search) {
    return search == ContactSearch::OncePerFrame ? std::max(1, world.settings.substeps) - 1 : 0;
}

std::vector<BodyPair> findAllPairCandidates(const World& world, int lookAhead) {
    std::vector<Aabb> bounds = bodyBounds(world);
    if (lookAhead > 0) {
        // Grow each box by the body's own share of the margin (the margin of a pair is the sum).
        for (std::size_t i = 0; i < bounds.size(); ++i) {
            const Real grow = speculativeMargin(world, static_cast<int>(i), static_cast<int>(i), lookAhead) / 2;
            bounds[i].min.array() -= grow;
            bounds[i].max.array() += grow;
        }
    }
    std::vector<BodyPair> candidates;
    const int bodyCount = static_cast<int>(world.bodies.size());
    for (int i = 0; i < bodyCount; ++i) {
        for (int j = i + 1; j < bodyCount; ++j) {
            // Boxes that do not overlap rule the pair out for the price of six comparisons.
            if (canCollide(world.bodies[i], world.bodies[j]) && bounds[i].overlaps(bounds[j]))
                candidates.push_back(BodyPair{i, j});
        }
    }
    return candidates;
}

namespace {

ContactPoint makeContactPoint(const Body& bodyA, const Body& bodyB, const ContactQuery& query) {
    ContactPoint point;
    point.pointA = query.pointA;
    point.pointB = query.pointB;
    point.localAnchorA = bodyA.transform.applyInverse(query.pointA);
    point.localAnchorB = bodyB.transform.applyInverse(query.pointB);
    point.depth = query.depth;
    point.featureId = query.featureId;
    return point;
}

// [ch03-carry-impulses]
/// A new point takes over the impulses of the previous record's point with the same features.
/// Friction is stored in the basis of the normal, so when the normal turned, the stored
/// friction vector is projected into the new basis.
void carryImpulses(Contact& contact, const Contact& previous) {
    Vec3 oldTangent1, oldTangent2, newTangent1, newTangent2;
    tangentBasis(previous.normal, oldTangent1, oldTangent2);
    tangentBasis(contact.normal, newTangent1, newTangent2);
    for (int i = 0; i < contact.pointCount; ++i) {
        ContactPoint& point = contact.points[i];
        if (point.featureId == 0) continue;
        for (int k = 0; k < previous.pointCount; ++k) {
            const ContactPoint& old = previous.points[k];
            if (old.featureId != point.featureId) continue;
            const Vec3 friction = old.tangentImpulse[0] * oldTangent1 + old.tangentImpulse[1] * oldTangent2;
            point.normalImpulse = old.normalImpulse;
            point.tangentImpulse[0] = friction.dot(newTangent1);
            point.tangentImpulse[1] = friction.dot(newTangent2);
            point.persisted = true;
            break;
        }
    }
}
// [ch03-carry-impulses]

}  // namespace

ContactSearchStart beginContactSearch(World& world, const std::vector<BodyPair>& candidates) {
    ContactSearchStart start;
    start.pairs = candidates;
    if (!std::is_sorted(start.pairs.begin(), start.pairs.end())) std::sort(start.pairs.begin(), start.pairs.end());
    start.pairs.erase(std::unique(start.pairs.begin(), start.pairs.end()), start.pairs.end());
    start.previous.swap(world.contacts);
    // At most a record a pair (and a missed record kept a few searches more): one allocation,
    // not a doubling series of copies.
    world.contacts.reserve(std::max(start.previous.size(), start.pairs.size()));
    world.step.contactsFoundAtSubstep = world.step.substep;
    world.pairs.clear();
    return start;
}

// [ch03-update-contacts]
int updateContacts(World& world, const std::vector<BodyPair>& candidates, int lookAhead,
                   const CollideOptions& options) {
    const auto [ordered, previous] = beginContactSearch(world, candidates);
    const bool speculative = lookAhead > 0;
    CollideOptions stageOptions = options;
    // Only speculative contacts need the distance of a pair that does not overlap.
    stageOptions.separationDistance = speculative;
    const int bodyCount = static_cast<int>(world.bodies.size());
    int queries = 0;
    for (const BodyPair& pair : ordered) {
        if (pair.bodyA < 0 || pair.bodyB >= bodyCount || pair.bodyA >= pair.bodyB) continue;
        const Body& bodyA = world.bodies[pair.bodyA];
        const Body& bodyB = world.bodies[pair.bodyB];
        if (!canCollide(bodyA, bodyB)) continue;
        ++queries;
        const ContactQuery query = collideShapes(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform, stageOptions);
        const bool closeEnough =
            speculative && query.routine != std::string("invalid") &&
            -query.depth < speculativeMargin(world, pair.bodyA, pair.bodyB, lookAhead);
        if (!query.intersect && !closeEnough) continue;
        if (query.intersect) world.pairs.push_back(pair);
        Contact contact;
        contact.bodyA = pair.bodyA;
        contact.bodyB = pair.bodyB;
        contact.normal = query.normal;
        contact.points[0] = makeContactPoint(bodyA, bodyB, query);
        contact.pointCount = 1;
        if (const Contact* old = findContact(previous, pair)) carryImpulses(contact, *old);
        world.contacts.push_back(contact);
    }
    return queries;
}
// [ch03-update-contacts]

namespace {

/// Where a point on a round body's surface is now: not the material point of its anchor (a
/// rolling ball turns that away from the ground) but the core's point nearest it (a sphere's
/// centre, a capsule's segment) pushed out by the radius along `outward`, the normal leaving the
/// body toward the other.
Vec3 roundSurfacePoint(const Body& body, const Vec3& localAnchor, const Vec3& outward) {
    const Shape& shape = body.shape;
    const Real along = shape.type == ShapeType::Capsule ? std::clamp(localAnchor.y(), -shape.halfHeight, shape.halfHeight) : Real(0);
    return body.transform.apply(Vec3(0, along, 0)) + shape.radius * outward;
}

}  // namespace

// [ch03-follow-point]
void followContactPoint(const Body& bodyA, const Body& bodyB, const Vec3& normal, ContactPoint& point) {
    const bool roundA = isRound(bodyA.shape), roundB = isRound(bodyB.shape);
    point.pointA = roundA ? roundSurfacePoint(bodyA, point.localAnchorA, normal) : bodyA.transform.apply(point.localAnchorA);
    point.pointB = roundB ? roundSurfacePoint(bodyB, point.localAnchorB, -normal) : bodyB.transform.apply(point.localAnchorB);
    // pointA - pointB = depth * normal when found; the normal stays for the frame.
    point.depth = normal.dot(point.pointA - point.pointB);
    // Against a round body the contact is where the round surface is: the other body's point
    // slides to face it at the same depth. Left behind where the frame began, the impulses would
    // act half a frame's roll behind the ball, and its weight would spin it up.
    if (roundB && !roundA) point.pointA = point.pointB + point.depth * normal;
    if (roundA && !roundB) point.pointB = point.pointA - point.depth * normal;
}
// [ch03-follow-point]

void followContact(const Body& bodyA, const Body& bodyB, Contact& contact) {
    const int count = std::min(std::max(contact.pointCount, 0), 4);
    if (isRound(bodyA.shape) || isRound(bodyB.shape)) {
        for (int i = 0; i < count; ++i) followContactPoint(bodyA, bodyB, contact.normal, contact.points[i]);
        return;
    }
    for (int i = 0; i < count; ++i) {  // corners and faces: the material points
        ContactPoint& point = contact.points[i];
        point.pointA = bodyA.transform.apply(point.localAnchorA);
        point.pointB = bodyB.transform.apply(point.localAnchorB);
        point.depth = contact.normal.dot(point.pointA - point.pointB);
    }
}

// [ch03-follow-anchors]
void followContactAnchors(World& world) {
    for (Contact& contact : world.contacts) followContact(world.bodies[contact.bodyA], world.bodies[contact.bodyB], contact);
}
// [ch03-follow-anchors]

int findContacts(World& world, ContactSearch search, const CollideOptions& options) {
    const int lookAhead = substepsAhead(world, search);
    world.candidatePairs = findAllPairCandidates(world, lookAhead);
    return updateContacts(world, world.candidatePairs, lookAhead, options);
}

// [ch03-stage]
Pipeline makeChapter03Pipeline(const World& world, ContactSearch search) {
    Pipeline pipeline = makeChapter02Pipeline(world);
    Stage stage;
    // Plan from the scene: the name says which routines this world will use.
    stage.name = stageName(stage_group::kNarrowphase, allPairsClosedForm(world) ? "closed_form" : "gjk_epa");
    stage.frequency = search == ContactSearch::OncePerFrame ? StageFrequency::FrameStart : StageFrequency::EverySubstep;
    stage.run = [search](World& stepWorld, Real) { findContacts(stepWorld, search); };
    pipeline.replaceOrAdd(std::move(stage));
    return pipeline;
}
// [ch03-stage]

bool allPairsClosedForm(const World& world) {
    // By shape type, not pair by pair: a plan for 100,000 bodies must not cost n^2. A pair of
    // types occurs when a moving body has the first and another body the second.
    constexpr int kTypes = kShapeTypeCount;
    int moving[kTypes] = {}, all[kTypes] = {};
    for (const Body& body : world.bodies) {
        const int type = static_cast<int>(body.shape.type);
        ++all[type];
        if (body.type != BodyType::Static) ++moving[type];
    }
    for (int a = 0; a < kTypes; ++a) {
        for (int b = 0; b < kTypes; ++b) {
            const bool occurs = moving[a] > 0 && (a == b ? all[a] >= 2 : all[b] > 0);
            if (occurs && !hasClosedForm(static_cast<ShapeType>(a), static_cast<ShapeType>(b))) return false;
        }
    }
    return true;
}

Real measureDeepestPenetration(const World& world) { return measureDeepestPenetrationAmong(world, {}); }

Real measureDeepestPenetrationAmong(const World& world, const std::function<bool(int bodyA, int bodyB)>& counts) {
    // Sweep along x: sorted by the boxes' lower x, a body only needs testing against the bodies
    // that start before it ends, so a run report does not pay for all n^2 pairs every frame.
    const std::vector<Aabb> bounds = bodyBounds(world);
    std::vector<int> order(world.bodies.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return bounds[a].min.x() < bounds[b].min.x(); });
    CollideOptions options;
    options.separationDistance = false;
    Real deepest = 0;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const int i = order[k];
        for (std::size_t m = k + 1; m < order.size() && bounds[order[m]].min.x() <= bounds[i].max.x(); ++m) {
            const int j = order[m];
            const Body& a = world.bodies[std::min(i, j)];
            const Body& b = world.bodies[std::max(i, j)];
            if (!canCollide(a, b) || !bounds[i].overlaps(bounds[j])) continue;
            if (counts && !counts(std::min(i, j), std::max(i, j))) continue;
            const ContactQuery query = collideShapes(a.shape, a.transform, b.shape, b.transform, options);
            if (query.intersect) deepest = std::max(deepest, query.depth);
        }
    }
    return deepest;
}

}  // namespace stepwise
