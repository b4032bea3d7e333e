#pragma once
// The narrowphase of chapter 6: contact manifolds of up to four points per pair, kept from step to
// step. Polytopes (boxes, hulls) get their points by clipping the incident face against the
// reference face (clipping.h, polytope_faces.h); spheres and capsules in closed form
// (round_manifolds.h); persistence.h matches the new points to last step's and carries their
// impulses.

#include "03_epa/narrowphase.h"
#include "world/world.h"

#include <cstdint>
#include <functional>
#include <string>

namespace stepwise {

/// The shape query a manifold is built from (chapter 3's collideShapes, or a faster one for some pairs).
using ContactQueryFunction = ContactQuery (*)(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                                              const CollideOptions& options);

/// What a later chapter's manifold function says of a pair (ManifoldOptions::pairManifold).
struct PairManifold {
    bool handled = false;    // false: the pair is chapter 3's and buildManifold's
    bool built = false;      // a contact within keepDistance was built into the record
    bool intersect = false;  // the shapes overlap (the pair counts in World::pairs)
};

/// The manifold of a pair of shapes that chapter 3's query cannot answer as one convex pair
/// (chapter 13: compounds, meshes, height fields; cylinders' faces). Fills `contact`'s normal and
/// points (bodies are set by the caller) from the shapes at their poses, keeping points within
/// keepDistance; `previous` is the pair's last record, if any.
/// A std::function: the chapter's stage keeps what its shapes need from frame to frame (a mesh's
/// tree) in what the function holds.
using PairManifoldFunction = std::function<PairManifold(const Shape& a, const Transform& ta, const Shape& b,
                                                        const Transform& tb, Real keepDistance, const Contact* previous,
                                                        Contact& contact)>;

struct ManifoldOptions {
    bool multiPoint = true;          // false: chapter 3's one point per pair (for A/B in tests, bench, demo)
    ContactQueryFunction query = nullptr;  // null: collideShapes; chapter 10 hands its box-box query here
    Real matchDistance = Real(0.01); // m: fallback match of body-local anchors when feature ids differ (Jolt uses 1 cm)
    int keepSteps = 3;               // steps a pair whose bounds still overlap keeps its manifold within the speculative margin
    PairManifoldFunction pairManifold = nullptr;  // a later chapter's shapes (chapter 13); asked first
};

/// The narrowphase stage of chapter 6: for each candidate pair (World::candidatePairs, canonical
/// order), builds a manifold of up to 4 points, matches it against the pair's previous record in
/// world.contacts (feature id, then anchor distance), carries normalImpulse and tangentImpulse
/// (re-expressed in the new tangentBasis) into matched points, sets persisted, and replaces
/// world.contacts (sorted by pair). Fills World::pairs with the overlapping pairs.
///
/// `lookAhead` is counted in substeps, as chapter 3's updateContacts counts it
/// (substepsAhead(world, search)): a pair within speculativeMargin(world, a, b, lookAhead) becomes
/// a contact with speculative points (depth < 0); so does every pair within one pointSlack, moving or
/// not. Returns the number of shape queries made.
int updateManifolds(World& world, Real lookAhead, const ManifoldOptions& options = ManifoldOptions{});

/// One pair's manifold from chapter 3's query of the same pair (no persistence): contact.normal
/// and up to four points with world points, anchors, depths and feature ids; bodyA and bodyB are
/// left as they are. Points more than keepDistance apart (above the reference face) are left out.
/// False when no point is left or the input is invalid (then contact.pointCount is 0).
/// `previous`: the pair's last record, if any; its reference face is kept while nearly as good,
/// so the points (and their feature ids) do not flip with the face. Sets contact.referenceSide.
bool buildManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, const ContactQuery& query,
                   Real keepDistance, const ManifoldOptions& options, Contact& contact,
                   const Contact* previous = nullptr);

/// collideShapes (with the separation distance when keepDistance > 0), then buildManifold.
bool collideManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, Real keepDistance,
                     Contact& contact, const ManifoldOptions& options = ManifoldOptions{},
                     const Contact* previous = nullptr);

/// The speculative margin of a pair `lookAhead` substeps ahead (chapter 3's speculativeMargin,
/// which is linear in the substeps, so fractions are allowed). 0 for lookAhead <= 0.
Real manifoldMargin(const World& world, int bodyA, int bodyB, Real lookAhead);

/// The same from the two bodies' speedBound (chapter 3), for a stage that bounds each body once.
Real manifoldMarginOf(const World& world, Real speedA, Real speedB, Real lookAhead);

/// How far apart a pair still makes a contact, and a point of it is kept above the reference face,
/// beyond the pair's margin: one slop. A box rocking on one corner keeps its other corners as speculative points, whose rows
/// only act if they close faster than the gap allows (Box2D keeps 4 slops, its "speculative
/// distance").
Real pointSlack(const World& world);

/// What World::contacts holds after a search, for benches, tests and the demo's panel.
struct ManifoldStats {
    int contacts = 0;           // records (pairs)
    int points = 0;
    int persistedPoints = 0;    // matched a point of the pair's previous record
    int speculativePoints = 0;  // depth < 0
    int keptRecords = 0;        // out of reach, kept by the life cycle (missedSteps > 0)
};
ManifoldStats countManifolds(const World& world);

/// A feature id in a few characters, for labels: "f3/v5" is A's face 3 against B's vertex 5
/// (v vertex, e edge, f face, c core, ? unknown); edges print as their two vertices, "e2-6".
std::string featureIdLabel(std::uint32_t featureId);

}  // namespace stepwise
