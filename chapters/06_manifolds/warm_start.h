#pragma once
// Warm starting: the solve begins where the last one ended. Each contact point that the
// narrowphase matched to a point of the previous step (persisted, see manifold.h) still holds
// the impulses it carried; applied to the bodies before the first iteration, they give the
// solver last step's answer as its first guess, and the iterations only have to correct what
// changed (Catto, "Iterative Dynamics with Temporal Coherence", GDC 2005; Box2D and Box3D do the
// same in their "warm start" pass).

#include "04_pgs/contact_constraints.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

/// Sets every contact row's accumulated impulse from what its point carried last step: the
/// normal impulse as is, the friction impulse (stored as a vector in tangentBasis(normal)) projected
/// onto this step's friction directions and, when `clampToCone`, kept inside the friction cone.
/// Nothing is applied. The relax pass loads the biased solve's impulses unclamped: they are
/// already in the velocities, and an accumulated impulse smaller than the applied one would let
/// the relax iteration apply the difference a second time.
void loadCarriedImpulses(const World& world, ContactRows& contactRows, bool clampToCone = true);

/// loadCarriedImpulses, then pushes the bodies by those impulses: the warm start.
void warmStart(const World& world, ContactRows& contactRows, std::vector<SolverBody>& bodies);

}  // namespace stepwise
