#pragma once
// The narrowphase of chapter 6: contact manifolds of up to four points per pair, kept from step to
// step. Polytopes (boxes, hulls) get their points by clipping the incident face against the
// reference face (clipping.h, polytope_faces.h); spheres and capsules in closed form
// (round_manifolds.h); persistence.h matches the new points to last step's and carries their
// impulses.

#include "world/world.h"

namespace stepwise {

struct ManifoldOptions {
    bool multiPoint = true;          // false: chapter 3's one point per pair (for A/B in tests, bench, demo)
    Real matchDistance = Real(0.01); // m: fallback match of body-local anchors when feature ids differ (Jolt uses 1 cm)
    int keepSteps = 3;               // steps a pair whose bounds still overlap keeps its manifold within the speculative margin
};

/// The narrowphase stage of chapter 6: for each candidate pair (World::candidatePairs, canonical
/// order), builds a manifold of up to 4 points, matches it against the pair's previous record in
/// world.contacts (feature id, then anchor distance), carries normalImpulse and tangentImpulse
/// (re-expressed in the new tangentBasis) into matched points, sets persisted, and replaces
/// world.contacts (sorted by pair). Fills World::pairs with the overlapping pairs.
///
/// `lookAhead` is counted in substeps, as chapter 3's updateContacts counts it
/// (substepsAhead(world, search)): a pair within speculativeMargin(world, a, b, lookAhead) becomes
/// a contact with speculative points (depth < 0). 0: overlapping pairs only. Returns the number of
/// shape queries made.
int updateManifolds(World& world, Real lookAhead, const ManifoldOptions& options = ManifoldOptions{});

}  // namespace stepwise
