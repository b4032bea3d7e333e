#pragma once
// A pair's manifold from step to step: which new points are last step's points, what they carry
// over, and how long a record outlives the pair's contact.

#include "world/contact.h"
#include "world/world.h"

namespace stepwise {

/// Matches the points of a fresh manifold to the pair's previous record: first by feature id (the
/// same features touching, Box3D's rule), then, for points left over, by both body-local anchors
/// lying within matchDistance of an unmatched old point's (Jolt's rule, 1 cm by default), nearest
/// first. A matched point takes over normalImpulse and the friction impulse, re-expressed in the
/// new normal's tangentBasis, and is marked persisted. Returns how many points matched.
int matchContactPoints(Contact& contact, const Contact& previous, Real matchDistance);

/// Moves a record's points with their bodies: world points from the anchors, depth along the
/// record's normal (chapter 3's followContact, as for a substep).
void refreshFromAnchors(Contact& contact, const Body& bodyA, const Body& bodyB);

/// Whether the previous record of a pair still in the broadphase's candidates, but no longer close
/// enough to make a contact, is kept one more search: while it has missed fewer than keepSteps.
///
/// This life cycle replaces chapter 4's drop rule (dropUnloadedContactPoints, the stage
/// contacts:drop_unloaded), which removed every point that had carried no load after the frame's
/// last solve. With one point per pair found afresh every substep nothing was lost by that. A
/// manifold's unloaded corners are part of its next step (a corner that lifts for a step lands
/// again with its id, and should find its impulse), so chapter 6 drops whole records instead: at
/// once when the pair leaves the broadphase's candidates, after keepSteps searches out of reach
/// otherwise. Points that carry nothing simply hold a zero impulse.
bool keepsMissedRecord(const Contact& previous, int keepSteps);

}  // namespace stepwise
