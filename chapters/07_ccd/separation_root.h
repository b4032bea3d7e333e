#pragma once
// The other way to a time of impact, for comparison: Box2D's b2TimeOfImpact (Catto, "Continuous
// Collision", GDC 2013) finds the closest features with GJK once, then solves for the time at
// which their separation reaches the target by bisection and false position, instead of
// advancing by a motion bound. Written here with one kind of separation function: the gap along
// the closest direction, held fixed in the world (Box2D also has face functions that turn with a
// body). The gap along a fixed direction is never more than the distance, so every root it finds
// is safe; `stepwise bench ccd` measures it against conservative advancement. The stage uses
// conservative advancement (time_of_impact.h).

#include "07_ccd/time_of_impact.h"

namespace stepwise {

/// Root iterations per separating axis (bisection and false position, alternating).
constexpr int kRootMaxIterations = 50;

/// The same question as timeOfImpact(), answered by root finding on the separation along the
/// closest direction; ToiResult::iterations counts GJK queries and root steps together.
ToiResult timeOfImpactByRoots(const Shape& shapeA, const Sweep& a, const Shape& shapeB, const Sweep& b,
                              const ToiOptions& options);

}  // namespace stepwise
