#pragma once
// A triangle of a mesh or a height field as a convex solid. GJK and EPA measure depths of volumes,
// and chapter 6's clipping takes faces, so a triangle is taken as the prism between it and its
// copy kPrismDepth behind its front: a one-sided slab whose front face is the triangle. A body
// that reaches a triangle from behind is pushed out through the front, as a terrain should (the
// ground is solid below its surface); the prism's side faces are what a body crossing from one
// triangle to the next can catch on, which the mesh's inactive edges correct (triangle_edges.h).

#include "world/shape.h"

namespace stepwise {

// [ch13-prism-depth]
/// How far behind its front a triangle's prism reaches, m: deeper than a body sinks into the
/// ground in a step (a 10 m/s fall at 60 Hz moves 17 cm; the speculative contact stops it before),
/// shallow enough that a thin wall's two sides stay apart in a level a metre thick.
constexpr Real kPrismDepth = Real(0.5);
// [ch13-prism-depth]

/// The prism of the triangle (a, b, c), counter-clockwise seen from its front, in the frame the
/// corners are given in: vertices 0-2 the triangle, 3-5 behind it; faces 0 the front, 1 the back,
/// 2-4 the sides of edges (a, b), (b, c), (c, a).
Shape trianglePrism(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace stepwise
