#pragma once
// Closed-form contacts for the pairs that have one. A sphere is a point with a radius and a
// capsule a segment with a radius, so each routine finds the closest points of the cores
// (point-point, point-box, point-segment, segment-segment) and then inflates by the radii.
// These are exact, so the tests hold EPA to them and the pipeline never runs EPA on such pairs.

#include "03_epa/narrowphase.h"

namespace stepwise {

/// Two spheres. Concentric spheres overlap by rA + rB along any normal; +Y is chosen.
ContactQuery collideSpheres(const Vec3& centerA, Real radiusA, const Vec3& centerB, Real radiusB);

/// A box (A) and a sphere (B). A centre inside the box leaves through the nearest face.
ContactQuery collideBoxSphere(const Vec3& halfExtents, const Transform& box, const Vec3& center, Real radius);

/// A capsule (A, axis +Y in its frame) and a sphere (B).
ContactQuery collideCapsuleSphere(Real capsuleRadius, Real halfHeight, const Transform& capsule,
                                  const Vec3& center, Real radius);

/// Two capsules.
ContactQuery collideCapsules(Real radiusA, Real halfHeightA, const Transform& capsuleA, Real radiusB,
                             Real halfHeightB, const Transform& capsuleB);

/// The same contact seen with A and B swapped.
ContactQuery swapped(const ContactQuery& query);

}  // namespace stepwise
