// Round shapes and hulls against closed forms: sphere-sphere, sphere-box, capsule-sphere, and a
// hull made of a box's corners against the box oracle.

#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;
using namespace stepwise::test;

namespace {

constexpr double kBand = 1e-4;  // m: closer to contact than this, either answer is acceptable

// Checks GJK against a closed-form signed distance for one pair; returns false on a mismatch.
bool agrees(const ConvexProxy& a, const ConvexProxy& b, double exactSigned, double pairSize) {
    const GjkResult result = gjkIntersect(a, b);
    if (result.exit == GjkExit::IterationCap) return false;
    if (std::abs(exactSigned) > kBand && result.intersect != (exactSigned < 0)) return false;
    if (exactSigned > kBand) {
        const GjkDistanceResult distance = gjkDistance(a, b);
        if (!(std::abs(double(distance.distance) - exactSigned) <= distanceTolerance(exactSigned, pairSize))) return false;
        // The closest points realise the distance.
        if (!(std::abs((distance.pointA - distance.pointB).cast<double>().norm() - exactSigned) <=
              distanceTolerance(exactSigned, pairSize)))
            return false;
    }
    return true;
}

}  // namespace

TEST_CASE("sphere-sphere and sphere-box agree with the closed forms", "[ch02][gjk][round]") {
    Random random(31);
    int mismatches = 0;
    for (int index = 0; index < 2000; ++index) {
        const Shape sphereA = Shape::sphere(Real(random.uniform(0.05, 1)));
        const Shape sphereB = Shape::sphere(Real(random.uniform(0.05, 1)));
        const Transform poseA{random.unitVector() * Real(random.uniform(0, 2)), random.rotation()};
        const Transform poseB{poseA.position + random.unitVector() * Real(random.uniform(0, 2.5)), random.rotation()};
        const double centers = (poseB.position.cast<double>() - poseA.position.cast<double>()).norm();
        const double sumOfRadii = double(sphereA.radius) + double(sphereB.radius);
        if (!agrees({&sphereA, poseA}, {&sphereB, poseB}, centers - sumOfRadii, sumOfRadii)) {
            ++mismatches;
            FAIL_CHECK("sphere-sphere pair " << index);
        }

        // Sphere against a box: the distance from the centre to the box, minus the radius.
        const BoxPair pair = randomBoxPair(random, 0.05, 2.0);
        const Shape box = Shape::box(pair.halfExtentsB);
        const oracle::OracleBox exactBox = oracleB(pair);
        const double centerToBox = oracle::pointBoxDistance(pair.poseA.position.cast<double>(), exactBox);
        // Inside the box the signed distance is minus the depth to the nearest face: only its
        // sign matters here, and a centre inside means overlap whatever the radius.
        const double exactSigned = centerToBox > 0 ? centerToBox - double(sphereA.radius) : -double(sphereA.radius);
        if (!agrees({&sphereA, pair.poseA}, {&box, pair.poseB}, exactSigned, exactBox.halfExtents.norm() + sphereA.radius)) {
            ++mismatches;
            FAIL_CHECK("sphere-box pair " << index << ", exact " << exactSigned);
        }
    }
    CHECK(mismatches == 0);
}

TEST_CASE("capsule-sphere agrees with the segment distance", "[ch02][gjk][round]") {
    Random random(32);
    for (int index = 0; index < 1000; ++index) {
        const Shape capsule = Shape::capsule(Real(random.uniform(0.05, 0.5)), Real(random.uniform(0, 1)));
        const Shape sphere = Shape::sphere(Real(random.uniform(0.05, 0.5)));
        const Transform poseA{Vec3::Zero(), random.rotation()};
        const Transform poseB{random.unitVector() * Real(random.uniform(0, 2.5)), Quat::Identity()};
        const oracle::Vec3d axis = poseA.rotation.cast<double>().normalized() * oracle::Vec3d(0, double(capsule.halfHeight), 0);
        const double toSegment = oracle::segmentSegmentDistance(-axis, axis, poseB.position.cast<double>(), poseB.position.cast<double>());
        const double exactSigned = toSegment - double(capsule.radius) - double(sphere.radius);
        INFO("pair " << index << ", exact " << exactSigned);
        CHECK(agrees({&capsule, poseA}, {&sphere, poseB}, exactSigned, double(capsule.halfHeight + capsule.radius + sphere.radius)));
    }
}

TEST_CASE("a hull of a box's corners behaves exactly like the box", "[ch02][gjk][hull]") {
    Random random(33);
    for (int index = 0; index < 500; ++index) {
        const BoxPair pair = randomBoxPair(random, 0.05, 2.0);
        std::vector<Vec3> corners;
        const Vec3& h = pair.halfExtentsA;
        for (int c = 0; c < 8; ++c) corners.emplace_back((c & 1) ? h.x() : -h.x(), (c & 2) ? h.y() : -h.y(), (c & 4) ? h.z() : -h.z());
        const Shape hull = Shape::convex(corners);
        const Shape box = Shape::box(pair.halfExtentsB);
        const oracle::OracleBox boxA = oracleA(pair), boxB = oracleB(pair);
        const oracle::SatResult sat = oracle::boxSat(boxA, boxB);
        const double exactSigned = sat.overlap ? -sat.depth : oracle::boxDistance(boxA, boxB).distance;
        INFO("pair " << index << ", exact " << exactSigned);
        CHECK(agrees({&hull, pair.poseA}, {&box, pair.poseB}, exactSigned, boxA.halfExtents.norm() + boxB.halfExtents.norm()));
    }
}
