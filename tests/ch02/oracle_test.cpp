// The oracle checks itself: known configurations, and an independent method (alternating
// projections) on random pairs. Chapters 2 and 3 trust it, so it must earn that.

#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;
using namespace stepwise::oracle;

namespace {

OracleBox cube(double half, const Vec3d& center, const Mat3d& axes = Mat3d::Identity()) {
    OracleBox box;
    box.halfExtents = Vec3d::Constant(half);
    box.center = center;
    box.axes = axes;
    return box;
}

Mat3d rotation(double angle, const Vec3d& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

// Von Neumann's alternating projections between two disjoint convex sets converge to a closest
// pair: an answer reached by a completely different route than the feature enumeration.
double alternatingProjectionDistance(const OracleBox& a, const OracleBox& b) {
    Vec3d onA = a.center, onB = b.center;
    for (int i = 0; i < 20000; ++i) {
        pointBoxDistance(onB, a, &onA);
        pointBoxDistance(onA, b, &onB);
    }
    return (onA - onB).norm();
}

}  // namespace

TEST_CASE("oracle: face, edge-edge and vertex configurations with known answers", "[ch02][oracle]") {
    const double sqrtHalf = std::sqrt(0.5);
    SECTION("faces, separated and overlapping") {
        const OracleBox a = cube(0.5, Vec3d::Zero());
        const SatResult apart = boxSat(a, cube(0.25, Vec3d(0.85, 0.1, 0)));
        CHECK_FALSE(apart.overlap);
        CHECK(apart.depth == Approx(0.1));
        CHECK(boxDistance(a, cube(0.25, Vec3d(0.85, 0.1, 0))).distance == Approx(0.1));
        const SatResult deep = boxSat(a, cube(0.25, Vec3d(0.65, 0.1, 0)));
        CHECK(deep.overlap);
        CHECK(deep.depth == Approx(0.1));
        CHECK(deep.axis.isApprox(Vec3d::UnitX()));
        CHECK(deep.axisIndex == 0);
    }
    SECTION("crossed edges: the edge-edge axis wins") {
        // A's top edge runs along x at height sqrt(1/2); B's bottom edge along z, crossing it.
        const OracleBox a = cube(0.5, Vec3d::Zero(), rotation(0.25 * M_PI, Vec3d::UnitX()));
        for (double gap : {0.1, -0.1}) {
            const OracleBox b = cube(0.5, Vec3d(0, 2 * sqrtHalf + gap, 0), rotation(0.25 * M_PI, Vec3d::UnitY()) *
                                                                              rotation(0.25 * M_PI, Vec3d::UnitX()));
            const SatResult sat = boxSat(a, b);
            CHECK(sat.overlap == (gap < 0));
            CHECK(sat.depth == Approx(std::abs(gap)));
            CHECK(std::abs(sat.axis.y()) == Approx(1.0));
            CHECK(sat.axisIndex >= 6);
            if (gap > 0) {
                const DistanceResult distance = boxDistance(a, b);
                CHECK(distance.distance == Approx(gap));
                CHECK(distance.pointA.isApprox(Vec3d(0, sqrtHalf, 0), 1e-9));
            }
        }
    }
    SECTION("corner to corner along the diagonal") {
        const OracleBox a = cube(0.5, Vec3d::Zero());
        const OracleBox b = cube(0.5, Vec3d(1.1, 1.1, 1.1));
        CHECK(boxDistance(a, b).distance == Approx(0.1 * std::sqrt(3.0)));
    }
}

TEST_CASE("oracle: depth and distance are consistent with independent checks", "[ch02][oracle]") {
    Random random(2024);
    int separatedChecked = 0, overlapChecked = 0;
    for (int index = 0; index < 300; ++index) {
        const BoxPair pair = randomBoxPair(random, 0.05, 2.0);
        const OracleBox a = test::oracleA(pair);
        OracleBox b = test::oracleB(pair);
        const SatResult sat = boxSat(a, b);
        if (sat.overlap) {
            // Moving B by the depth along the axis just separates it; a little less does not.
            OracleBox moved = b;
            moved.center = b.center + (sat.depth + 1e-9) * sat.axis;
            CHECK_FALSE(boxSat(a, moved).overlap);
            moved.center = b.center + (sat.depth - 1e-7) * sat.axis;
            CHECK(boxSat(a, moved).overlap);
            ++overlapChecked;
        } else {
            const DistanceResult distance = boxDistance(a, b);
            CHECK(distance.distance >= sat.depth - 1e-12);  // SAT gap is a lower bound
            CHECK(pointBoxDistance(distance.pointA, a) < 1e-12);
            CHECK(pointBoxDistance(distance.pointB, b) < 1e-12);
            CHECK((distance.pointA - distance.pointB).norm() == Approx(distance.distance));
            CHECK(alternatingProjectionDistance(a, b) == Approx(distance.distance).margin(1e-7));
            ++separatedChecked;
        }
    }
    CHECK(overlapChecked > 50);
    CHECK(separatedChecked > 50);
}
