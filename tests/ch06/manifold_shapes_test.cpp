// Chapter 6's manifolds where the answer needs no reference: round shapes (one point for spheres,
// two for capsules lying along each other or on a face), degenerate input, and boxes' faces and
// edges described like hulls'.
#include "ch06/manifold_fixture.h"
#include "06_manifolds/manifold.h"
#include "06_manifolds/polytope_faces.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace stepwise;
using namespace stepwise::test;

TEST_CASE("round shapes: one point for spheres, two for capsules lying along each other or on a face", "[ch06][manifold]") {
    const Shape capsule = Shape::capsule(Real(0.2), Real(0.5));
    const Quat lying = axisAngle(Vec3::UnitZ(), 90);  // axis along x
    Contact contact;
    SECTION("sphere on a box: one point") {
        REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), Shape::sphere(Real(0.3)), pose(Vec3(0, Real(0.54), 0)), 0, contact));
        CHECK(contact.pointCount == 1);
        CHECK(contact.points[0].depth == Approx(0.01).margin(1e-5));
    }
    SECTION("capsule lying on a box: the two ends of its segment, 1 cm deep") {
        REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), capsule, pose(Vec3(Real(0.1), Real(0.44), 0), lying), 0, contact));
        REQUIRE(contact.pointCount == 2);
        CHECK((contact.normal - Vec3::UnitY()).norm() < 1e-5);
        for (int i = 0; i < 2; ++i) {
            CHECK(contact.points[i].depth == Approx(0.01).margin(2e-5));
            CHECK(std::abs(std::abs(contact.points[i].pointA.x() - Real(0.1)) - Real(0.5)) < 1e-4);
        }
        CHECK(contact.points[0].featureId != contact.points[1].featureId);
    }
    SECTION("capsule over the box's rim: its segment clipped at the side plane") {
        REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), capsule, pose(Vec3(Real(0.9), Real(0.44), 0), lying), 0, contact));
        REQUIRE(contact.pointCount == 2);
        const Real right = std::max(contact.points[0].pointA.x(), contact.points[1].pointA.x());
        CHECK(right == Approx(1).margin(1e-4));
    }
    SECTION("parallel capsules: two points at the ends of the overlap") {
        REQUIRE(collideManifold(capsule, pose(Vec3::Zero(), lying), capsule, pose(Vec3(Real(0.3), Real(0.39), 0), lying), 0, contact));
        REQUIRE(contact.pointCount == 2);
        const Real low = std::min(contact.points[0].pointA.x(), contact.points[1].pointA.x());
        const Real high = std::max(contact.points[0].pointA.x(), contact.points[1].pointA.x());
        CHECK(low == Approx(-0.2).margin(1e-4));
        CHECK(high == Approx(0.5).margin(1e-4));
        CHECK(contact.points[0].depth == Approx(0.01).margin(1e-4));
    }
    SECTION("crossed capsules: one point") {
        REQUIRE(collideManifold(capsule, pose(Vec3::Zero(), lying), capsule,
                                pose(Vec3(0, Real(0.39), 0), axisAngle(Vec3::UnitX(), 90)), 0, contact));
        CHECK(contact.pointCount == 1);
    }
    SECTION("capsule lying on a hull's face: two points, the face's normal") {
        const Shape prism = prismHull();
        // The prism's bottom face is y = -0.4: a capsule under it, pressing 1 cm up into it.
        REQUIRE(collideManifold(capsule, pose(Vec3(0, Real(-0.59), 0), axisAngle(Vec3::UnitZ(), 90)), prism, pose(Vec3::Zero()), 0,
                                contact));
        REQUIRE(contact.pointCount == 2);
        CHECK((contact.normal - Vec3::UnitY()).norm() < 1e-4);
        for (int i = 0; i < 2; ++i) CHECK(contact.points[i].depth == Approx(0.01).margin(1e-4));
    }
    SECTION("one point per pair when multiPoint is off") {
        ManifoldOptions single;
        single.multiPoint = false;
        REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), kUnitBox, pose(Vec3(0, Real(0.74), 0)), 0, contact, single));
        CHECK(contact.pointCount == 1);
    }
}

TEST_CASE("degenerate input gives no points and no crash", "[ch06][manifold]") {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    const Real infinity = std::numeric_limits<Real>::infinity();
    Contact contact;
    contact.pointCount = 3;
    CHECK_FALSE(collideManifold(Shape::box(Vec3(0, Real(0.5), Real(0.5))), pose(Vec3::Zero()), kUnitBox,
                                pose(Vec3(0, Real(0.9), 0)), Real(0.1), contact));
    CHECK(contact.pointCount == 0);
    CHECK_FALSE(collideManifold(kUnitBox, pose(Vec3(nan, 0, 0)), kUnitBox, pose(Vec3(0, Real(0.9), 0)), Real(0.1), contact));
    CHECK(contact.pointCount == 0);
    CHECK_FALSE(collideManifold(kUnitBox, pose(Vec3::Zero(), Quat(nan, 0, 0, 0)), kUnitBox, pose(Vec3(0, Real(0.9), 0)), 0, contact));
    CHECK_FALSE(collideManifold(kUnitBox, pose(Vec3::Zero()), kUnitBox, pose(Vec3(0, infinity, 0)), Real(0.1), contact));
    CHECK_FALSE(collideManifold(kUnitBox, pose(Vec3::Zero(), Quat(0, 0, 0, 0)), kUnitBox, pose(Vec3(0, Real(0.9), 0)), 0, contact));
    CHECK_FALSE(collideManifold(kUnitBox, pose(Vec3::Zero()), Shape::sphere(0), pose(Vec3(0, Real(0.5), 0)), 0, contact));
    CHECK_FALSE(collideManifold(kUnitBox, pose(Vec3::Zero()), kUnitBox, pose(Vec3::Zero()), nan, contact));
    // Coincident boxes: deep, but a defined answer with at most four finite points.
    if (collideManifold(kUnitBox, pose(Vec3::Zero()), kUnitBox, pose(Vec3::Zero()), 0, contact)) {
        REQUIRE(contact.pointCount <= 4);
        for (int i = 0; i < contact.pointCount; ++i) CHECK(isFinite(contact.points[i].pointA));
    }
}

TEST_CASE("polytope faces: boxes are described like hulls", "[ch06][manifold]") {
    const Shape box = Shape::box(Vec3(1, 2, 3));
    for (int face = 0; face < 6; ++face) {
        const FacePolygon polygon = polytopeFace(box, face);
        REQUIRE(polygon.corners.size() == 4);
        // Counter-clockwise seen from outside: Newell's normal agrees with the outward normal.
        Vec3 newell = Vec3::Zero();
        for (std::size_t k = 0; k < 4; ++k) newell += polygon.corners[k].cross(polygon.corners[(k + 1) % 4]);
        CHECK(newell.normalized().dot(polygon.normal) == Approx(1));
        for (const Vec3& corner : polygon.corners) CHECK(polygon.normal.dot(corner) == Approx(polygon.offset));
    }
    CHECK(polytopeEdges(box).size() == 12);
    CHECK(polytopeEdges(octahedronHull(1)).size() == 12);
    CHECK(polytopeEdges(prismHull()).size() == 18);
}
