#pragma once
// Shapes and poses drawn from fuzzer bytes, for the narrowphase and stepper targets: every kind
// of shape, and convex hulls made to be hard (flat, needle-like, with duplicated points, with
// many nearly coplanar points).

#include "fuzz_input.h"

#include "math/math.h"
#include "world/shape.h"

#include <optional>

namespace stepwise::fuzz {

/// A shape of any kind whose bounding radius is about `size` (hulls may be thinner).
/// nullopt when the drawn points span no volume (the hull builder rejects them, correctly).
std::optional<Shape> randomShape(FuzzInput& input, double size);

/// randomShape's kinds, or one time in six a compound of two or three of them: a body's shape.
std::optional<Shape> randomBodyShape(FuzzInput& input, double size);

/// A ground for the whole step: nullopt (a box, the caller's), a triangle mesh or a height field
/// (with holes) of 12 x 12 cells of random size and heights, from nearly flat to spiky, starting
/// at the origin and running along +x and +z.
std::optional<Shape> randomGround(FuzzInput& input);

/// A uniformly random rotation.
Quat randomRotation(FuzzInput& input);

/// The signed distance of a point (in the shape's frame) to the shape's surface: < 0 inside.
/// Exact for boxes, spheres and capsules; for hulls the largest face-plane distance, exact
/// inside and never larger than the true distance outside.
double signedDistance(const Shape& shape, const Eigen::Vector3d& localPoint);

}  // namespace stepwise::fuzz
