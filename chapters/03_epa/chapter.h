#pragma once
// Chapter 3's pipeline: chapter 2's, with its yes/no stage `narrowphase:gjk` replaced by a
// stage that also measures each overlap and keeps World::contacts, the contact cache (one point
// per pair). The stage is called `narrowphase:closed_form` when every pair of the scene has a
// closed form (no GJK or EPA will run), else `narrowphase:gjk_epa`.

#include "03_epa/narrowphase.h"
#include "world/pipeline.h"

#include <functional>

#include <vector>

namespace stepwise {

/// False for two static bodies: nothing could respond to their contact (as in chapter 2).
bool canCollide(const Body& a, const Body& b);

// [ch03-contact-search]
/// When the narrowphase looks for contacts. A single point per pair cannot follow a body that
/// rocks within a frame (the deepest corner changes from substep to substep), so chapter 3's
/// one-point contacts are searched every substep. Contacts that hold every touching corner
/// (chapter 6) can be searched once per frame: their points ride on their bodies
/// (anchors) through the substeps, and pairs that could close during the frame are taken in
/// early as speculative points.
enum class ContactSearch { EverySubstep, OncePerFrame };
// [ch03-contact-search]

/// How far a pair can close over `substepsAhead` substeps after the search, m: the speculative
/// margin within which a pair becomes a contact before it touches. Zero for zero substeps.
Real speculativeMargin(const World& world, int bodyA, int bodyB, int substepsAhead);

/// An upper bound on how fast any point of the body moves, m/s: the centre of mass's speed plus the
/// turn times the farthest a point lies from the centre of mass (maxLeverArm: the radius about the
/// shape's origin plus the centre's offset from it). Zero for a body without motion.
Real speedBound(const World& world, int bodyIndex);

/// speculativeMargin from the two bodies' speedBound, for a stage that asks it of many pairs and
/// bounds each body once.
Real speculativeMarginOf(const World& world, Real speedA, Real speedB, int substepsAhead);

/// How many substeps a search of this kind must look ahead: 0 every substep, substeps - 1 once
/// per frame.
int substepsAhead(const World& world, ContactSearch search);

/// Chapter 3's own candidate source: every pair that can collide whose bounds (grown by the
/// speculative margin) overlap, in canonical order. Chapter 5 finds them faster (sweep and prune).
std::vector<BodyPair> findAllPairCandidates(const World& world, int lookAhead = 0);

/// How every narrowphase starts a search: the candidates in canonical order without repeats,
/// and last search's records taken out of the world (sorted by pair, for findContact), with
/// World::pairs cleared and the substep noted (World::step.contactsFoundAtSubstep).
struct ContactSearchStart {
    std::vector<BodyPair> pairs;
    std::vector<Contact> previous;
};
ContactSearchStart beginContactSearch(World& world, const std::vector<BodyPair>& candidates);

/// The narrowphase entry point. Tests the candidate pairs (any order; they are handled in
/// canonical order), and rebuilds World::contacts: one record per touching pair, one point
/// each, with anchors on both bodies and a feature id. A point whose features match a point of
/// the pair's previous record keeps its impulses (re-expressed in the new tangent basis) and is
/// marked persisted. Fills World::pairs with the touching pairs. Returns the shape queries made.
/// `lookAhead` substeps: pairs within the speculative margin become contacts with depth < 0.
int updateContacts(World& world, const std::vector<BodyPair>& candidates, int lookAhead = 0,
                   const CollideOptions& options = CollideOptions{});

/// Moves one contact point with its bodies: world points from the anchors, depth along the
/// normal found with them. A point on a sphere or a capsule stays where its round surface faces
/// the other body, however the body turned, and the other body's point faces it (a rolling ball's
/// contact stays under the ball).
void followContactPoint(const Body& bodyA, const Body& bodyB, const Vec3& normal, ContactPoint& point);

/// followContactPoint for every point of a contact (its depth and world points; a pair of
/// polytopes takes the material points without asking each point).
void followContact(const Body& bodyA, const Body& bodyB, Contact& contact);

/// followContact for every contact. The substeps after the first see how far their bodies moved
/// since the contacts were found.
void followContactAnchors(World& world);

/// findAllPairCandidates then updateContacts: the stage of this chapter.
int findContacts(World& world, ContactSearch search = ContactSearch::EverySubstep,
                 const CollideOptions& options = CollideOptions{});

/// True when every pair of bodies that could collide has a closed-form routine.
bool allPairsClosedForm(const World& world);

/// The deepest overlap between any two bodies (static pairs skipped), m; 0 when none overlap.
/// The penetration probe of run reports (max_penetration).
Real measureDeepestPenetration(const World& world);
/// The same over the pairs `counts` accepts (body indices, lower first): chapter 8 leaves out the
/// pairs a joint holds together, which overlap at their joints by design and never collide.
Real measureDeepestPenetrationAmong(const World& world, const std::function<bool(int bodyA, int bodyB)>& counts);

/// Chapter 2's pipeline with its narrowphase stage replaced by chapter 3's.
Pipeline makeChapter03Pipeline(const World& world, ContactSearch search = ContactSearch::EverySubstep);

}  // namespace stepwise
