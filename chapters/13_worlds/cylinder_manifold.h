#pragma once
// Manifolds of a cylinder. Chapter 3's query finds a cylinder's deepest point from its support map
// (02_gjk/support.cpp, cylinderSupport), but one point cannot hold a cylinder standing on its
// face, and a lying cylinder touches along a line. So the feature of the cylinder that faces the
// other shape is taken as an incident polygon, as chapter 6 takes a box's face, and clipped
// against the other shape's reference face:
//   - the axis within kCapAngle of the normal: the cap, a kCapCorners-gon on the true rim;
//   - the axis within kSideAngle of the contact plane: the side's support segment, two points;
//   - otherwise a rim point on an edge or a corner: chapter 3's single point.
// The other shape must have a face (a box, a hull, a triangle's prism) or be a cylinder whose cap
// faces this one; a sphere or a capsule touches a cylinder in one point anyway.

#include "03_epa/narrowphase.h"
#include "06_manifolds/manifold_point.h"
#include "world/shape.h"

namespace stepwise {

// [ch13-cylinder-features]
/// A cap faces the other shape while its axis is within this angle of the contact normal (rad).
/// Wide enough that a cylinder standing on a slope's face under friction, tilted by the soft
/// contact's give, keeps its face contact; narrow enough that a tipping cylinder rolls on its rim
/// (a cap point at 3 degrees is 2.6 mm off the plane per 5 cm of radius, the slop's half).
constexpr Real kCapAngle = Real(0.05);
/// The side faces the other shape while the axis is within this angle of the contact plane (rad).
constexpr Real kSideAngle = Real(0.05);
/// The cap as a polygon of this many corners on the true rim: the reduction to four keeps the
/// extreme ones, and eight find them within cos(22.5 deg) of the true extent in any direction.
constexpr int kCapCorners = 8;
// [ch13-cylinder-features]

/// Candidates of a pair in which at least one shape is a cylinder, from chapter 3's query of the
/// pair (in the same frame). False when neither feature rule applies (leave it to a single point).
bool cylinderManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                      const ContactQuery& query, Real keepDistance, ManifoldCandidates& out);

}  // namespace stepwise
