// Matching manifolds between steps, and the life cycle of a pair's record.
#include "06_manifolds/persistence.h"

#include "03_epa/chapter.h"

#include <algorithm>

namespace stepwise {

namespace {

void carryPoint(ContactPoint& point, const ContactPoint& old, const Vec3 oldBasis[2], const Vec3 newBasis[2]) {
    // Friction is stored in the basis of the normal; the normal may have turned since, so the old
    // friction vector is rebuilt in the world and projected on the new basis.
    const Vec3 friction = old.tangentImpulse[0] * oldBasis[0] + old.tangentImpulse[1] * oldBasis[1];
    point.normalImpulse = old.normalImpulse;
    point.tangentImpulse[0] = friction.dot(newBasis[0]);
    point.tangentImpulse[1] = friction.dot(newBasis[1]);
    point.persisted = true;
}

/// Puts matched points in the slots of the points they continue, new points after them. The
/// solver sweeps a manifold's points in order, and Gauss-Seidel splits the load of a face resting
/// on four corners by that order (the two corners solved first carry more): a manifold whose
/// points came back in another order would start its solve from last step's split and drift to
/// another, a twist on every box of a stack each step.
void keepPreviousOrder(Contact& contact, const int matchedOld[4]) {
    const int count = std::min(std::max(contact.pointCount, 0), 4);
    ContactPoint ordered[4];
    int placed = 0;
    for (int slot = 0; slot < 4; ++slot)
        for (int i = 0; i < count; ++i)
            if (matchedOld[i] == slot) ordered[placed++] = contact.points[i];
    for (int i = 0; i < count; ++i)
        if (matchedOld[i] < 0) ordered[placed++] = contact.points[i];
    for (int i = 0; i < count; ++i) contact.points[i] = ordered[i];
}

}  // namespace

// [ch06-match-points]
int matchContactPoints(Contact& contact, const Contact& previous, Real matchDistance) {
    Vec3 oldBasis[2], newBasis[2];
    tangentBasis(previous.normal, oldBasis[0], oldBasis[1]);
    tangentBasis(contact.normal, newBasis[0], newBasis[1]);
    const int newCount = std::min(std::max(contact.pointCount, 0), 4);
    const int oldCount = std::min(std::max(previous.pointCount, 0), 4);
    bool oldUsed[4] = {false, false, false, false};
    bool matched[4] = {false, false, false, false};
    int matchedOld[4] = {-1, -1, -1, -1};
    int matches = 0;
    // 1. The same features: the same corner on the same face, wherever exactly it is now.
    for (int i = 0; i < newCount; ++i) {
        ContactPoint& point = contact.points[i];
        if (point.featureId == 0) continue;
        for (int k = 0; k < oldCount; ++k) {
            if (oldUsed[k] || previous.points[k].featureId != point.featureId) continue;
            carryPoint(point, previous.points[k], oldBasis, newBasis);
            oldUsed[k] = matched[i] = true;
            matchedOld[i] = k;
            ++matches;
            break;
        }
    }
    // 2. Features differ (a face choice flipped, a hull's ids collided) but the point has not
    // moved on either body: it is the same point. Nearest pair first.
    const Real limit = matchDistance * matchDistance;
    for (;;) {
        int bestNew = -1, bestOld = -1;
        Real bestDistance = limit;
        for (int i = 0; i < newCount; ++i) {
            if (matched[i]) continue;
            for (int k = 0; k < oldCount; ++k) {
                if (oldUsed[k]) continue;
                const Real distanceA = (contact.points[i].localAnchorA - previous.points[k].localAnchorA).squaredNorm();
                const Real distanceB = (contact.points[i].localAnchorB - previous.points[k].localAnchorB).squaredNorm();
                const Real distance = std::max(distanceA, distanceB);
                if (distance < bestDistance) {
                    bestDistance = distance;
                    bestNew = i;
                    bestOld = k;
                }
            }
        }
        if (bestNew < 0) break;
        carryPoint(contact.points[bestNew], previous.points[bestOld], oldBasis, newBasis);
        matched[bestNew] = oldUsed[bestOld] = true;
        matchedOld[bestNew] = bestOld;
        ++matches;
    }
    keepPreviousOrder(contact, matchedOld);
    return matches;
}
// [ch06-match-points]

void refreshFromAnchors(Contact& contact, const Body& bodyA, const Body& bodyB) { followContact(bodyA, bodyB, contact); }

// [ch06-keep-missed]
bool keepsMissedRecord(const Contact& previous, int keepSteps) {
    return previous.pointCount > 0 && previous.missedSteps < keepSteps;
}
// [ch06-keep-missed]

}  // namespace stepwise
