// A sphere or a capsule against a hull: the distance between the cores answers while they are
// apart (collideRoundCores), and only overlapping cores go on to GJK and EPA.
#include "03_epa/narrowphase.h"
#include "ch03/random_pairs.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace stepwise;
using stepwise::Random;
using stepwise::test::boxSurfaceDistance;
using stepwise::test::finiteQuery;

namespace {

/// A box as a hull of its eight corners: no closed form knows it, so round shapes meet it through
/// the general routines, and boxSurfaceDistance still measures it exactly.
Shape boxHull(const Vec3& half) {
    std::vector<Vec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.emplace_back((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(), (i & 4) ? half.z() : -half.z());
    return Shape::convex(corners);
}

/// Distance from a segment to a box (double): the distance to a convex set is convex along the
/// segment, so a ternary search finds its least.
double segmentBoxDistance(const Vec3& start, const Vec3& end, const Vec3& half, const Transform& pose) {
    double low = 0, high = 1;
    const auto at = [&](double t) {
        const Vec3 point = (start.cast<double>() + t * (end - start).cast<double>()).cast<Real>();
        return boxSurfaceDistance(point, half, pose);
    };
    for (int i = 0; i < 200; ++i) {
        const double a = low + (high - low) / 3, b = high - (high - low) / 3;
        if (at(a) < at(b)) high = b;
        else low = a;
    }
    return at(0.5 * (low + high));
}

double quantile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    return values[static_cast<std::size_t>(p * static_cast<double>(values.size() - 1))];
}

}  // namespace

TEST_CASE("A sphere or a capsule sunk into a hull reads its depth from the cores, exactly", "[ch03][round_cores]") {
    Random random(23u);
    CollideOptions epaOnly;
    epaOnly.closedForms = false;  // the same pairs through GJK and EPA, for comparison
    std::vector<double> coreErrors, epaErrors;
    for (int attempt = 0; coreErrors.size() < 2000; ++attempt) {
        const Vec3 half(Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)));
        const bool sphere = attempt % 2 == 0;
        const Real radius = Real(random.uniform(0.05, 0.5));
        const Real halfHeight = sphere ? Real(0) : Real(random.uniform(0.05, 0.8));
        const Shape round = sphere ? Shape::sphere(radius) : Shape::capsule(radius, halfHeight);
        Transform boxPose, roundPose;
        boxPose.rotation = random.rotation();
        roundPose.rotation = random.rotation();
        roundPose.position = Real(random.uniform(0, 2)) * random.unitVector();
        const Vec3 axis = roundPose.rotation * Vec3::UnitY();
        const double coreDistance = segmentBoxDistance(roundPose.position - halfHeight * axis,
                                                       roundPose.position + halfHeight * axis, half, boxPose);
        const double trueDepth = double(radius) - coreDistance;
        // Cores apart (a tenth of the radius at least) and the radius reaching in by a tenth or more.
        if (coreDistance < 0.1 * radius || trueDepth < 0.1 * radius) continue;
        const Shape hull = boxHull(half);
        const ContactQuery query = collideShapes(round, roundPose, hull, boxPose);
        REQUIRE(finiteQuery(query));
        CHECK(std::string(query.routine) == "round_cores");
        CHECK(query.intersect);
        CHECK(query.epaIterations == 0);
        // pointA - pointB = depth * normal, and the normal leaves the round shape's core.
        CHECK((query.pointA - query.pointB - query.depth * query.normal).norm() <= Real(1e-5));
        coreErrors.push_back(std::abs(double(query.depth) - trueDepth));
        const ContactQuery viaEpa = collideShapes(round, roundPose, hull, boxPose, epaOnly);
        REQUIRE(finiteQuery(viaEpa));
        epaErrors.push_back(std::abs(double(viaEpa.depth) - trueDepth));
    }
    std::printf("round shapes sunk into hulls: depth error from the cores p95 %.2e max %.2e m; through EPA p95 %.2e "
                "max %.2e m\n",
                quantile(coreErrors, 0.95), quantile(coreErrors, 1), quantile(epaErrors, 0.95),
                quantile(epaErrors, 1));
    // A few float ulps of the shapes' size; EPA stops at its relative tolerance instead.
    CHECK(quantile(coreErrors, 1) <= 2e-6);
    CHECK(quantile(coreErrors, 0.95) <= quantile(epaErrors, 0.95));
}

TEST_CASE("A round shape apart from a hull gets its gap from the cores; cores that overlap go to EPA", "[ch03][round_cores]") {
    const Shape hull = boxHull(Vec3(1, 0.5, 1));
    const Transform ground;  // the hull's top face at y = 0.5
    SECTION("a capsule lying 3 cm above the top face") {
        Transform pose;
        pose.position = Vec3(0.2f, 0.5f + 0.1f + 0.03f, -0.1f);
        pose.rotation = Quat(Eigen::AngleAxis<Real>(Real(1.5707963), Vec3::UnitZ()));  // lying along x
        const ContactQuery query = collideShapes(Shape::capsule(0.1f, 0.4f), pose, hull, ground);
        CHECK(std::string(query.routine) == "round_cores");
        CHECK_FALSE(query.intersect);
        CHECK(query.depth == Approx(-0.03).margin(1e-5));
        CHECK(query.normal.y() == Approx(-1).margin(1e-5));  // from the capsule down to the hull
    }
    SECTION("a capsule lying 2 cm into the top face") {
        Transform pose;
        pose.position = Vec3(0.2f, 0.5f + 0.1f - 0.02f, -0.1f);
        pose.rotation = Quat(Eigen::AngleAxis<Real>(Real(1.5707963), Vec3::UnitZ()));
        const ContactQuery query = collideShapes(Shape::capsule(0.1f, 0.4f), pose, hull, ground);
        CHECK(std::string(query.routine) == "round_cores");
        CHECK(query.intersect);
        CHECK(query.depth == Approx(0.02).margin(1e-5));
        CHECK(query.normal.y() == Approx(-1).margin(1e-5));
    }
    SECTION("a sphere whose centre is inside the hull") {
        Transform pose;
        pose.position = Vec3(0.3f, 0.4f, 0.2f);  // 10 cm under the top face
        const ContactQuery query = collideShapes(Shape::sphere(0.25f), pose, hull, ground);
        CHECK(std::string(query.routine) == "gjk_epa");
        CHECK(query.intersect);
        CHECK(query.depth == Approx(0.35).margin(1e-3));
    }
}
