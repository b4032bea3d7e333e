#pragma once
// The answers EPA gives when its polytope cannot (epa.h has the algorithm around them): the best
// of a handful of candidate axes when no tetrahedron holds the origin, and the contact along the
// tightest upper bound when round-off stops the polytope far from the boundary. Internal to
// chapter 3.

#include "03_epa/epa.h"

namespace stepwise::epa_fallback {

/// A direction and how far A - B reaches along it: the depth is at most `reach`.
struct UpperBound {
    Real reach = kRealMax;
    Vec3 normal = Vec3::UnitY();
    SupportPoint support;
};

/// No tetrahedron around the origin could be built: the contact along the candidate axis (from
/// the simplex, the centres, a round shape's core, the coordinate axes) A - B reaches least along.
EpaResult fallbackContact(const ConvexProxy& a, const ConvexProxy& b, const Simplex& simplex);

/// The contact along an upper bound's normal, `reach` deep, its points on the shapes' surfaces
/// (within `slack`).
void answerWithBound(const ConvexProxy& a, const ConvexProxy& b, const UpperBound& bound, Real slack,
                     EpaResult& result);

}  // namespace stepwise::epa_fallback
