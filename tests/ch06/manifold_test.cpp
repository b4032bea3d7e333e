// Chapter 6's manifolds against an independent reference (tests/ch06/sat_reference.h: SAT over
// faces and edge pairs, then clipping, in double): box-box in face-face, edge-face and edge-edge
// contact, box-hull and hull-hull (round shapes and degenerate input: manifold_shapes_test.cpp;
// the reduction to four: reduction_test.cpp).
#include "ch06/manifold_fixture.h"
#include "06_manifolds/clipping.h"
#include "06_manifolds/manifold.h"
#include "06_manifolds/reduction.h"
#include "ch06/sat_reference.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>

using namespace stepwise;
using namespace stepwise::test;

namespace {

// [ch06-reference-tolerance]
/// How close the engine's points must come to the reference's. In double, 1e-5 m: the clipping is
/// exact up to round-off and the normal chapter 3 supplies only picks the faces. In float, 2e-5 m:
/// the points are built from world coordinates of order 1 m through a rotation, plane distances
/// and a crossing parameter, some ten float operations deep, each worth an ulp of 1 m (6e-8 m),
/// and a crossing divides by the difference of two distances, which amplifies that where an edge
/// meets a side plane at a shallow angle. The largest error over the suite's configurations is
/// under 1e-5 m in float (about 4e-6 m for most); twice that leaves room for other compilers.
constexpr double kPointTolerance = sizeof(Real) == sizeof(double) ? 1e-5 : 2e-5;
// [ch06-reference-tolerance]

/// Tolerance the reference uses to prefer faces, as the engine does.
constexpr double kFaceTolerance = 0.0005;

std::string describe(const Contact& contact) {
    std::ostringstream text;
    text << "normal " << contact.normal.transpose() << ", " << contact.pointCount << " points:";
    for (int i = 0; i < contact.pointCount; ++i)
        text << "\n  A " << contact.points[i].pointA.transpose() << "  B " << contact.points[i].pointB.transpose()
             << "  depth " << contact.points[i].depth << "  id " << contact.points[i].featureId;
    return text.str();
}

std::string describe(const reference::ReferenceManifold& manifold) {
    std::ostringstream text;
    text << "reference kind " << manifold.kind << ", normal " << manifold.normal.transpose() << ", "
         << manifold.points.size() << " points:";
    for (const auto& point : manifold.points)
        text << "\n  A " << point.pointA.transpose() << "  B " << point.pointB.transpose() << "  depth " << point.depth;
    return text.str();
}

/// The engine's manifold agrees with the reference: same normal, every engine point is a reference
/// point (A, B and depth), and all of them when the reference has at most four.
void requireMatchesReference(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                             double keepDistance = 0) {
    Contact contact;
    const bool found = collideManifold(a, ta, b, tb, static_cast<Real>(keepDistance), contact);
    const reference::ReferenceManifold expected = reference::satManifold(a, ta, b, tb, keepDistance, kFaceTolerance);
    INFO(describe(contact));
    INFO(describe(expected));
    REQUIRE(found);
    REQUIRE(!expected.points.empty());
    REQUIRE((contact.normal.cast<double>() - expected.normal).norm() < kPointTolerance);
    REQUIRE(contact.pointCount <= 4);
    REQUIRE(contact.pointCount == static_cast<int>(std::min<std::size_t>(4, expected.points.size())));
    for (int i = 0; i < contact.pointCount; ++i) {
        const ContactPoint& point = contact.points[i];
        double nearest = std::numeric_limits<double>::max();
        for (const auto& candidate : expected.points) {
            nearest = std::min(nearest, std::max({(point.pointA.cast<double>() - candidate.pointA).norm(),
                                                  (point.pointB.cast<double>() - candidate.pointB).norm(),
                                                  std::abs(static_cast<double>(point.depth) - candidate.depth)}));
        }
        INFO("point " << i);
        REQUIRE(nearest < kPointTolerance);
    }
    // The deepest reference point is always among the engine's.
    double deepestExpected = -1e300, deepestEngine = -1e300;
    for (const auto& candidate : expected.points) deepestExpected = std::max(deepestExpected, candidate.depth);
    for (int i = 0; i < contact.pointCount; ++i) deepestEngine = std::max(deepestEngine, static_cast<double>(contact.points[i].depth));
    REQUIRE(std::abs(deepestEngine - deepestExpected) < kPointTolerance);
}

}  // namespace

TEST_CASE("box-box face-face: the clipped patch matches SAT + clipping", "[ch06][manifold]") {
    SECTION("a small box fully on a slab: its four bottom corners") {
        requireMatchesReference(kSlab, pose(Vec3::Zero()), kUnitBox,
                                pose(Vec3(Real(0.1), Real(0.74), Real(-0.05)), axisAngle(Vec3::UnitY(), 20)));
    }
    SECTION("overhanging a corner: crossings of side planes, reduced to four") {
        requireMatchesReference(kSlab, pose(Vec3::Zero()), kUnitBox,
                                pose(Vec3(Real(0.85), Real(0.74), Real(0.6)), axisAngle(Vec3::UnitY(), 30)));
    }
    SECTION("B below A: B's face is the reference") {
        requireMatchesReference(kUnitBox, pose(Vec3(Real(0.2), Real(0.74), 0), axisAngle(Vec3::UnitY(), 10)), kSlab,
                                pose(Vec3::Zero()));
    }
    SECTION("slightly tilted: only the low corners, the others within the keep distance as speculative points") {
        requireMatchesReference(kSlab, pose(Vec3::Zero()), kUnitBox,
                                pose(Vec3(0, Real(0.745), 0), axisAngle(Vec3(1, 0, 1), 0.5)), 0.01);
    }
}

TEST_CASE("boxes that just touch: four points, whatever normal EPA settles on at zero depth", "[ch06][manifold]") {
    // A stack's two boxes as a run left them: touching face to face within round-off. EPA's
    // depth is zero along many normals here (one run found (0, 0.45, -0.89)); the faces must come
    // from SAT, not from that normal.
    Transform ta{Vec3(Real(7.9576188e-05), Real(0.499795228), Real(3.9876395e-05)),
                 Quat(1, Real(-4.75539964e-05), Real(7.98101246e-06), Real(-0.000301369611)).normalized()};
    Transform tb{Vec3(Real(0.000667190703), Real(1.49980295), Real(-5.87820141e-05)),
                 Quat(1, Real(-4.93622829e-05), Real(-1.05312483e-06), Real(-0.000295281585)).normalized()};
    // The faces' edges lie within 3e-4 rad of each other: where they cross the side planes is
    // ill-conditioned (millimetres along the edges), so this pose is checked by what must hold
    // whichever crossings are taken: four points spanning the face, at depth zero, along +y.
    Contact touching;
    REQUIRE(collideManifold(kUnitBox, ta, kUnitBox, tb, Real(0.005), touching));
    REQUIRE(touching.pointCount == 4);
    CHECK((touching.normal - Vec3::UnitY()).norm() < 1e-3);
    Real spanX = 0, spanZ = 0;
    for (int i = 0; i < 4; ++i) {
        CHECK(std::abs(touching.points[i].depth) < 1e-4);
        for (int k = 0; k < 4; ++k) {
            spanX = std::max(spanX, std::abs(touching.points[i].pointA.x() - touching.points[k].pointA.x()));
            spanZ = std::max(spanZ, std::abs(touching.points[i].pointA.z() - touching.points[k].pointA.z()));
        }
    }
    CHECK(spanX > Real(0.99));
    CHECK(spanZ > Real(0.99));
    requireMatchesReference(kUnitBox, pose(Vec3(0, Real(0.5), 0)), kUnitBox, pose(Vec3(0, Real(1.5), 0)), 0.005);
    Contact contact;
    REQUIRE(collideManifold(kUnitBox, pose(Vec3(0, Real(0.5), 0)), kUnitBox, pose(Vec3(0, Real(1.5), 0)), Real(0.005), contact));
    CHECK(contact.pointCount == 4);
    CHECK((contact.normal - Vec3::UnitY()).norm() < 1e-5);
}

TEST_CASE("box-box edge-face: the two ends of the resting edge", "[ch06][manifold]") {
    const Quat edgeDown = axisAngle(Vec3::UnitZ(), 45) * axisAngle(Vec3::UnitY(), 0);
    const Real lift = Real(0.25) + Real(0.5) * std::sqrt(Real(2)) - Real(0.01);
    requireMatchesReference(kSlab, pose(Vec3::Zero()), kUnitBox, pose(Vec3(Real(0.1), lift, Real(0.05)), edgeDown));
    // Over the slab's rim: the edge is cut by a side plane.
    requireMatchesReference(kSlab, pose(Vec3::Zero()), kUnitBox,
                            pose(Vec3(0, lift, Real(0.55)), axisAngle(Vec3::UnitY(), 15) * axisAngle(Vec3::UnitX(), 45)));
    Contact contact;
    REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), kUnitBox, pose(Vec3(Real(0.1), lift, Real(0.05)), edgeDown), 0, contact));
    REQUIRE(contact.pointCount == 2);
}

TEST_CASE("box-box edge-edge: one point, the closest points of the crossing edges", "[ch06][manifold]") {
    // A's top is an edge along z, B's bottom an edge along x: they cross at right angles.
    const Transform ta = pose(Vec3::Zero(), axisAngle(Vec3::UnitZ(), 45));
    const Real reach = Real(0.5) * std::sqrt(Real(2));
    const Transform tb = pose(Vec3(Real(0.05), 2 * reach - Real(0.01), Real(-0.03)), axisAngle(Vec3::UnitX(), 45));
    requireMatchesReference(kUnitBox, ta, kUnitBox, tb);
    Contact contact;
    REQUIRE(collideManifold(kUnitBox, ta, kUnitBox, tb, 0, contact));
    REQUIRE(contact.pointCount == 1);
    CHECK(contact.points[0].depth == Approx(0.01).margin(1e-4));
    // Named by the two edges, not by whatever chapter 3's EPA ended on.
    // A box corner's index is its sign bits; the edge's index is lower * 128 + higher.
    const auto extremeEdge = [](const Transform& transform, Real sign) {
        std::vector<std::pair<Real, int>> heights;
        for (int index = 0; index < 8; ++index) {
            const Vec3 corner((index & 1) ? Real(0.5) : Real(-0.5), (index & 2) ? Real(0.5) : Real(-0.5),
                              (index & 4) ? Real(0.5) : Real(-0.5));
            heights.emplace_back(sign * transform.apply(corner).y(), index);
        }
        std::sort(heights.begin(), heights.end());
        const int i = std::min(heights[6].second, heights[7].second), j = std::max(heights[6].second, heights[7].second);
        return makeFeature(FeatureKind::Edge, static_cast<std::uint32_t>(i * 128 + j));
    };
    CHECK(contact.points[0].featureId == makeFeatureId(extremeEdge(ta, 1), extremeEdge(tb, -1)));
    // Crossing at an angle, and turned about the vertical.
    requireMatchesReference(kUnitBox, ta, kUnitBox,
                            pose(Vec3(0, 2 * reach - Real(0.02), 0), axisAngle(Vec3::UnitY(), 30) * axisAngle(Vec3::UnitX(), 45)));
}

struct RandomComparison {
    int compared = 0;
    int kinds[4] = {0, 0, 0, 0};
};

/// Random poses of B around A, slid together until the reference finds them touching, then 0 to
/// 2 cm deeper, and compared wherever SAT's choice is clear (near-ties, where either answer is
/// right, are skipped).
RandomComparison compareRandomPoses(const Shape& shapeA, const Shape& shapeB, int trials, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    RandomComparison result;
    for (int trial = 0; trial < trials; ++trial) {
        const Vec3 axisA(static_cast<Real>(unit(random)), static_cast<Real>(unit(random)), static_cast<Real>(unit(random)));
        const Vec3 axisB(static_cast<Real>(unit(random)), static_cast<Real>(unit(random)), static_cast<Real>(unit(random)));
        Vec3 direction(static_cast<Real>(unit(random)), static_cast<Real>(unit(random)), static_cast<Real>(unit(random)));
        const double angleA = 180 * unit(random), angleB = 180 * unit(random), extra = 0.01 * (unit(random) + 1);
        if (axisA.norm() < 0.1 || axisB.norm() < 0.1 || direction.norm() < 0.1) continue;
        direction.normalize();
        const Transform ta = pose(Vec3::Zero(), axisAngle(axisA, angleA));
        Transform tb = pose(direction * Real(3), axisAngle(axisB, angleB));
        // The separation along the ray is the largest of linear functions of the distance, so it
        // is convex and crosses zero once: bisect for the touching distance.
        const auto separationAt = [&](double distance) {
            tb.position = direction * static_cast<Real>(distance);
            const auto probe = reference::satManifold(shapeA, ta, shapeB, tb, 0, kFaceTolerance);
            return std::max(probe.bestFace, probe.bestEdge);
        };
        double inside = 0, outside = 3;
        for (int step = 0; step < 30; ++step) {
            const double middle = 0.5 * (inside + outside);
            (separationAt(middle) < 0 ? inside : outside) = middle;
        }
        tb.position = direction * static_cast<Real>(outside - extra);
        const auto expected = reference::satManifold(shapeA, ta, shapeB, tb, 0, kFaceTolerance);
        const bool clearEdge = expected.bestEdge > expected.bestFace + 5 * kFaceTolerance;
        const bool clearFace = expected.bestEdge < expected.bestFace + 0.2 * kFaceTolerance;
        if (expected.points.empty() || !(clearEdge || clearFace)) continue;
        INFO("trial " << trial);
        requireMatchesReference(shapeA, ta, shapeB, tb);
        ++result.compared;
        ++result.kinds[expected.kind];
    }
    return result;
}

TEST_CASE("random box-box poses agree with the reference wherever SAT's choice is clear", "[ch06][manifold]") {
    const RandomComparison result = compareRandomPoses(kUnitBox, kSlab, 400, 606);
    INFO("face A " << result.kinds[1] << ", face B " << result.kinds[2] << ", edge " << result.kinds[3]);
    CHECK(result.compared > 100);
    CHECK(result.kinds[3] > 10);
    CHECK(result.kinds[1] + result.kinds[2] > 10);
}

TEST_CASE("box-hull and hull-hull manifolds agree with the reference", "[ch06][manifold]") {
    const Shape prism = prismHull();
    const Shape octahedron = octahedronHull(Real(0.7));
    SECTION("a box on the prism's slanted top") {
        // The top plane is y = 0.4 + 0.1 x: tilt the box to match, then sink it 5 mm.
        const Real slope = std::atan(Real(0.1));
        const Quat tilt = Quat(Eigen::AngleAxis<Real>(slope, Vec3::UnitZ()));
        const Vec3 up = tilt * Vec3::UnitY();
        requireMatchesReference(prism, pose(Vec3::Zero()), Shape::box(Vec3(Real(0.2), Real(0.2), Real(0.2))),
                                pose(Vec3(0, Real(0.4), 0) + up * Real(0.195), tilt * axisAngle(Vec3::UnitY(), 25)));
    }
    SECTION("the prism standing on a box (the box is A)") {
        requireMatchesReference(kSlab, pose(Vec3::Zero()), prism,
                                pose(Vec3(Real(0.7), Real(0.25) + Real(0.4) - Real(0.01), 0), axisAngle(Vec3::UnitY(), 10)));
    }
    SECTION("random poses, box-hull and hull-hull") {
        const RandomComparison boxHull = compareRandomPoses(kUnitBox, prism, 150, 61);
        const RandomComparison hullHull = compareRandomPoses(octahedron, prism, 150, 62);
        INFO("box-hull: face " << boxHull.kinds[1] + boxHull.kinds[2] << ", edge " << boxHull.kinds[3]);
        INFO("hull-hull: face " << hullHull.kinds[1] + hullHull.kinds[2] << ", edge " << hullHull.kinds[3]);
        CHECK(boxHull.compared > 40);
        CHECK(hullHull.compared > 40);
        CHECK(boxHull.kinds[3] > 5);
        CHECK(hullHull.kinds[3] > 5);
    }
    SECTION("octahedron face on prism side") {
        // An octahedron face (normal (1,1,1)/sqrt 3) turned to face -x, against the prism's side.
        const Quat turn = Quat::FromTwoVectors(Vec3(1, 1, 1).normalized(), Vec3(-1, 0, 0));
        const Real faceDistance = Real(0.7) / std::sqrt(Real(3));
        const Real prismSide = Real(0.6) * std::cos(Real(3.14159265358979323846 / 6.0));
        const Quat prismTurn = axisAngle(Vec3::UnitY(), 30);  // a flat side facing +x
        requireMatchesReference(prism, pose(Vec3::Zero(), prismTurn), octahedron,
                                pose(Vec3(prismSide + faceDistance - Real(0.01), Real(0.05), 0), turn));
    }
}

TEST_CASE("a box resting squarely on another: four corner points whatever round-off tilts them", "[ch06][manifold]") {
    // Two unit boxes face to face, turned by angles of round-off size (a stack after a step): the
    // manifold's points must be the four corners of the face (its edges crossing the side planes
    // anywhere must not replace one).
    std::mt19937 random(11);
    std::uniform_real_distribution<double> tiny(-1e-8, 1e-8);
    for (int trial = 0; trial < 200; ++trial) {
        const auto wobble = [&] {
            return Quat(1, static_cast<Real>(tiny(random)), static_cast<Real>(tiny(random)), static_cast<Real>(tiny(random))).normalized();
        };
        const Transform lower{Vec3(static_cast<Real>(tiny(random)), Real(0.5), 0), wobble()};
        const Transform upper{Vec3(static_cast<Real>(tiny(random)), Real(1.5) - Real(1e-4), static_cast<Real>(tiny(random))), wobble()};
        Contact contact;
        REQUIRE(collideManifold(kUnitBox, lower, kUnitBox, upper, Real(0.005), contact));
        INFO("trial " << trial << ": " << describe(contact));
        REQUIRE(contact.pointCount == 4);
        for (int i = 0; i < 4; ++i) {
            const Vec3 local = contact.points[i].pointA - lower.position;
            CHECK(std::abs(std::abs(local.x()) - Real(0.5)) < 1e-5);
            CHECK(std::abs(std::abs(local.z()) - Real(0.5)) < 1e-5);
            for (int k = i + 1; k < 4; ++k) CHECK((contact.points[i].pointA - contact.points[k].pointA).norm() > 0.9);
        }
    }
}
