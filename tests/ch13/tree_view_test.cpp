// The demo's mesh-tree view: each level's boxes cover every triangle once (the nodes at that
// depth and the leaves above it), each box lies inside a box of the level above, and the view
// draws them as twelve lines each in the mesh body's frame; the demo finds it by name.
#include "13_worlds/scenes.h"
#include "13_worlds/tree_view.h"

#include "app/registry.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace stepwise;

namespace {

bool treeViewInside(const Aabb& inner, const Aabb& outer) {
    return (inner.min.array() >= outer.min.array()).all() && (inner.max.array() <= outer.max.array()).all();
}

/// How many triangles the leaves under `node` hold.
int treeViewTrianglesUnder(const MeshTree& tree, int node) {
    const MeshTreeNode& at = tree.nodes[node];
    if (at.secondChild < 0) return at.triangleCount;
    return treeViewTrianglesUnder(tree, node + 1) + treeViewTrianglesUnder(tree, at.secondChild);
}

}  // namespace

TEST_CASE("each level of the mesh-tree view covers every triangle once, inside the level above", "[ch13]") {
    const Shape hills = hillsMesh(20, 1, Real(1.5));
    const MeshTree tree = buildMeshTree(*hills.mesh);
    const int triangles = static_cast<int>(hills.mesh->triangles.size());
    REQUIRE(triangles == 800);

    const std::vector<Aabb> root = meshTreeLevelBoxes(tree, 0);
    REQUIRE(root.size() == 1);
    CHECK(root[0].min == tree.nodes[0].box.min);
    CHECK(root[0].max == tree.nodes[0].box.max);

    std::vector<Aabb> above = root;
    for (int level = 1; level < kTreeViewLevels; ++level) {
        const std::vector<Aabb> boxes = meshTreeLevelBoxes(tree, level);
        INFO("level " << level);
        REQUIRE(boxes.size() >= above.size());
        // Every triangle's box lies in some box of the level (the tree's boxes hold what is below).
        int covered = 0;
        for (int t = 0; t < triangles; ++t) {
            const Aabb triangle = meshTriangleBox(*hills.mesh, t);
            for (const Aabb& box : boxes)
                if (treeViewInside(triangle, box)) {
                    ++covered;
                    break;
                }
        }
        CHECK(covered == triangles);
        for (const Aabb& box : boxes) {
            bool inAbove = false;
            for (const Aabb& outer : above) inAbove = inAbove || treeViewInside(box, outer);
            CHECK(inAbove);
        }
        above = boxes;
    }
    // Deep enough, the level is the leaves: 800 triangles in leaves of at most four.
    const std::vector<Aabb> deepest = meshTreeLevelBoxes(tree, kTreeViewLevels - 1);
    int leaves = 0;
    for (const MeshTreeNode& node : tree.nodes) leaves += node.secondChild < 0 ? 1 : 0;
    CHECK(static_cast<int>(deepest.size()) == leaves);
    CHECK(leaves >= triangles / kMeshTreeLeafTriangles);
    CHECK(treeViewTrianglesUnder(tree, 0) == triangles);
    CHECK(meshTreeLevelBoxes(tree, -1).empty());
    CHECK(meshTreeLevelBoxes(MeshTree{}, 0).empty());
}

TEST_CASE("the mesh-tree view draws each box as twelve lines in the mesh body's frame", "[ch13]") {
    World world = emptyWorld("tree-view");
    BodyDef ground;
    ground.name = "hills";
    ground.type = BodyType::Static;
    ground.shape = hillsMesh(8, 1, Real(0.5));
    ground.transform.position = Vec3(3, -1, 2);
    ground.transform.rotation = Quat(Eigen::AngleAxis<Real>(Real(0.5), Vec3::UnitY()));
    addBody(world, ground);
    BodyDef box;
    box.name = "box";
    box.shape = Shape::box(Vec3::Constant(Real(0.5)));
    box.transform.position = Vec3(3, 2, 2);
    addBody(world, box);

    WorldShapesCache cache;
    const MeshTree tree = buildMeshTree(*world.bodies[0].shape.mesh);
    for (int level : {0, 2, 5}) {
        RecordingDraw recorded;
        drawMeshTreeLevel(recorded, world, level, cache);
        const std::vector<Aabb> boxes = meshTreeLevelBoxes(tree, level);
        REQUIRE(recorded.count(RecordingDraw::Kind::Line) == 12 * static_cast<int>(boxes.size()));
        // Every line end is a corner of one of the level's boxes, placed by the body's pose.
        for (const RecordingDraw::Command& line : recorded.commands()) {
            const Vec3 local = world.bodies[0].transform.applyInverse(line.a);
            bool corner = false;
            for (const Aabb& levelBox : boxes)
                corner = corner || (((local - levelBox.min).cwiseAbs().array() < Real(1e-4)) ||
                                    ((local - levelBox.max).cwiseAbs().array() < Real(1e-4)))
                                       .all();
            CHECK(corner);
        }
    }
    // The dynamic box draws nothing: only meshes have trees.
    RecordingDraw none;
    World boxes = emptyWorld("no-mesh");
    addBody(boxes, box);
    drawMeshTreeLevel(none, boxes, 3, cache);
    CHECK(none.commands().empty());
}

TEST_CASE("chapter 13 adds the mesh-tree view to the demo, drawing over its mesh scene", "[ch13]") {
    const Registry& registry = chapterRegistry();
    const DebugOverlay* view = nullptr;
    for (const DebugOverlay& overlay : registry.debugOverlays())
        if (overlay.name == "mesh-tree") view = &overlay;
    REQUIRE(view != nullptr);
    CHECK(view->chapter == 13);
    CHECK(view->levels == kTreeViewLevels);
    const SceneEntry* scene = registry.findScene("worlds-mesh-terrain");
    REQUIRE(scene != nullptr);
    const World world = scene->build();
    const OverlayDraw draw = view->make();
    RecordingDraw recorded;
    draw(recorded, world, 3);
    CHECK(recorded.count(RecordingDraw::Kind::Line) == 12 * 8);  // 3,200 triangles: a full tree to level 3
}
