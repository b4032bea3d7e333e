#pragma once
// A bounding volume hierarchy over a triangle mesh's triangles: a binary tree of axis-aligned
// boxes, built once when the mesh is made and asked every step which triangles lie near a body.
//
// Built top down (Ericson, "Real-Time Collision Detection", 2005, 6.2.1): a node's triangles are
// split in two halves by count at the median of their centroids along the axis on which the
// centroids spread most, until a node holds at most kMeshTreeLeafTriangles. Binned SAH, the
// surface area heuristic over 16 bins per axis (Wald, "On fast Construction of SAH-based
// Bounding Volume Hierarchies", IEEE Symposium on Interactive Ray Tracing, 2007), was measured
// against it on 100,000 triangles: on a terrain it answered 1 m box queries no faster, on a soup
// of random triangles and on a level mixing large slabs with small props up to a third faster
// (a fraction of a microsecond either way), for a build 1.5 to 2 times as long. The
// median split stays because it is simpler and because it halves the count at every level: the
// depth stays under log2 of the triangle count, so the query's stack is a fixed array that cannot
// overflow, where an SAH tree's depth has no such bound.
//
// The nodes lie in one vector in depth-first order: a node's first child is the next node, its
// second child is named by index. The tree keeps its own copy of each triangle's box in leaf
// order, so a query reads two contiguous arrays and never the mesh's scattered vertices (that
// made the query 1.5 to 2 times faster in the same measurement, for 24 bytes per triangle).

#include "world/shape.h"

#include <vector>

namespace stepwise {

/// The most triangles a leaf holds. A leaf's boxes are tested one after another from one array,
/// each test as cheap as a node's without the jump to the next node; of leaves of 1, 2, 4 and 8
/// triangles, 4 answered 1 m queries fastest or within noise of the fastest on every mesh
/// measured, with half the nodes of 2 (Jolt's mesh shape allows up to 8).
constexpr int kMeshTreeLeafTriangles = 4;

/// Deeper than a median-split tree over 2^31 triangles can be (each level halves the count),
/// so the query's stack never overflows.
constexpr int kMeshTreeMaxDepth = 64;

/// One node. An inner node has two children: the node right after it and `secondChild`; its
/// `triangleCount` is 0. A leaf names `triangleCount` entries of MeshTree::triangles from
/// `firstTriangle`; its `secondChild` is -1.
struct MeshTreeNode {
    Aabb box;               // holds the boxes of every triangle below, mesh frame
    int secondChild = -1;
    int firstTriangle = 0;
    int triangleCount = 0;
};

/// The tree of one mesh: nodes[0] is the root (no nodes for a mesh without triangles);
/// `triangles` holds every triangle index once, each leaf's run in ascending order, and
/// triangleBoxes[i] is the box of triangle triangles[i].
struct MeshTree {
    std::vector<MeshTreeNode> nodes;
    std::vector<int> triangles;
    std::vector<Aabb> triangleBoxes;
};

/// The box of one triangle: its three corners'.
Aabb meshTriangleBox(const TriangleMesh& mesh, int triangle);

/// Builds the tree over every triangle of the mesh, whose vertices must be finite (as
/// Shape::triangleMesh makes sure). The same mesh gives the same tree on every platform: ties
/// between equal centroids are broken by triangle index.
MeshTree buildMeshTree(const TriangleMesh& mesh);

/// Appends to `triangles` the index of every triangle whose box (meshTriangleBox) overlaps `box`
/// (mesh frame, touching counts), each once, in the tree's leaf order. It does not clear the
/// list: a caller that gathers from several meshes or several boxes clears it when it wants to.
/// An empty box (min > max) or one with a NaN finds nothing. `mesh` is the mesh the tree was
/// built over (debug builds check that their triangle counts agree); the query reads only the
/// boxes the tree keeps.
void queryMeshTree(const MeshTree& tree, const TriangleMesh& mesh, const Aabb& box, std::vector<int>& triangles);

}  // namespace stepwise
