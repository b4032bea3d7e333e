// Exercise check for chapter 13 (`ctest -L ch13-exercise`): rewrite queryMeshTree in
// chapters/13_worlds/mesh_tree.cpp from the page (a stack of nodes; a node whose box misses the
// query box is skipped with everything under it; a leaf's triangles are tested box by box) and
// run this. On a terrain of 20,000 triangles, a random soup and a single triangle, every query box
// must find exactly the triangles whose boxes overlap it, each once.
#include "13_worlds/mesh_tree.h"
#include "13_worlds/scenes.h"
#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

namespace {

std::vector<int> bruteForce(const TriangleMesh& mesh, const Aabb& box) {
    std::vector<int> found;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
        if (meshTriangleBox(mesh, t).overlaps(box)) found.push_back(t);
    return found;
}

Shape soup(int count, Random& random) {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    for (int t = 0; t < count; ++t) {
        const Vec3 at(random.uniformReal(-20, 20), random.uniformReal(-5, 5), random.uniformReal(-20, 20));
        for (int k = 0; k < 3; ++k)
            vertices.push_back(at + Vec3(random.uniformReal(-1, 1), random.uniformReal(-1, 1), random.uniformReal(-1, 1)));
        triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    return Shape::triangleMesh(std::move(vertices), std::move(triangles));
}

}  // namespace

TEST_CASE("exercise: the tree's query finds exactly the triangles whose boxes overlap the box", "[ch13-exercise]") {
    Random random(7);
    const std::vector<Shape> meshes = {tiledFloor(100, Real(0.5)), soup(3000, random),
                                       Shape::triangleMesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)}, {{0, 2, 1}})};
    for (const Shape& mesh : meshes) {
        const MeshTree tree = buildMeshTree(*mesh.mesh);
        for (int query = 0; query < 300; ++query) {
            const Vec3 centre(random.uniformReal(-25, 55), random.uniformReal(-6, 6), random.uniformReal(-25, 55));
            const Vec3 half(random.uniformReal(0, 3), random.uniformReal(0, 3), random.uniformReal(0, 3));
            Aabb box;
            box.min = centre - half;
            box.max = centre + half;
            std::vector<int> found;
            queryMeshTree(tree, *mesh.mesh, box, found);
            std::sort(found.begin(), found.end());
            INFO("mesh of " << mesh.mesh->triangles.size() << " triangles, query " << query);
            REQUIRE(found == bruteForce(*mesh.mesh, box));
        }
    }
}
