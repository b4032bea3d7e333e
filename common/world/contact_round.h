#pragma once
// Which contacts roll: a point on a round surface does not turn with its body (a rolling ball's
// lowest point stays lowest), so a solve that moves contact points with their bodies within a
// frame moves a round shape's points with its core (a sphere's centre, a capsule's segment, a
// cylinder's axis) instead (chapter 11's arms, chapter 6's round manifolds).

#include "world/shape.h"

namespace stepwise {

/// A cylinder's side rolls while the contact normal is this close to square to its axis
/// (|axis . n| below it, 3 degrees); on its caps and rims it has corners.
constexpr Real kRollingSideCosine = Real(0.05);

/// How far a contact of world normal `normal` lies outside the core it rolls on: a sphere's or a
/// capsule's radius, a cylinder's radius when the normal is across its axis, 0 otherwise.
Real contactRoundRadius(const Shape& shape, const Transform& pose, const Vec3& normal);

}  // namespace stepwise
