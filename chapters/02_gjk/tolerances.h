#pragma once
// Collision tolerances, in one place, shared by GJK (chapter 2) and EPA (chapter 3). Each is a
// multiple of the machine epsilon, relative to the size of the pair (shapeScale of both shapes,
// in metres), so a 1 mm and a 1 km pair get the same relative treatment and Real = float and
// Real = double both work. (Box2D v3 keeps its tolerances in one constants.h the same way.)

#include "math/math.h"

namespace stepwise::tolerance {

// [ch02-tolerance-constants]
/// GJK: shapes closer than this (times the pair's size, m) touch, and a distance step smaller
/// than this fraction is no progress. A hundred rounding errors of a support point.
constexpr Real kTouching = Real(100) * kEpsilon;

/// EPA's seed tetrahedron must hold the origin to within this (times the pair's size, m):
/// a little looser than kTouching, so that every simplex GJK called touching is accepted.
constexpr Real kSeedContainment = Real(128) * kEpsilon;

/// A length, area or volume (relative to the pair's size to the power 1, 2 or 3) below this
/// counts as zero: a few hundred rounding errors, so that slivers are classified as slivers.
constexpr Real kDegenerateFraction = Real(256) * kEpsilon;

/// The finest gap (relative to the pair's size) a float dot product of such vectors can decide:
/// EPA treats smaller gaps as zero instead of chasing them.
constexpr Real kRoundOff = Real(8) * kEpsilon;

/// An EPA face is too thin to have a trustworthy normal when its cross product is within this
/// factor of the round-off the cross product itself carries (the normal would be off by > 1/64 rad).
constexpr Real kThinFace = 64;

/// Two EPA faces whose unit normals agree this well (cosine; 0.26 degrees) lie in one plane.
constexpr Real kCoplanar = Real(0.99999);
// [ch02-tolerance-constants]

}  // namespace stepwise::tolerance
