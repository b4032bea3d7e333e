// Inputs that break naive GJKs: coincident shapes, exact touching contact of faces, edges and
// vertices, a zero search direction, non-finite input. None may loop (hit the cap) or give NaN.

#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace stepwise;
using stepwise::test::tetrahedronHoldsOrigin;

namespace {

Transform pose(const Vec3& position, const Quat& rotation = Quat::Identity()) { return Transform{position, rotation}; }

Quat turn(Real degrees, const Vec3& axis) { return Quat(Eigen::AngleAxis<Real>(degrees * kPi / 180, axis.normalized())); }

void requireWellBehaved(const ConvexProxy& a, const ConvexProxy& b) {
    const GjkResult result = gjkIntersect(a, b);
    INFO("boolean exit " << toString(result.exit) << " after " << result.iterations);
    CHECK(result.exit != GjkExit::IterationCap);
    CHECK(result.iterations < 75);
    for (int i = 0; i < result.simplex.count; ++i) {
        CHECK(result.simplex.vertices[i].w.allFinite());
        CHECK(result.simplex.vertices[i].onA.allFinite());
    }
    const GjkDistanceResult distance = gjkDistance(a, b);
    INFO("distance exit " << toString(distance.exit) << " after " << distance.iterations);
    CHECK(distance.exit != GjkExit::IterationCap);
    CHECK(std::isfinite(distance.distance));
    CHECK(distance.pointA.allFinite());
    CHECK(distance.pointB.allFinite());
}

}  // namespace

TEST_CASE("identical coincident boxes intersect, with a tetrahedron around the origin", "[ch02][gjk][degenerate]") {
    const Shape box = Shape::box(Vec3(Real(0.5), Real(0.3), Real(0.2)));
    for (SupportMode mode : {SupportMode::Extents, SupportMode::Vertices}) {
        const ConvexProxy a{&box, pose(Vec3(1, 2, 3), turn(30, Vec3(1, 1, 0))), mode};
        const GjkResult result = gjkIntersect(a, a);
        CHECK(result.intersect);
        CHECK(result.exit == GjkExit::Intersect);
        REQUIRE(result.simplex.count == 4);
        // The tetrahedron holds the origin, inside or (here: the first two support points are
        // opposite corners of A - B, so the origin is on an edge) on its boundary.
        CHECK(tetrahedronHoldsOrigin(result.simplex, gjkTolerances(a, a).touching));
        requireWellBehaved(a, a);
        CHECK_FALSE(gjkDistance(a, a).separated);
    }
}

TEST_CASE("exact touching contact: faces, edges, vertices", "[ch02][gjk][degenerate]") {
    const Shape cube = Shape::box(Vec3::Constant(Real(0.5)));
    const Real diagonal = std::sqrt(Real(0.5));
    struct Case {
        const char* name;
        Transform poseB;
    };
    const Case cases[] = {
        {"face on face", pose(Vec3(1, 0, 0))},
        {"face on face, offset", pose(Vec3(Real(0.3), 1, Real(-0.2)))},
        {"edge on edge, parallel", pose(Vec3(1, 1, 0))},
        {"vertex on vertex", pose(Vec3(1, 1, 1))},
        {"edge across face", pose(Vec3(0, Real(0.5) + diagonal, 0), turn(45, Vec3::UnitX()))},
        {"vertex on face", pose(Vec3(0, Real(0.5) + std::sqrt(Real(0.75)), 0),
                                Quat::FromTwoVectors(Vec3(1, 1, 1).normalized(), Vec3(0, -1, 0)))},
    };
    for (const Case& touching : cases) {
        for (SupportMode mode : {SupportMode::Extents, SupportMode::Vertices}) {
            INFO(touching.name << (mode == SupportMode::Extents ? " (extents)" : " (vertices)"));
            const ConvexProxy a{&cube, pose(Vec3::Zero()), mode};
            const ConvexProxy b{&cube, touching.poseB, mode};
            requireWellBehaved(a, b);
            // Touching is within tolerance of both answers; the distance must say "about zero".
            CHECK(gjkDistance(a, b).distance <= gjkTolerances(a, b).touching);
        }
    }
    SECTION("crossed edges touching, and the same 10 km from the origin") {
        const Transform poseA = pose(Vec3::Zero(), turn(45, Vec3::UnitX()));
        const Transform poseB = pose(Vec3(0, 2 * diagonal, 0), turn(45, Vec3::UnitY()) * turn(45, Vec3::UnitX()));
        requireWellBehaved({&cube, poseA}, {&cube, poseB});
        const Vec3 far(Real(1e4), Real(-1e4), Real(1e4));
        requireWellBehaved({&cube, pose(poseA.position + far, poseA.rotation)}, {&cube, pose(poseB.position + far, poseB.rotation)});
    }
}

TEST_CASE("a zero search direction: concentric shapes and shapes of zero size", "[ch02][gjk][degenerate]") {
    const Shape box = Shape::box(Vec3(1, 2, 3));
    const Shape ball = Shape::sphere(Real(0.5));
    const Shape point = Shape::box(Vec3::Zero());
    const Shape dot = Shape::sphere(0);
    const Transform here = pose(Vec3(Real(0.5), -1, 2), turn(20, Vec3(0, 1, 1)));
    // cA - cB = 0: the first search direction is zero and GJK must pick one itself.
    CHECK(gjkIntersect({&box, here}, {&ball, here}).intersect);
    CHECK(gjkIntersect({&ball, here}, {&ball, here}).intersect);
    CHECK(gjkIntersect({&point, here}, {&point, here}).intersect);
    CHECK(gjkIntersect({&dot, here}, {&box, here}).intersect);
    requireWellBehaved({&point, here}, {&point, here});
    requireWellBehaved({&dot, here}, {&dot, here});
    // A point and a box: a zero-size shape is a valid convex set; its distance is point-to-box.
    const ConvexProxy corner{&point, pose(Vec3(3, 4, 0))};
    const ConvexProxy unitBox{&box, pose(Vec3::Zero())};
    CHECK_FALSE(gjkIntersect(corner, unitBox).intersect);
    CHECK(gjkDistance(corner, unitBox).distance == Approx(std::sqrt(Real(8))).epsilon(1e-5));
}

TEST_CASE("non-finite input gives a defined answer, never NaN", "[ch02][gjk][degenerate]") {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real inf = std::numeric_limits<Real>::infinity();
    const Shape box = Shape::box(Vec3::Ones());
    const Shape badBox = Shape::box(Vec3(1, nan, 1));
    const ConvexProxy good{&box, pose(Vec3::Zero())};
    const ConvexProxy inputs[] = {{&box, pose(Vec3(nan, 0, 0))}, {&box, pose(Vec3(inf, 0, 0))}, {&badBox, pose(Vec3::Zero())},
                                  {&box, Transform{Vec3::Zero(), Quat(nan, 0, 0, 0)}}, {nullptr, pose(Vec3::Zero())}};
    for (const ConvexProxy& bad : inputs) {
        const GjkResult result = gjkIntersect(good, bad);
        CHECK_FALSE(result.intersect);
        CHECK(result.exit == GjkExit::Degenerate);
        const GjkDistanceResult distance = gjkDistance(bad, good);
        CHECK(distance.exit == GjkExit::Degenerate);
        CHECK(distance.distance == 0);
        CHECK(distance.pointA.allFinite());
    }
}
