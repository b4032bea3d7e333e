#include "13_worlds/mesh_tree.h"

#include <algorithm>
#include <cassert>

namespace stepwise {

namespace {

/// What the build reads for every triangle, computed once: its box and its centroid (times 3:
/// the sum of its corners orders the triangles as the centroid does, without a division).
struct MeshTreeScratch {
    std::vector<Aabb> boxes;
    std::vector<Vec3> centroidSums;
};

MeshTreeScratch meshTreeScratch(const TriangleMesh& mesh) {
    MeshTreeScratch scratch;
    const int count = static_cast<int>(mesh.triangles.size());
    scratch.boxes.resize(count);
    scratch.centroidSums.resize(count);
    for (int t = 0; t < count; ++t) {
        const std::array<int, 3>& corners = mesh.triangles[t];
        scratch.boxes[t] = meshTriangleBox(mesh, t);
        scratch.centroidSums[t] = mesh.vertices[corners[0]] + mesh.vertices[corners[1]] + mesh.vertices[corners[2]];
    }
    return scratch;
}

/// The axis along which the centroids of triangles [first, first + count) spread most (ties: the
/// lower axis). Their spread, not the node box's: long triangles can stretch the box along an axis
/// on which their centroids all coincide, and a split there would separate nothing.
int meshTreeSplitAxis(const MeshTreeScratch& scratch, const std::vector<int>& order, int first, int count) {
    Aabb spread;
    for (int i = first; i < first + count; ++i) spread.grow(scratch.centroidSums[order[i]]);
    const Vec3 size = spread.max - spread.min;
    int axis = 0;
    if (size.y() > size[axis]) axis = 1;
    if (size.z() > size[axis]) axis = 2;
    return axis;
}

/// Adds the node over entries [first, first + count) of tree.triangles, then its subtree, depth
/// first, reordering the entries as it splits them.
/// Recursion is safe here: every split halves the count, so the depth stays under 32.
void meshTreeBuildNode(MeshTree& tree, const MeshTreeScratch& scratch, int first, int count, int depth) {
    assert(depth < kMeshTreeMaxDepth);
    const int index = static_cast<int>(tree.nodes.size());
    tree.nodes.emplace_back();
    Aabb box;
    for (int i = first; i < first + count; ++i) box.grow(scratch.boxes[tree.triangles[i]]);
    tree.nodes[index].box = box;

    std::vector<int>& order = tree.triangles;
    if (count <= kMeshTreeLeafTriangles) {
        // Ascending inside a leaf: the query's answer then does not depend on how the standard
        // library's nth_element left the run.
        std::sort(order.begin() + first, order.begin() + first + count);
        tree.nodes[index].firstTriangle = first;
        tree.nodes[index].triangleCount = count;
        return;
    }
    // Partition at the median by count, ties broken by index: the lower half holds exactly the
    // count / 2 triangles that come first in this total order, whatever the library.
    const int axis = meshTreeSplitAxis(scratch, order, first, count);
    const int half = count / 2;
    std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                     [&scratch, axis](int a, int b) {
                         const Real ca = scratch.centroidSums[a][axis];
                         const Real cb = scratch.centroidSums[b][axis];
                         return ca < cb || (ca == cb && a < b);
                     });
    meshTreeBuildNode(tree, scratch, first, half, depth + 1);
    tree.nodes[index].secondChild = static_cast<int>(tree.nodes.size());
    meshTreeBuildNode(tree, scratch, first + half, count - half, depth + 1);
}

}  // namespace

Aabb meshTriangleBox(const TriangleMesh& mesh, int triangle) {
    const std::array<int, 3>& corners = mesh.triangles[triangle];
    Aabb box;
    for (int corner : corners) box.grow(mesh.vertices[corner]);
    return box;
}

MeshTree buildMeshTree(const TriangleMesh& mesh) {
    MeshTree tree;
    const int count = static_cast<int>(mesh.triangles.size());
    if (count == 0) return tree;
    const MeshTreeScratch scratch = meshTreeScratch(mesh);
    tree.triangles.resize(count);
    for (int t = 0; t < count; ++t) tree.triangles[t] = t;
    // A split of more than four triangles leaves two or more on each side, so a mesh of two or
    // more triangles has at most count / 2 leaves and fewer than count nodes.
    tree.nodes.reserve(count);
    meshTreeBuildNode(tree, scratch, 0, count, 0);
    tree.triangleBoxes.resize(count);
    for (int i = 0; i < count; ++i) tree.triangleBoxes[i] = scratch.boxes[tree.triangles[i]];
    return tree;
}

// [ch13-tree-query]
void queryMeshTree(const MeshTree& tree, [[maybe_unused]] const TriangleMesh& mesh, const Aabb& box,
                   std::vector<int>& triangles) {
    assert(tree.triangleBoxes.size() == mesh.triangles.size());
    if (tree.nodes.empty()) return;
    // Nodes still to visit: the second child of every inner node on the path down, at most one
    // per level.
    int pending[kMeshTreeMaxDepth];
    int pendingCount = 0;
    int node = 0;
    for (;;) {
        const MeshTreeNode& current = tree.nodes[node];
        if (current.box.overlaps(box)) {
            if (current.triangleCount == 0) {
                pending[pendingCount++] = current.secondChild;
                node = node + 1;  // the first child follows its parent
                continue;
            }
            const int end = current.firstTriangle + current.triangleCount;
            for (int i = current.firstTriangle; i < end; ++i) {
                if (tree.triangleBoxes[i].overlaps(box)) triangles.push_back(tree.triangles[i]);
            }
        }
        if (pendingCount == 0) return;
        node = pending[--pendingCount];
    }
}
// [ch13-tree-query]

}  // namespace stepwise
