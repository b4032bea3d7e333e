// The views as drawing commands: which shapes, colours and fills each flag adds, and the pair
// diagnosis they draw from agreeing with the narrowphase (EPA's normal and depth, GJK's distance).
#include "09_debug/debug_views.h"

#include "03_epa/narrowphase.h"
#include "04_pgs/scenes.h"
#include "08_joints/scenes.h"
#include "09_debug/scenes.h"
#include "app/registry.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

bool same(const Color& a, const Color& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

int countOf(const RecordingDraw& draw, RecordingDraw::Kind kind, const Color& color) {
    int count = 0;
    for (const RecordingDraw::Command& command : draw.commands()) count += command.kind == kind && same(command.color, color);
    return count;
}

/// Two unit boxes, B resting 5 cm into A, B turned about y so the EPA face is a real face.
World overlappingBoxes() {
    World world;
    addStaticBox(world, "base", Vec3::Zero(), Vec3::Constant(Real(0.5)));
    BodyDef top;
    top.name = "top";
    top.shape = Shape::box(Vec3::Constant(Real(0.5)));
    top.transform = Transform{Vec3(Real(0.1), Real(0.95), 0), Quat(Eigen::AngleAxis<Real>(Real(0.3), Vec3::UnitY()))};
    addBody(world, top);
    return world;
}

}  // namespace

TEST_CASE("pair diagnosis: EPA's face, normal and depth agree with the narrowphase; apart, GJK's distance", "[ch09][views]") {
    World world = overlappingBoxes();
    const PairDiagnosis diagnosis = diagnosePair(world, 0, 1);
    REQUIRE(diagnosis.overlapping);
    REQUIRE(diagnosis.hasEpaFace);
    const ContactQuery query = collideShapes(world.bodies[0].shape, world.bodies[0].transform, world.bodies[1].shape,
                                             world.bodies[1].transform, CollideOptions{});
    CHECK(diagnosis.depth == Approx(0.05).margin(1e-5));
    CHECK(diagnosis.depth == Approx(query.depth).margin(1e-5));
    CHECK(diagnosis.normal.dot(query.normal) == Approx(1).margin(1e-5));
    // The face is the face of A - B nearest the origin: its plane holds the penetration vector,
    // depth times the normal.
    for (const SupportPoint& vertex : diagnosis.epaFace) CHECK(vertex.w.dot(diagnosis.normal) == Approx(0.05).margin(1e-4));
    CHECK(diagnosis.minkowskiPoints.size() == 64u);   // 8 corners minus 8 corners

    world.bodies[1].transform.position.y() = Real(1.3);   // 30 cm apart
    const PairDiagnosis apart = diagnosePair(world, 0, 1);
    CHECK_FALSE(apart.overlapping);
    CHECK_FALSE(apart.hasEpaFace);
    CHECK(apart.depth == Approx(-0.3).margin(1e-5));
    CHECK(apart.normal.y() == Approx(1).margin(1e-5));
    CHECK(diagnosePair(world, 1, 1).bodyA == -1);
    CHECK(diagnosePair(world, 0, 7).bodyA == -1);
}

TEST_CASE("each view flag draws its own commands, in its own colour", "[ch09][views]") {
    World world = overlappingBoxes();
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    world.settings.gravity = Vec3::Zero();
    pipeline.step(world);
    const HitTree tree = buildHitTree(world);
    REQUIRE_FALSE(tree.pairs.empty());

    DebugViews none;
    none.colliders = none.wireframeSelection = none.contactPoints = none.contactNormals = false;
    RecordingDraw empty;
    drawDebugViews(empty, world, none, -1, tree, HitSelection{});
    CHECK(empty.commands().empty());

    const auto drawn = [&](auto enable, int selected = -1) {
        DebugViews views = none;
        enable(views);
        RecordingDraw draw;
        drawDebugViews(draw, world, views, selected, tree, HitSelection{});
        return draw;
    };
    const RecordingDraw colliders = drawn([](DebugViews& v) { v.colliders = true; });
    CHECK(colliders.count(RecordingDraw::Kind::Box) == 2);
    const RecordingDraw points = drawn([](DebugViews& v) { v.contactPoints = true; });
    CHECK(countOf(points, RecordingDraw::Kind::Box, colors::kRed) == 2 * tree.pointCount());
    const RecordingDraw normals = drawn([](DebugViews& v) { v.contactNormals = true; });
    CHECK(countOf(normals, RecordingDraw::Kind::Arrow, colors::kYellow) == tree.pointCount());
    const RecordingDraw face = drawn([](DebugViews& v) { v.epaFace = true; });
    const PairDiagnosis diagnosis = diagnosePair(world, 0, 1);
    INFO("overlapping " << diagnosis.overlapping << ", face " << diagnosis.hasEpaFace << ", depth " << diagnosis.depth);
    // On each body, the face's vertices on that body: a triangle, an edge or a corner.
    CHECK(countOf(face, RecordingDraw::Kind::Line, colors::kBlue) + countOf(face, RecordingDraw::Kind::Point, colors::kBlue) >= 2);
    const RecordingDraw simplex = drawn([](DebugViews& v) { v.gjkSimplex = true; });
    CHECK(countOf(simplex, RecordingDraw::Kind::Point, colors::kMagenta) == 4);   // a tetrahedron around the origin
    const RecordingDraw minkowski = drawn([](DebugViews& v) { v.minkowski = true; });
    CHECK(countOf(minkowski, RecordingDraw::Kind::Hull, colors::kRed) == 1);      // red: overlapping
    CHECK(countOf(minkowski, RecordingDraw::Kind::Point, colors::kGrey) == 64);
    const RecordingDraw bounds = drawn([](DebugViews& v) { v.bounds = true; });
    CHECK(countOf(bounds, RecordingDraw::Kind::Box, colors::kCyan) == 2);
    // The selected body as a wireframe; the static base it rests on stays solid (the floor must
    // not vanish). A selected contact draws both bodies of its pair as wireframes.
    const auto fills = [](const RecordingDraw& draw) {
        std::pair<int, int> wireAndSolid{0, 0};
        for (const RecordingDraw::Command& command : draw.commands())
            if (command.kind == RecordingDraw::Kind::Box) (command.fill == Fill::Wire ? wireAndSolid.first : wireAndSolid.second) += 1;
        return wireAndSolid;
    };
    CHECK(fills(drawn([](DebugViews& v) { v.colliders = v.wireframeSelection = true; }, 1)) == std::pair<int, int>{1, 1});
    DebugViews both = none;
    both.colliders = both.wireframeSelection = true;
    RecordingDraw pairDraw;
    drawDebugViews(pairDraw, world, both, -1, tree, HitSelection{0, -1, -1});
    CHECK(fills(pairDraw) == std::pair<int, int>{2, 0});
}

TEST_CASE("the joint view draws every joint of the gallery", "[ch09][views]") {
    World world = chapterRegistry().findScene("joints-gallery")->build();
    DebugViews views;
    views.colliders = views.contactPoints = views.contactNormals = views.wireframeSelection = false;
    views.joints = true;
    RecordingDraw draw;
    drawDebugViews(draw, world, views, -1, HitTree{}, HitSelection{});
    CHECK(draw.count(RecordingDraw::Kind::Point) + draw.count(RecordingDraw::Kind::Line) >= int(world.joints.size()));
}

TEST_CASE("the chosen pair: the selected contact's, the selected body's first, the first touching, the first two", "[ch09][views]") {
    World world = buildDebugDrop();
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    const int box = world.findBody("box"), ball = world.findBody("ball");
    CHECK(chosenPair(world, HitTree{}, HitSelection{}, -1) == BodyPair{0, 1});
    for (int frame = 0; frame < 90; ++frame) pipeline.step(world);
    const HitTree tree = buildHitTree(world);
    REQUIRE(tree.pairs.size() == 2);
    CHECK(chosenPair(world, tree, HitSelection{}, ball) == BodyPair{0, ball});
    CHECK(chosenPair(world, tree, HitSelection{1, -1, -1}, box) == BodyPair{tree.pairs[1].bodyA, tree.pairs[1].bodyB});
    CHECK(chosenPair(world, tree, HitSelection{}, -1) == BodyPair{tree.pairs[0].bodyA, tree.pairs[0].bodyB});
}
