// The hit result tree of a known scene: a box resting flat on the ground and a ball beside it.
// The tree lists both pairs, the box's four corners and the ball's one point with their depths
// and normals; a ray through a corner selects that corner's node, and a node selected in the
// tree is the one drawn highlighted.
#include "09_debug/debug_views.h"
#include "09_debug/hit_tree.h"

#include "04_pgs/scenes.h"
#include "app/registry.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

/// Ground (top at y = 0), a 1 x 0.4 x 0.6 box resting on it and a ball of radius 0.3 beside it,
/// both placed one millimetre into the ground so the first step finds them touching.
World restingPair() {
    World world;
    world.name = "hit-tree";
    addGroundPlane(world);
    addCrate(world, "box", Vec3(0, Real(0.2) - Real(0.001), 0), Vec3(Real(0.5), Real(0.2), Real(0.3)), 1, Material{});
    addBall(world, "ball", Vec3(2, Real(0.3) - Real(0.001), 0), Real(0.3), 1, Material{});
    return world;
}

}  // namespace

TEST_CASE("the hit tree lists the expected pairs, manifolds and points", "[ch09][tree]") {
    World world = restingPair();
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    for (int frame = 0; frame < 30; ++frame) pipeline.step(world);   // settled: the impulses carry the weight
    const HitTree tree = buildHitTree(world);
    REQUIRE(tree.pairs.size() == 2);
    CHECK(tree.pointCount() == 5);
    const HitPair& boxPair = tree.pairs[0];
    CHECK(boxPair.nameA == "ground");
    CHECK(boxPair.nameB == "box");
    REQUIRE(boxPair.manifolds.size() == 1);
    CHECK(boxPair.manifolds[0].normal.y() == Approx(1).margin(1e-5));
    REQUIRE(boxPair.manifolds[0].points.size() == 4);
    Real impulse = 0;
    for (const HitPoint& point : boxPair.manifolds[0].points) {
        // The box's four bottom corners, a millimetre deep, each carrying part of its weight.
        CHECK(std::abs(point.position.x()) == Approx(0.5).margin(1e-4));
        CHECK(std::abs(point.position.z()) == Approx(0.3).margin(1e-4));
        CHECK(point.depth > 0);
        CHECK(point.depth < world.settings.slop * 2);
        CHECK(point.normalImpulse > 0);
        impulse += point.normalImpulse;
    }
    // Together they hold the box up. The impulses are those of the solve's last substep, and the
    // soft step (chapter 6) splits each frame into as many substeps as solver iterations: the
    // box's weight over one of them.
    const Real substep = world.settings.dt / Real(world.settings.substeps * world.settings.solverIterations);
    CHECK(impulse == Approx(9.81 * substep).epsilon(0.05));
    const HitPair& ballPair = tree.pairs[1];
    CHECK(ballPair.nameB == "ball");
    REQUIRE(ballPair.manifolds[0].points.size() == 1);
    CHECK(ballPair.manifolds[0].points[0].position.x() == Approx(2).margin(1e-4));
    CHECK(describePair(boxPair) == "ground / box (4 points)");
    CHECK(describeManifold(boxPair.manifolds[0]).rfind("normal (", 0) == 0);
    CHECK(describePoint(0, boxPair.manifolds[0].points[0]).rfind("#0 depth ", 0) == 0);
}

TEST_CASE("the hit tree: a ray through a contact selects its node, and the node is drawn highlighted", "[ch09][tree]") {
    World world = restingPair();
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    pipeline.step(world);
    const HitTree tree = buildHitTree(world);
    // Look down at the corner (+0.5, 0, +0.3) from above and slightly to the side.
    const Vec3 eye(Real(0.8), 3, Real(0.6));
    const Vec3 corner(Real(0.5), 0, Real(0.3));
    const HitSelection picked = pickHitPoint(tree, Ray{eye, (corner - eye).normalized(), 100}, Real(0.05));
    REQUIRE_FALSE(picked.empty());
    const HitPoint* point = selectedPoint(tree, picked);
    REQUIRE(point != nullptr);
    CHECK((point->position - corner).norm() < Real(0.01));
    CHECK(picked.pair == 0);
    // Far from every point: nothing.
    CHECK(pickHitPoint(tree, Ray{eye, Vec3(1, 0, 0), 100}, Real(0.05)).empty());
    CHECK(findPair(tree, 2, 0) == HitSelection{1, -1, -1});
    CHECK(findPair(tree, 1, 2).empty());

    // Drawn with the selection: white cubes and a white arrow at that point, on top of the red
    // cubes and yellow arrows of every contact.
    RecordingDraw draw;
    DebugViews views;
    drawDebugViews(draw, world, views, -1, tree, picked);
    int white = 0, red = 0, yellow = 0;
    for (const RecordingDraw::Command& command : draw.commands()) {
        const bool isWhite = command.color.r == 1 && command.color.g == 1 && command.color.b == 1;
        if (command.kind == RecordingDraw::Kind::Box && isWhite && (command.a - point->pointA).norm() < 1e-6) ++white;
        if (command.kind == RecordingDraw::Kind::Box && command.color.r == colors::kRed.r && command.color.g == colors::kRed.g) ++red;
        if (command.kind == RecordingDraw::Kind::Arrow && command.color.r == colors::kYellow.r && command.color.b == colors::kYellow.b) ++yellow;
    }
    CHECK(white == 1);
    CHECK(red == 2 * 5);      // both surfaces of each of the five points
    CHECK(yellow == 5);
}
