// Millimetre and kilometre boxes, and pairs 10 km from the origin, against the oracle. The
// tolerances are relative to the pair's size, so the same checks must pass at every scale.

#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

using namespace stepwise;
using namespace stepwise::test;

namespace {

struct ScaleReport {
    int pairs = 0;
    int wrong = 0;
    int distanceFailures = 0;
    int capped = 0;
};

// Random pairs of sizes [minSize, maxSize] around `origin`; agreement outside a band of 1e-4 of
// the size, distances to distanceTolerance with the pair's own size.
ScaleReport checkScale(std::uint32_t seed, int count, double minSize, double maxSize, const Vec3& origin) {
    Random random(seed);
    ScaleReport report;
    const double band = 1e-4 * maxSize / 2;
    for (int index = 0; index < count; ++index) {
        const BoxPair pair = randomBoxPair(random, minSize, maxSize, origin);
        const oracle::OracleBox boxA = oracleA(pair), boxB = oracleB(pair);
        const oracle::SatResult sat = oracle::boxSat(boxA, boxB);
        const double exact = sat.overlap ? 0.0 : oracle::boxDistance(boxA, boxB).distance;
        const double signedDistance = sat.overlap ? -sat.depth : exact;
        const double pairSize = boxA.halfExtents.norm() + boxB.halfExtents.norm();
        for (SupportMode mode : {SupportMode::Extents, SupportMode::Vertices}) {
            const BoxPairProxies proxies(pair, mode);
            const GjkResult result = gjkIntersect(proxies.a, proxies.b);
            ++report.pairs;
            report.capped += result.exit == GjkExit::IterationCap ? 1 : 0;
            if (std::abs(signedDistance) > band && result.intersect != sat.overlap) ++report.wrong;
            if (!sat.overlap && exact > band) {
                const GjkDistanceResult distance = gjkDistance(proxies.a, proxies.b);
                if (!(std::abs(double(distance.distance) - exact) <= distanceTolerance(exact, pairSize))) ++report.distanceFailures;
            }
        }
    }
    return report;
}

}  // namespace

TEST_CASE("GJK is scale-aware: 1 mm, 1 m and 1 km boxes, and pairs 10 km out", "[ch02][gjk][scale]") {
    struct Setting {
        const char* name;
        double minSize, maxSize;
        Vec3 origin;
    };
    const Setting settings[] = {
        {"millimetre boxes", 0.05e-3, 2e-3, Vec3::Zero()},
        {"metre boxes", 0.05, 2.0, Vec3::Zero()},
        {"kilometre boxes", 50.0, 2000.0, Vec3::Zero()},
        {"metre boxes 10 km from the origin", 0.05, 2.0, Vec3(Real(1e4), Real(-1e4), Real(7e3))},
        {"kilometre boxes 10 km from the origin", 50.0, 2000.0, Vec3(Real(-1e4), Real(1e4), Real(1e4))},
    };
    std::uint32_t seed = 1000;
    for (const Setting& setting : settings) {
        const ScaleReport report = checkScale(seed++, 1500, setting.minSize, setting.maxSize, setting.origin);
        std::cout << "[ch02] " << setting.name << ": " << report.pairs << " queries, " << report.wrong
                  << " wrong outside the band, " << report.distanceFailures << " distance failures, " << report.capped
                  << " capped\n";
        INFO(setting.name);
        CHECK(report.wrong == 0);
        CHECK(report.distanceFailures == 0);
        CHECK(report.capped == 0);
    }
}
