// The closed-form routines against double-precision references, and against GJK + EPA.
#include "03_epa/closed_form.h"
#include "03_epa/narrowphase.h"
#include "ch03/random_pairs.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

using namespace stepwise;
using stepwise::test::finiteQuery;
using stepwise::Random;
using Vec3d = Eigen::Vector3d;

namespace {

// Float keeps about 7 digits: a value of size `size` is good to a few ulps of it.
const double kUlps = 16 * double(kEpsilon);

/// Expected contact of two fat points (double): depth and normal from the cores.
void checkAgainstCores(const ContactQuery& query, const Vec3d& coreA, double radiusA, const Vec3d& coreB,
                       double radiusB) {
    const double distance = (coreB - coreA).norm();
    const double size = radiusA + radiusB + distance;
    REQUIRE(finiteQuery(query));
    CHECK(std::abs(double(query.depth) - (radiusA + radiusB - distance)) <= kUlps * size);
    CHECK(query.intersect == (radiusA + radiusB - distance >= 0));
    if (distance > 0) {
        // The direction of a float difference is good to a few ulps of the size over its length
        // (more for nearly parallel segments, whose closest points are ill-conditioned).
        const Vec3d normal = (coreB - coreA) / distance;
        CHECK((query.normal.cast<double>() - normal).norm() <= std::max(1e-5, 4 * kUlps * size / distance));
    }
    CHECK(std::abs(query.normal.norm() - Real(1)) <= Real(1e-5));
    // pointA - pointB = depth * normal, with both points on their shapes' surfaces.
    CHECK((query.pointA - query.pointB - query.depth * query.normal).norm() <= Real(kUlps * size));
}

}  // namespace

TEST_CASE("Sphere pairs are exact", "[ch03][closed_form]") {
    Random random(11u);
    for (int i = 0; i < 5000; ++i) {
        const Real radiusA = Real(random.uniform(0.05, 1)), radiusB = Real(random.uniform(0.05, 1));
        Transform poseA, poseB;
        poseA.position = Vec3(Real(random.uniform(-3, 3)), Real(random.uniform(-3, 3)), Real(random.uniform(-3, 3)));
        poseB.position = poseA.position + Real(random.uniform(0, 1.5 * (radiusA + radiusB))) * random.unitVector();
        const ContactQuery query = collideShapes(Shape::sphere(radiusA), poseA, Shape::sphere(radiusB), poseB);
        CHECK(std::string(query.routine) == "sphere_sphere");
        CHECK(query.gjkIterations == 0);
        CHECK(query.epaIterations == 0);
        checkAgainstCores(query, poseA.position.cast<double>(), radiusA, poseB.position.cast<double>(), radiusB);
        const double surfaceA = (query.pointA - poseA.position).norm() - radiusA;
        const double surfaceB = (query.pointB - poseB.position).norm() - radiusB;
        CHECK(std::abs(surfaceA) <= 1e-5);
        CHECK(std::abs(surfaceB) <= 1e-5);
    }
}

TEST_CASE("Concentric spheres overlap by the sum of the radii along +Y", "[ch03][closed_form]") {
    const ContactQuery query = collideSpheres(Vec3(1, 2, 3), Real(0.5), Vec3(1, 2, 3), Real(0.25));
    CHECK(query.intersect);
    CHECK(query.depth == Approx(0.75));
    CHECK(query.normal == Vec3::UnitY());
    CHECK(finiteQuery(query));
}

TEST_CASE("Box-sphere matches the distance to the box, inside and out, in either order", "[ch03][closed_form]") {
    Random random(12u);
    int inside = 0;
    for (int i = 0; i < 5000; ++i) {
        const Vec3 half(Real(random.uniform(0.1, 1)), Real(random.uniform(0.1, 1)), Real(random.uniform(0.1, 1)));
        Transform box;
        box.rotation = random.rotation();
        const Real radius = Real(random.uniform(0.05, 1));
        Transform sphere;
        sphere.position = Real(random.uniform(0, half.norm() + 1.2 * radius)) * random.unitVector();
        const oracle::OracleBox oracleBox = oracle::makeOracleBox(half, box);
        const Vec3d center = sphere.position.cast<double>();
        const Vec3d local = oracleBox.axes.transpose() * (center - oracleBox.center);
        const double outside = oracle::pointBoxDistance(center, oracleBox);
        const double exact = outside > 0 ? radius - outside : radius + (oracleBox.halfExtents - local.cwiseAbs()).minCoeff();
        inside += outside == 0;

        const ContactQuery query = collideShapes(Shape::box(half), box, Shape::sphere(radius), sphere);
        REQUIRE(finiteQuery(query));
        CHECK(std::string(query.routine) == "box_sphere");
        CHECK(std::abs(double(query.depth) - exact) <= kUlps * 4);
        CHECK(std::abs(test::boxSurfaceDistance(query.pointA, half, box)) <= 1e-5);
        CHECK(std::abs((query.pointB - sphere.position).norm() - radius) <= Real(1e-5));
        CHECK((query.pointA - query.pointB - query.depth * query.normal).norm() <= Real(1e-5));
        // The normal points from the box towards the sphere's centre side.
        if (outside > 0) CHECK(query.normal.dot(sphere.position - query.pointA) > 0);

        const ContactQuery flipped = collideShapes(Shape::sphere(radius), sphere, Shape::box(half), box);
        // The same routine with the roles swapped (each query works relative to its own A).
        CHECK(flipped.depth == Approx(query.depth).margin(1e-6));
        CHECK((flipped.normal + query.normal).norm() <= Real(1e-6));
        CHECK((flipped.pointA - query.pointB).norm() <= Real(1e-6));
        CHECK((flipped.pointB - query.pointA).norm() <= Real(1e-6));
    }
    CHECK(inside > 100);  // the sample does reach the "centre inside the box" branch
}

TEST_CASE("Capsule pairs match segment distances", "[ch03][closed_form]") {
    Random random(13u);
    for (int i = 0; i < 5000; ++i) {
        const Real radiusA = Real(random.uniform(0.05, 0.6)), radiusB = Real(random.uniform(0.05, 0.6));
        const Real halfA = Real(random.uniform(0, 1)), halfB = Real(random.uniform(0, 1));
        Transform poseA, poseB;
        poseA.rotation = random.rotation();
        poseB.rotation = random.rotation();
        poseB.position = Real(random.uniform(0, 1.2 * (radiusA + radiusB + halfA + halfB))) * random.unitVector();
        const auto endpoints = [](const Transform& pose, Real half, Vec3d& p, Vec3d& q) {
            p = pose.apply(Vec3(0, -half, 0)).cast<double>();
            q = pose.apply(Vec3(0, half, 0)).cast<double>();
        };
        Vec3d p1, q1, p2, q2, onA, onB;
        endpoints(poseA, halfA, p1, q1);
        endpoints(poseB, halfB, p2, q2);
        oracle::segmentSegmentDistance(p1, q1, p2, q2, &onA, &onB);
        const ContactQuery capsules =
            collideShapes(Shape::capsule(radiusA, halfA), poseA, Shape::capsule(radiusB, halfB), poseB);
        CHECK(std::string(capsules.routine) == "capsule_capsule");
        checkAgainstCores(capsules, onA, radiusA, onB, radiusB);

        const Vec3d center = poseB.position.cast<double>();
        oracle::segmentSegmentDistance(p1, q1, center, center, &onA, &onB);
        const ContactQuery withSphere = collideShapes(Shape::capsule(radiusA, halfA), poseA, Shape::sphere(radiusB), poseB);
        CHECK(std::string(withSphere.routine) == "capsule_sphere");
        checkAgainstCores(withSphere, onA, radiusA, center, radiusB);
    }
}

TEST_CASE("Crossing capsule axes separate along their common perpendicular", "[ch03][closed_form]") {
    Transform poseA, poseB;
    poseA.rotation = Quat(Eigen::AngleAxis<Real>(kPi / 2, Vec3::UnitZ()));  // axis along -X
    poseB.position = Vec3(0, 0, Real(0.01));                                   // axis along +Y
    const ContactQuery query = collideShapes(Shape::capsule(Real(0.2), 1), poseA, Shape::capsule(Real(0.3), 1), poseB);
    CHECK(query.intersect);
    CHECK(query.depth == Approx(0.49).epsilon(1e-5));
    CHECK(std::abs(query.normal.z()) == Approx(1).epsilon(1e-5));

    // Exactly crossing, and a sphere centred on a capsule axis: any direction is as deep.
    poseB.position = Vec3::Zero();
    const ContactQuery crossing = collideShapes(Shape::capsule(Real(0.2), 1), poseA, Shape::capsule(Real(0.3), 1), poseB);
    CHECK(crossing.depth == Approx(0.5));
    CHECK(std::abs(crossing.normal.z()) == Approx(1));
    const ContactQuery onAxis = collideShapes(Shape::capsule(Real(0.2), 1), poseB, Shape::sphere(Real(0.1)), poseB);
    CHECK(onAxis.depth == Approx(0.3));
    CHECK(std::abs(onAxis.normal.y()) < Real(1e-6));
    CHECK(finiteQuery(onAxis));
}

TEST_CASE("GJK + EPA agrees with the closed forms on curved shapes", "[ch03][closed_form][epa]") {
    // A - B is curved here, so EPA approaches it from inside: a lower bound that converges
    // to the relative tolerance, capped at 50 expansions.
    Random random(14u);
    CollideOptions epaOnly;
    epaOnly.closedForms = false;
    std::vector<double> errors;
    int routed = 0;
    for (int attempt = 0; errors.size() < 3000; ++attempt) {
        // Alternate sphere-box and capsule-capsule (capsule-box has no closed form to compare).
        const bool sphereBox = attempt % 2 == 0;
        const Shape a = sphereBox ? Shape::sphere(Real(random.uniform(0.1, 1)))
                                  : Shape::capsule(Real(random.uniform(0.1, 0.5)), Real(random.uniform(0.1, 1)));
        const Shape b = sphereBox ? Shape::box(Vec3(Real(random.uniform(0.1, 1)), Real(random.uniform(0.1, 1)), Real(random.uniform(0.1, 1))))
                                  : Shape::capsule(Real(random.uniform(0.1, 0.5)), Real(random.uniform(0.1, 1)));
        Transform poseA, poseB;
        poseA.rotation = random.rotation();
        poseB.rotation = random.rotation();
        poseB.position = Real(random.uniform(0, boundingRadius(a) + boundingRadius(b))) * random.unitVector();
        const ContactQuery exact = collideShapes(a, poseA, b, poseB);
        if (!exact.intersect || exact.depth < Real(0.02) * std::min(a.radius, b.type == ShapeType::Box ? a.radius : b.radius)) {
            continue;  // a relative error means little at a depth of a few ulps
        }
        const ContactQuery viaEpa = collideShapes(a, poseA, b, poseB, epaOnly);
        routed += std::string(viaEpa.routine) == "gjk_epa";
        REQUIRE(finiteQuery(viaEpa));
        CHECK(viaEpa.intersect);
        errors.push_back(std::abs(double(viaEpa.depth - exact.depth)) / double(exact.depth));
    }
    std::printf("curved pairs through EPA: %zu, depth rel. error p50 %.2e p95 %.2e max %.2e\n", errors.size(),
                percentile(errors, 0.5), percentile(errors, 0.95), percentile(errors, 1.0));
    CHECK(routed == static_cast<int>(errors.size()));
    CHECK(percentile(errors, 0.95) <= 1e-3);
    CHECK(percentile(errors, 1.0) <= 2e-2);
}

TEST_CASE("The narrowphase knows which pairs have closed forms", "[ch03][closed_form]") {
    CHECK(hasClosedForm(ShapeType::Sphere, ShapeType::Sphere));
    CHECK(hasClosedForm(ShapeType::Sphere, ShapeType::Box));
    CHECK(hasClosedForm(ShapeType::Box, ShapeType::Sphere));
    CHECK(hasClosedForm(ShapeType::Capsule, ShapeType::Capsule));
    CHECK(hasClosedForm(ShapeType::Sphere, ShapeType::Capsule));
    CHECK_FALSE(hasClosedForm(ShapeType::Box, ShapeType::Box));
    CHECK_FALSE(hasClosedForm(ShapeType::Capsule, ShapeType::Box));
    CHECK_FALSE(hasClosedForm(ShapeType::Convex, ShapeType::Sphere));
}
