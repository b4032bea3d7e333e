// The mesh tree against brute force: a query finds exactly the triangles whose boxes overlap the
// box, each once, on random soups (slivers, duplicates and all), on terrain grids and on a
// single triangle; every triangle sits in exactly one leaf, and every box holds what is below it.
#include "13_worlds/mesh_tree.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace stepwise;

namespace {

Real meshTreeTestUniform(Random& random, Real low, Real high) { return random.uniformReal(low, high); }

/// Draws x, then y, then z: in one call's arguments the order would be the compiler's, and the
/// meshes would differ between GCC and Clang.
Vec3 meshTreeTestPoint(Random& random, Real halfSize) {
    const Real x = meshTreeTestUniform(random, -halfSize, halfSize);
    const Real y = meshTreeTestUniform(random, -halfSize, halfSize);
    const Real z = meshTreeTestUniform(random, -halfSize, halfSize);
    return Vec3(x, y, z);
}

/// A soup of `count` triangles in a 20 m cube: small and large ones, slivers (a corner a hair off
/// the opposite edge), needles (two corners nearly together), exact duplicates (equal centroids)
/// and axis-aligned flat ones (a box of zero thickness).
TriangleMesh meshTreeTestSoup(Random& random, int count) {
    TriangleMesh mesh;
    for (int t = 0; t < count; ++t) {
        const int first = static_cast<int>(mesh.vertices.size());
        const int kind = t % 5;
        if (kind == 4 && t > 0) {  // a duplicate of the previous triangle, over the same vertices
            mesh.triangles.push_back(mesh.triangles.back());
            continue;
        }
        const Vec3 a = meshTreeTestPoint(random, 10);
        const Real size = meshTreeTestUniform(random, Real(0.01), Real(3));
        Vec3 b = a + size * random.unitVector();
        Vec3 c = a + size * random.unitVector();
        if (kind == 1) c = a + (b - a) * Real(0.5) + Real(1e-4) * random.unitVector();  // sliver
        if (kind == 2) b = a + Real(1e-4) * random.unitVector();                        // needle
        if (kind == 3) b.y() = c.y() = a.y();                                           // flat in y
        mesh.vertices.insert(mesh.vertices.end(), {a, b, c});
        mesh.triangles.push_back({first, first + 1, first + 2});
    }
    for (const Vec3& v : mesh.vertices) mesh.bounds.grow(v);
    return mesh;
}

/// A terrain of n x n quads, two triangles each, over shared vertices, 1 m apart, with random
/// heights of up to 0.5 m.
TriangleMesh meshTreeTestGrid(Random& random, int n) {
    TriangleMesh mesh;
    for (int r = 0; r <= n; ++r) {
        for (int c = 0; c <= n; ++c) mesh.vertices.emplace_back(Real(c), meshTreeTestUniform(random, 0, Real(0.5)), Real(r));
    }
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < n; ++c) {
            const int a = r * (n + 1) + c, b = a + 1, below = a + n + 1, d = below + 1;
            mesh.triangles.push_back({a, d, b});
            mesh.triangles.push_back({a, below, d});
        }
    }
    for (const Vec3& v : mesh.vertices) mesh.bounds.grow(v);
    return mesh;
}

std::vector<int> meshTreeTestBruteForce(const TriangleMesh& mesh, const Aabb& box) {
    std::vector<int> found;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
        Aabb triangleBox;
        for (int corner : mesh.triangles[t]) triangleBox.grow(mesh.vertices[corner]);
        if (triangleBox.overlaps(box)) found.push_back(t);
    }
    return found;
}

/// A box of random size (a point, thin slabs, up to larger than the mesh) somewhere around the
/// mesh's bounds.
Aabb meshTreeTestBox(Random& random, const TriangleMesh& mesh) {
    const Aabb& around = mesh.bounds;
    // Half of them centred on a vertex, so sparse soups get met too.
    const int vertex = static_cast<int>(random.uniform() * static_cast<double>(mesh.vertices.size()));
    const Vec3 reach = around.extents() + Vec3::Constant(1);
    const Vec3 centre = random.uniform() < 0.5 ? mesh.vertices[vertex]
                                               : around.center() + reach.cwiseProduct(meshTreeTestPoint(random, 1));
    Vec3 half = meshTreeTestPoint(random, 2).cwiseAbs();
    const int shape = static_cast<int>(random.uniform() * 4);
    if (shape == 0) half = Vec3::Zero();                                   // a point
    if (shape == 1) half.y() = 0;                                          // a slab
    if (shape == 2) half *= meshTreeTestUniform(random, 1, 20);            // large
    Aabb box;
    box.min = centre - half;
    box.max = centre + half;
    return box;
}

void meshTreeTestMatchesBruteForce(const TriangleMesh& mesh, Random& random, int queries) {
    const MeshTree tree = buildMeshTree(mesh);
    int nonEmpty = 0;
    for (int q = 0; q < queries; ++q) {
        const Aabb box = meshTreeTestBox(random, mesh);
        std::vector<int> found;
        queryMeshTree(tree, mesh, box, found);
        std::vector<int> sorted = found;
        std::sort(sorted.begin(), sorted.end());
        CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());  // each once
        const std::vector<int> expected = meshTreeTestBruteForce(mesh, box);
        CHECK(sorted == expected);
        if (!expected.empty()) ++nonEmpty;
    }
    CHECK(nonEmpty > queries / 3);  // the boxes did meet the mesh
    CHECK(nonEmpty < queries);      // and some missed it
}

}  // namespace

TEST_CASE("a mesh tree query finds exactly the triangles whose boxes overlap the box, each once", "[ch13]") {
    Random random(1301);
    SECTION("random soups with slivers, needles, flat and duplicate triangles") {
        for (int count : {2, 5, 17, 300, 5000}) {
            INFO("triangles: " << count);
            meshTreeTestMatchesBruteForce(meshTreeTestSoup(random, count), random, 300);
        }
    }
    SECTION("terrain grids") {
        for (int n : {1, 3, 40}) {
            INFO("grid: " << n);
            meshTreeTestMatchesBruteForce(meshTreeTestGrid(random, n), random, 300);
        }
    }
    SECTION("a single triangle") {
        TriangleMesh mesh;
        mesh.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0)};
        mesh.triangles = {{0, 1, 2}};
        for (const Vec3& v : mesh.vertices) mesh.bounds.grow(v);
        meshTreeTestMatchesBruteForce(mesh, random, 200);
    }
}

TEST_CASE("every triangle sits in exactly one leaf, in ascending runs, and every node's box holds everything below it",
          "[ch13]") {
    Random random(1302);
    for (int count : {1, 4, 5, 9, 1000, 4097}) {
        INFO("triangles: " << count);
        const TriangleMesh mesh = meshTreeTestSoup(random, count);
        const MeshTree tree = buildMeshTree(mesh);
        REQUIRE(!tree.nodes.empty());
        std::vector<int> seen(count, 0);
        // Walk the tree from the root, following the child links, so a node no link reaches is
        // not counted either.
        std::vector<int> pending = {0};
        int visited = 0, deepest = 0;
        std::vector<int> depth(tree.nodes.size(), 0);
        while (!pending.empty()) {
            const int index = pending.back();
            pending.pop_back();
            ++visited;
            deepest = std::max(deepest, depth[index]);
            const MeshTreeNode& node = tree.nodes[index];
            if (node.triangleCount > 0) {
                CHECK(node.secondChild == -1);
                CHECK(node.triangleCount <= kMeshTreeLeafTriangles);
                // Ascending, so the answer's order does not depend on the standard library.
                const auto run = tree.triangles.begin() + node.firstTriangle;
                CHECK(std::is_sorted(run, run + node.triangleCount));
                for (int i = node.firstTriangle; i < node.firstTriangle + node.triangleCount; ++i) {
                    const int triangle = tree.triangles[i];
                    ++seen[triangle];
                    const Aabb box = meshTriangleBox(mesh, triangle);
                    CHECK(((node.box.min.array() <= box.min.array()).all() && (box.max.array() <= node.box.max.array()).all()));
                }
                continue;
            }
            REQUIRE(node.secondChild > index + 1);
            REQUIRE(node.secondChild < static_cast<int>(tree.nodes.size()));
            for (int child : {index + 1, node.secondChild}) {
                const Aabb& inner = tree.nodes[child].box;
                CHECK(((node.box.min.array() <= inner.min.array()).all() && (inner.max.array() <= node.box.max.array()).all()));
                depth[child] = depth[index] + 1;
                pending.push_back(child);
            }
        }
        CHECK(visited == static_cast<int>(tree.nodes.size()));
        CHECK(std::all_of(seen.begin(), seen.end(), [](int times) { return times == 1; }));
        CHECK(tree.triangles.size() == static_cast<size_t>(count));
        // The median split halves the count at each level.
        CHECK(deepest <= static_cast<int>(std::ceil(std::log2(std::max(count, 1)))));
    }
}

TEST_CASE("a mesh tree query appends to the caller's list and finds nothing for an empty or distant box", "[ch13]") {
    Random random(1303);
    const TriangleMesh mesh = meshTreeTestGrid(random, 10);
    const MeshTree tree = buildMeshTree(mesh);
    std::vector<int> found = {-7, -8};
    Aabb box;
    box.min = Vec3(Real(2.5), -1, Real(2.5));
    box.max = Vec3(Real(3.5), 1, Real(3.5));
    queryMeshTree(tree, mesh, box, found);
    REQUIRE(found.size() > 2);
    CHECK(found[0] == -7);
    CHECK(found[1] == -8);

    std::vector<int> none;
    queryMeshTree(tree, mesh, Aabb(), none);  // the default box is empty: min > max
    Aabb far;
    far.min = Vec3(100, 100, 100);
    far.max = Vec3(101, 101, 101);
    queryMeshTree(tree, mesh, far, none);
    Aabb notANumber = box;
    notANumber.min.x() = std::nan("");
    queryMeshTree(tree, mesh, notANumber, none);
    CHECK(none.empty());
}

TEST_CASE("a mesh without triangles has an empty tree that finds nothing", "[ch13]") {
    const TriangleMesh mesh;
    const MeshTree tree = buildMeshTree(mesh);
    CHECK(tree.nodes.empty());
    std::vector<int> found;
    Aabb everything;
    everything.min = Vec3::Constant(-1000);
    everything.max = Vec3::Constant(1000);
    queryMeshTree(tree, mesh, everything, found);
    CHECK(found.empty());
}
