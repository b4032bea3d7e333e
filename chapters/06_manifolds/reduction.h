#pragma once
// Reducing a clipped patch to at most four points. Four points that span the patch hold a box as
// well as all of them do (the solver's rows for more points would only be redundant), and a fixed
// four keeps the cost per pair bounded.

#include "06_manifolds/manifold_point.h"

namespace stepwise {

constexpr int kMaxManifoldPoints = 4;

/// Indices of at most four of `points` (candidates in the plane of `normal`): the deepest (of those
/// equally deep, the farthest from the patch's centre), the one
/// farthest from it, the one making the largest triangle with those two, and the one adding the
/// most area on the other side (Gregorius, "Robust Contact Creation for Physics Simulations",
/// GDC 2015; Box3D's convex manifold reduction); the last three from the touching points (depth
/// within 0.1 mm of zero or more) while those give an answer, then from all. Returns how many
/// were chosen, in that order.
int reduceManifold(const std::vector<ManifoldPoint>& points, const Vec3& normal, int chosen[kMaxManifoldPoints]);

}  // namespace stepwise
