#pragma once
// Chapter 13's manifolds: the pairs with a compound, a mesh, a height field or a cylinder. Each
// such shape is taken apart into convex parts near the other body (a compound's children, the
// triangles the mesh's tree or the height field's grid finds under the other body's box, each as
// its prism), every pair of parts is collided as chapter 6 collides two convex shapes (a cylinder
// by cylinder_manifold.h), and the parts' points become the pair's one manifold:
//   - its normal is the deepest part contact's;
//   - every part contact whose normal is within kMergeAngle of it gives its points, their depths
//     along the common normal; the rest wait for the deepest to change;
//   - chapter 6's reduction keeps four, and each point's feature id names its parts, so that
//     chapter 6's persistence matches it from frame to frame.
// A triangle's contact whose normal is not the triangle's own, at an edge the mesh marks inactive
// (a seam between coplanar triangles), takes the triangle's normal: the internal-edge correction.

#include "06_manifolds/manifold.h"
#include "13_worlds/mesh_tree.h"
#include "13_worlds/triangle_edges.h"

#include <memory>
#include <unordered_map>
#include <vector>

namespace stepwise {

// [ch13-merge-angle]
/// A part contact joins the pair's manifold while its normal is within this angle of the deepest
/// one's (rad): a box across two triangles of gently rolling ground keeps both; one wedged in a
/// V-shaped groove takes one side at a time (a body pair has one normal in chapter 6's solve).
constexpr Real kMergeAngle = Real(0.35);
// [ch13-merge-angle]

/// What the manifold function keeps from frame to frame: each mesh's tree and edges, built the
/// first time the mesh is met (the mesh never changes; the pointer it holds keeps it alive).
struct WorldShapesCache {
    struct MeshEntry {
        std::shared_ptr<const TriangleMesh> mesh;
        MeshTree tree;
        TriangleEdges edges;
    };
    std::unordered_map<const TriangleMesh*, MeshEntry> meshes;
    bool internalEdgeFix = true;  // false: no correction (the demo's and the bench's A/B)
    const MeshEntry& entry(const std::shared_ptr<const TriangleMesh>& mesh);
};

/// Whether a pair is chapter 13's: one of its shapes is a compound, a mesh, a height field or a
/// cylinder.
bool isWorldPair(const Shape& a, const Shape& b);

/// ManifoldOptions::pairManifold for chapter 13 (handled only for world pairs).
PairManifold worldManifold(WorldShapesCache& cache, const Shape& a, const Transform& ta, const Shape& b,
                           const Transform& tb, Real keepDistance, const Contact* previous, Contact& contact);

/// The function chapter 13's pipeline hands chapter 6, holding `cache`.
PairManifoldFunction worldManifoldFunction(std::shared_ptr<WorldShapesCache> cache);

}  // namespace stepwise
