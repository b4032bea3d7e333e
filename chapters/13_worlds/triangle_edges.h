#pragma once
// Which triangle edges a body may really hit: the cure for ghost collisions. A body sliding
// across a floor made of triangles overlaps the next triangle a little before it leaves the one it
// is on; tested against that next triangle alone, its shortest way out is back across the
// seam's edge, and the contact stops it as if it had tripped on a crack (Catto, "Ghost
// Collisions", Box2D blog, 2020; Box2D's chain shapes give each segment its neighbours' ghost
// vertices for the same reason, in 2D). The edge is no edge of the surface: the surface
// continues beyond it.
//
// Each triangle edge is therefore marked active (a real edge of the surface, whose contact
// normals are true) or inactive (a seam inside a surface that continues, whose only true normal
// is the face's), as Jolt does (Rouwe, ActiveEdges.h and the mesh shape's active edge threshold,
// 2021) and Bullet's internal edge utility before it (Coumans, btInternalEdgeUtility, 2010):
//   - an edge of one triangle (the mesh's boundary) is active;
//   - an edge of two triangles is inactive when they are coplanar or bend convexly by less than
//     kActiveEdgeAngle, and inactive whenever they bend concavely, however sharply: a convex
//     body in a valley touches both faces, whose own normals push it out, and the edge's normals
//     only lie between them; it is active when it bends convexly by more, or when the two lie
//     back to back (a fin, or a sheet seen from both sides), where convex cannot be told from
//     concave;
//   - an edge of three or more triangles (no surface's edge at all; Jolt marks it active too)
//     and an edge whose two triangles disagree on their front (opposite windings) are active:
//     nothing says their normals are false, and a missed contact costs more than a ghost one.
//
// Edges are matched by their vertex indices only: a mesh exported as a soup of separate
// triangles, or one with T-junctions, has every edge on its boundary, all active, until its
// vertices are welded. Marks live per triangle edge, so a vertex is judged by the two edges of
// the triangle that meet there. That has a blind spot, which Jolt's flags share: where a fan of
// triangles meets the mesh's boundary only at a vertex, the middle triangle's edges there are
// inactive, and a body pushing sideways against that corner gets the face normal.

#include "world/shape.h"

#include <array>
#include <vector>

namespace stepwise {

/// The convex bend, radians, below which an edge between two triangles is inactive. Jolt's
/// default (cos 5 degrees): a curved surface tessellated for games (rolling terrain, a ramp's
/// rounded lip) bends a few degrees per edge, and a body sliding over it must not catch there;
/// the contact normal that replaces the edge's is then at most this far from the true one.
constexpr Real kActiveEdgeAngle = 5 * kDegree;
constexpr Real kActiveEdgeCos = Real(0.99619469809174553);  // cos(kActiveEdgeAngle)

/// Two faces whose normals are closer to opposite than this (cos 179 degrees) lie back to back:
/// their cross product is too short to tell a convex bend from a concave one.
constexpr Real kBackToBackCos = Real(-0.99984769515639124);

/// How close to an edge a contact point counts as on it, as a fraction of the triangle's longest
/// edge. Contact points come from clipping and from EPA (relative tolerance 1e-5), both in the
/// float round-off of coordinates up to a few hundred metres from the mesh's origin (1e-4 of a
/// metre-sized triangle); a point this close to an inactive edge gets the face normal, which is
/// the right normal for an interior point too, so a generous band costs nothing.
constexpr Real kEdgeContactFraction = Real(1e-3);

/// A normal this close to the face normal (cosine; about 0.08 degrees) already is it: it is
/// returned as it came, bit for bit, so a contact that persists keeps its normal.
constexpr Real kSameNormalCos = Real(1) - Real(1e-6);

/// Per triangle and edge (edge k runs from corner k to corner (k + 1) % 3): the triangle across
/// it, -1 on the boundary (and for an edge of three or more triangles), and whether it is active.
struct TriangleEdges {
    std::vector<std::array<int, 3>> neighbour;
    std::vector<std::array<bool, 3>> active;
};

/// The rule above for an edge shared by two triangles with consistent windings: `faceNormal` and
/// `neighbourNormal` are the two faces' normals (any length: cross products will do), `edge` runs
/// along the shared edge in the first face's winding. A face without area (a zero normal) makes
/// the edge active.
bool isEdgeActive(const Vec3& faceNormal, const Vec3& neighbourNormal, const Vec3& edge);

/// Neighbours and active flags of every edge of the mesh, matched by shared vertex indices.
TriangleEdges findTriangleEdges(const TriangleMesh& mesh);

/// The normal a contact with one triangle should have. `triangle` holds its corners, `normal`
/// points out of the triangle's side towards the body (unit), `pointOnTriangle` is the contact's
/// point on it, all in one frame. Returns the face normal (unit, out of the front: meshes are
/// one-sided) when the point lies on an inactive edge, or at a vertex whose two edges in this
/// triangle are both inactive, and `normal` is not already the face normal; otherwise `normal`
/// unchanged (an interior point, an active edge, a triangle without area).
Vec3 correctedNormal(const Vec3 triangle[3], const std::array<bool, 3>& activeEdges, const Vec3& pointOnTriangle,
                     const Vec3& normal);

/// The triangle across edge `edge` of a height field's triangle (the grid's own adjacency; edges
/// numbered as heightFieldTriangle's corners), or -1 past the grid's border or in a hole.
int heightFieldNeighbour(const HeightField& field, int triangle, int edge);

/// The active flags of a height field triangle's edges, by the same rules as findTriangleEdges;
/// a hole's neighbour counts as the boundary. A triangle in a hole gets all three active. Reads
/// four triangles' corners: cheap enough per contact, or cache it per triangle.
std::array<bool, 3> heightFieldActiveEdges(const HeightField& field, int triangle);

}  // namespace stepwise
