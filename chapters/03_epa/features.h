#pragma once
// Feature ids for contacts that GJK and EPA found. EPA ends on a face of the Minkowski
// difference whose three vertices are differences of support points, a_i - b_i. The distinct
// a_i name a feature of A (one corner, an edge between two, a face through three), the
// distinct b_i one of B; together they name the contact, the same way from step to step while
// the same corner touches the same face. Chapter 6 names its clipped points by the
// faces and edges that made them.

#include "02_gjk/support.h"

#include <cstdint>

namespace stepwise {

/// The index of the shape's vertex at a local support point: a box corner by its sign bits, a
/// hull vertex by nearest match, a capsule's cap (0 bottom, 1 top). Spheres have none: -1.
int supportVertexIndex(const Shape& shape, const Vec3& localPoint);

/// The feature of one shape spanned by up to three world support points (world/contact.h).
std::uint32_t supportFeature(const Shape& shape, const Transform& transform, const Vec3 worldPoints[3]);

/// The feature id of EPA's closest face: A's feature and B's.
std::uint32_t epaFeatureId(const ConvexProxy& a, const ConvexProxy& b, const SupportPoint face[3]);

}  // namespace stepwise
