// Mass properties against closed forms, and the convex hull builder.
#include <catch2/catch.hpp>

#include "world/shape.h"

using namespace stepwise;

namespace {

std::vector<Vec3> boxCorners(const Vec3& halfExtents, const Vec3& offset = Vec3::Zero()) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.push_back(offset + Vec3(i & 1 ? halfExtents.x() : -halfExtents.x(), i & 2 ? halfExtents.y() : -halfExtents.y(),
                                        i & 4 ? halfExtents.z() : -halfExtents.z()));
    return corners;
}

void requireClose(const Mat3& actual, const Mat3& expected, double relative) {
    const double scale = expected.norm();
    INFO("actual\n" << actual << "\nexpected\n" << expected);
    REQUIRE((actual - expected).norm() <= relative * scale);
}

}  // namespace

TEST_CASE("box mass properties match the closed form", "[common][mass]") {
    const Shape box = Shape::box(Vec3(1, 0.5f, 0.25f));
    const MassProperties props = computeMassProperties(box, 1000);
    const Real mass = 1000 * 8 * Real(0.125);
    REQUIRE(props.mass == Approx(mass));
    Mat3 expected = Mat3::Zero();
    expected.diagonal() << mass / 12 * (1 + Real(0.25)), mass / 12 * (4 + Real(0.25)), mass / 12 * (4 + 1);
    requireClose(props.inertia, expected, 1e-5);
}

TEST_CASE("sphere and capsule mass properties match the closed form", "[common][mass]") {
    const MassProperties sphere = computeMassProperties(Shape::sphere(0.5f), 2000);
    const Real sphereMass = 2000 * Real(4.0 / 3.0) * kPi * Real(0.125);
    REQUIRE(sphere.mass == Approx(sphereMass));
    REQUIRE(sphere.inertia(0, 0) == Approx(0.4 * sphereMass * 0.25));

    // A capsule with no cylinder is a sphere.
    const MassProperties ball = computeMassProperties(Shape::capsule(0.5f, 0), 2000);
    REQUIRE(ball.mass == Approx(sphereMass));
    requireClose(ball.inertia, sphere.inertia, 1e-5);

    // A long capsule approaches a rod: transverse inertia ~ m L^2 / 12.
    const MassProperties rod = computeMassProperties(Shape::capsule(0.001f, 50), 1000);
    REQUIRE(rod.inertia(0, 0) == Approx(rod.mass * 100 * 100 / 12).epsilon(1e-3));
    REQUIRE(rod.inertia(1, 1) < rod.inertia(0, 0) * 1e-6);
}

TEST_CASE("a hull of a box's corners has the box's mass properties", "[common][mass][hull]") {
    const Vec3 halfExtents(0.3f, 0.7f, 1.1f);
    const Vec3 offset(2, -1, 0.5f);
    const Shape hull = Shape::convex(boxCorners(halfExtents, offset));
    REQUIRE(hull.hull->vertices.size() == 8);
    REQUIRE(hull.hull->faces.size() == 6);
    const MassProperties fromHull = computeMassProperties(hull, 500);
    const MassProperties fromBox = computeMassProperties(Shape::box(halfExtents), 500);
    REQUIRE(fromHull.mass == Approx(fromBox.mass).epsilon(1e-5));
    REQUIRE((fromHull.localCenter - offset).norm() < 1e-5);
    requireClose(fromHull.inertia, fromBox.inertia, 1e-4);
}

TEST_CASE("a hull of a rotated box has the rotated inertia tensor", "[common][mass][hull]") {
    const Vec3 halfExtents(0.2f, 0.5f, 0.9f);
    const Quat rotation = Quat(Eigen::AngleAxis<Real>(Real(0.7), Vec3(1, 2, 3).normalized()));
    std::vector<Vec3> corners = boxCorners(halfExtents);
    for (Vec3& corner : corners) corner = rotation * corner;
    const MassProperties fromHull = computeMassProperties(Shape::convex(corners), 1000);
    const Mat3 rotationMatrix = rotation.toRotationMatrix();
    const Mat3 expected = rotationMatrix * computeMassProperties(Shape::box(halfExtents), 1000).inertia * rotationMatrix.transpose();
    requireClose(fromHull.inertia, expected, 1e-4);
}

TEST_CASE("a tetrahedron's centre of mass is its vertex average", "[common][mass][hull]") {
    const std::vector<Vec3> points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    const Shape tetrahedron = Shape::convex(points);
    REQUIRE(tetrahedron.hull->faces.size() == 4);
    REQUIRE(shapeVolume(tetrahedron) == Approx(1.0 / 6.0));
    const MassProperties props = computeMassProperties(tetrahedron, 1);
    REQUIRE((props.localCenter - Vec3::Constant(0.25f)).norm() < 1e-6);
    // From the definition, with the simplex moments int x^2 dV = 2!/5! and int x y dV = 1/5!,
    // shifted to the centroid by the parallel-axis theorem.
    const double volume = 1.0 / 6.0;
    const double secondMoment = 1.0 / 60.0;         // int y^2 dV over the unit tetrahedron
    const double expectedDiagonal = 2 * secondMoment - volume * 2 * 0.25 * 0.25;
    const double productMoment = 1.0 / 120.0;        // int x y dV
    const double expectedProduct = -(productMoment - volume * 0.25 * 0.25);
    REQUIRE(props.inertia(0, 0) == Approx(expectedDiagonal).epsilon(1e-5));
    REQUIRE(props.inertia(0, 1) == Approx(expectedProduct).epsilon(1e-5));
    REQUIRE(props.inertia(0, 0) == Approx(props.inertia(1, 1)));
    REQUIRE(props.inertia(0, 1) == Approx(props.inertia(1, 2)));
}

TEST_CASE("hull building drops interior points and merges coplanar faces", "[common][hull]") {
    std::vector<Vec3> points = boxCorners(Vec3::Ones());
    points.push_back(Vec3::Zero());          // interior
    points.push_back(Vec3(1, 0, 0));         // centre of a face
    points.push_back(Vec3(1, 1, 0));         // middle of an edge
    const Shape hull = Shape::convex(points);
    REQUIRE(hull.hull->vertices.size() == 8);
    REQUIRE(hull.hull->faces.size() == 6);
    for (const HullFace& face : hull.hull->faces) {
        REQUIRE(face.vertexIndices.size() == 4);
        for (int index : face.vertexIndices) REQUIRE(face.normal.dot(hull.hull->vertices[index]) == Approx(face.offset));
        // Counter-clockwise seen from outside: the polygon's area vector points along the normal.
        const Vec3& a = hull.hull->vertices[face.vertexIndices[0]];
        const Vec3& b = hull.hull->vertices[face.vertexIndices[1]];
        const Vec3& c = hull.hull->vertices[face.vertexIndices[2]];
        REQUIRE((b - a).cross(c - a).dot(face.normal) > 0);
    }
}

TEST_CASE("degenerate hulls are rejected with a reason", "[common][hull]") {
    using Catch::Matchers::Contains;
    REQUIRE_THROWS_WITH(buildConvexHull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}), Contains("at least 4"));
    REQUIRE_THROWS_WITH(buildConvexHull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)}),
                        Contains("coplanar"));
    REQUIRE_THROWS_WITH(buildConvexHull({Vec3::Ones(), Vec3::Ones(), Vec3::Ones(), Vec3::Ones()}), Contains("coincide"));
    const Real nan = std::numeric_limits<Real>::quiet_NaN();
    REQUIRE_THROWS_WITH(buildConvexHull({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, nan)}),
                        Contains("not finite"));
    std::vector<Vec3> tooMany(kMaxHullPoints + 1, Vec3::Zero());
    REQUIRE_THROWS_WITH(buildConvexHull(tooMany), Contains("at most"));
}

TEST_CASE("aabbs bound every shape", "[common][aabb]") {
    Transform pose;
    pose.position = Vec3(1, 2, 3);
    pose.rotation = Quat(Eigen::AngleAxis<Real>(kPi / 4, Vec3::UnitZ()));
    const Aabb box = computeAabb(Shape::box(Vec3(1, 1, 1)), pose);
    REQUIRE(box.max.x() == Approx(1 + std::sqrt(2.0)));
    REQUIRE(box.max.z() == Approx(4));
    const Aabb capsule = computeAabb(Shape::capsule(0.5f, 1), Transform{});
    REQUIRE(capsule.max.y() == Approx(1.5));
    REQUIRE(capsule.max.x() == Approx(0.5));
}
