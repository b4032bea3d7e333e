#pragma once
// The faces and edges of the polytopes (boxes and convex hulls) that clipping needs. A box is
// described here the way chapter 1's hull faces are: six faces, each a counter-clockwise polygon
// seen from outside with an outward normal, so the manifold code treats both shapes alike.

#include "world/shape.h"

#include <cstdint>
#include <vector>

namespace stepwise {

/// Faces and edges: boxes and convex hulls. Spheres and capsules are round (round_manifolds.h).
bool isPolytope(const Shape& shape);

int polytopeFaceCount(const Shape& shape);

/// One face in the body frame: outward unit normal, plane offset (dot(normal, x) = offset), the
/// corners counter-clockwise seen from outside and their vertex indices (a box corner's index is
/// its sign bits, as chapter 3's supportVertexIndex numbers them).
struct FacePolygon {
    int index = -1;
    Vec3 normal = Vec3::Zero();
    Real offset = 0;
    std::vector<Vec3> corners;
    std::vector<int> vertexIndices;
};

/// Face `face` of a box or hull, body frame. Empty corners for other shapes or a bad index.
FacePolygon polytopeFace(const Shape& shape, int face);
/// The same into `polygon`, whose vectors keep their room from call to call (the narrowphase
/// builds two faces a pair and allocates nothing once it has seen the largest).
void polytopeFace(const Shape& shape, int face, FacePolygon& polygon);

/// The outward normal of face `face`, body frame (no corners built).
Vec3 polytopeFaceNormal(const Shape& shape, int face);

/// The face whose world normal is most aligned with worldDirection; its dot product in
/// `alignment`. -1 when the shape has no faces.
int mostAlignedFace(const Shape& shape, const Transform& transform, const Vec3& worldDirection, Real& alignment);

/// The vertex farthest along localDirection, body frame.
Vec3 polytopeSupport(const Shape& shape, const Vec3& localDirection);

/// How far `other` lies outside face `face` of `shape` (negative: it reaches below the face's
/// plane): min over other's vertices of n . x - offset, in world units. SAT's face query (Ericson,
/// Real-Time Collision Detection, 5.2.1; Gregorius, "The Separating Axis Test between Convex
/// Polyhedra", GDC 2013).
Real faceSeparation(const Shape& shape, const Transform& transform, int face, const Shape& other,
                    const Transform& otherTransform);

/// An edge in the body frame, named by its two vertex indices (edgeIndexOf), the same whichever
/// face lists it.
struct PolytopeEdge {
    Vec3 start = Vec3::Zero();
    Vec3 end = Vec3::Zero();
    std::uint32_t id = 0;
};

/// Every edge of a box (12) or hull, body frame.
std::vector<PolytopeEdge> polytopeEdges(const Shape& shape);

/// The index of the edge between two vertices, for feature ids: lower * 128 + higher. Box corners
/// (0..7) and the vertices of hulls up to 64 points get distinct indices; beyond, the 13 bits of a
/// feature index (world/contact.h) wrap and two edges may share an id, which only makes matching
/// fall back to the anchor distance more often.
constexpr std::uint32_t edgeIndexOf(int vertex0, int vertex1) {
    return static_cast<std::uint32_t>(vertex0 < vertex1 ? vertex0 : vertex1) * 128u +
           static_cast<std::uint32_t>(vertex0 < vertex1 ? vertex1 : vertex0);
}

}  // namespace stepwise
