#pragma once
// Chapter 2's demo scenes. The builders are public so the tests run the very scenes the demo
// shows.

#include "02_gjk/gjk.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

class DebugDraw;
class Registry;

/// A cube tumbling slowly at the origin and a plank spinning next to it (both kinematic): the
/// plank's end sweeps through the cube and out again, over and over.
World buildGjkTwoBoxes();

/// A static sphere and a spinning octahedron ("diamond" hull) whose tips dip into it.
World buildGjkSphereDiamond();

/// Points of the Minkowski difference A - B of two bodies, for drawing: every corner difference
/// when both are polytopes (64 for two boxes); a round shape contributes support points in
/// spread directions instead of corners (at most kMaxHullPoints differences in all then).
std::vector<Vec3> minkowskiPoints(const Body& a, const Body& b, SupportMode mode);

/// The GJK overlay for bodies 0 and 1: the pair in red while GJK says they intersect, A - B
/// (points and hull) with the origin marked and the final simplex, drawn around `anchor`, and
/// the iteration count as text.
void drawGjkOverlay(const World& world, DebugDraw& draw, SupportMode mode, const Vec3& anchor);

void addChapter02Scenes(Registry& registry);

}  // namespace stepwise
