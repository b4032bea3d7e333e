// GJK on random box pairs against the exact oracle (chapters/02_gjk/box_oracle.h).

#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

using namespace stepwise;
using namespace stepwise::test;

namespace {

struct ModeTally {
    int falsePositives = 0;        // GJK says intersect, the oracle says separated
    int falseNegatives = 0;        // GJK says separated, the oracle says overlapping
    int wrongOutsideBand = 0;      // misclassified although |exact| > band
    int distanceFailures = 0;
    double worstRelativeError = 0;
    double worstErrorInEpsilons = 0;   // max over pairs of error / (eps * pair size)
    long iterations = 0;
    int maxIterations = 0;
    int newestDropped = 0;
    int cleanExits = 0;
    int intersecting = 0;
    int tetrahedraHoldingOrigin = 0;
};

const char* modeName(SupportMode mode) { return mode == SupportMode::Extents ? "extents" : "vertices"; }

}  // namespace

TEST_CASE("GJK agrees with the exact oracle on 10,000 random box pairs", "[ch02][gjk][oracle]") {
    const int pairCount = 10000;
    const double band = 1e-4;  // m: closer to contact than this either answer is acceptable
    Random random(0xC0FFEE02u);
    ModeTally tallies[2];
    int overlapping = 0;
    int disagreeModes = 0;
    for (int index = 0; index < pairCount; ++index) {
        const BoxPair pair = randomBoxPair(random, 0.05, 2.0);
        const oracle::OracleBox boxA = oracleA(pair);
        const oracle::OracleBox boxB = oracleB(pair);
        const oracle::SatResult sat = oracle::boxSat(boxA, boxB);
        const oracle::DistanceResult exact = oracle::boxDistance(boxA, boxB);
        const double signedDistance = sat.overlap ? -sat.depth : exact.distance;
        overlapping += sat.overlap ? 1 : 0;
        const double pairSize = boxA.halfExtents.norm() + boxB.halfExtents.norm();

        bool answers[2] = {false, false};
        for (int m = 0; m < 2; ++m) {
            const SupportMode mode = m == 0 ? SupportMode::Extents : SupportMode::Vertices;
            const BoxPairProxies proxies(pair, mode);
            ModeTally& tally = tallies[m];

            const GjkResult result = gjkIntersect(proxies.a, proxies.b);
            answers[m] = result.intersect;
            tally.iterations += result.iterations;
            tally.maxIterations = std::max(tally.maxIterations, result.iterations);
            tally.newestDropped += result.newestDropped;
            tally.cleanExits += (result.exit == GjkExit::Intersect || result.exit == GjkExit::Separated) ? 1 : 0;
            if (result.intersect) {
                ++tally.intersecting;
                tally.tetrahedraHoldingOrigin += tetrahedronHoldsOrigin(result.simplex, gjkTolerances(proxies.a, proxies.b).touching);
            }
            if (result.intersect && !sat.overlap) ++tally.falsePositives;
            if (!result.intersect && sat.overlap) ++tally.falseNegatives;
            if (result.intersect != sat.overlap && std::abs(signedDistance) > band) {
                ++tally.wrongOutsideBand;
                if (tally.wrongOutsideBand <= 3)
                    FAIL_CHECK("pair " << index << " (" << modeName(mode) << "): GJK intersect=" << result.intersect
                                       << " exit=" << toString(result.exit) << ", exact signed distance " << signedDistance);
            }

            if (!sat.overlap && exact.distance > band) {
                const GjkDistanceResult distance = gjkDistance(proxies.a, proxies.b);
                const double error = std::abs(double(distance.distance) - exact.distance);
                tally.worstRelativeError = std::max(tally.worstRelativeError, error / exact.distance);
                tally.worstErrorInEpsilons = std::max(tally.worstErrorInEpsilons, error / (double(kEpsilon) * pairSize));
                // The closest points must realise the distance and lie on the boxes.
                const double gapOfPoints = (distance.pointA - distance.pointB).cast<double>().norm();
                const double offA = oracle::pointBoxDistance(distance.pointA.cast<double>(), boxA);
                const double offB = oracle::pointBoxDistance(distance.pointB.cast<double>(), boxB);
                const double tolerance = distanceTolerance(exact.distance, pairSize);
                const bool ok = distance.separated && error <= tolerance &&
                                std::abs(gapOfPoints - exact.distance) <= tolerance && offA <= tolerance && offB <= tolerance;
                if (!ok && ++tally.distanceFailures <= 3)
                    FAIL_CHECK("pair " << index << " (" << modeName(mode) << "): GJK distance " << distance.distance
                                       << " exit=" << toString(distance.exit) << ", exact " << exact.distance
                                       << ", |pA-pB| " << gapOfPoints << ", off A " << offA << ", off B " << offB);
            }
        }
        if (answers[0] != answers[1] && std::abs(signedDistance) > band) ++disagreeModes;
    }

    std::cout << "[ch02] " << pairCount << " random box pairs (" << overlapping << " overlapping), Real = "
              << (sizeof(Real) == 4 ? "float" : "double") << "\n";
    for (int m = 0; m < 2; ++m) {
        const ModeTally& tally = tallies[m];
        std::cout << "[ch02]   " << modeName(m == 0 ? SupportMode::Extents : SupportMode::Vertices)
                  << ": false positives " << tally.falsePositives << ", false negatives " << tally.falseNegatives
                  << ", wrong outside the 1e-4 m band " << tally.wrongOutsideBand << ", mean iterations "
                  << double(tally.iterations) / pairCount << ", max " << tally.maxIterations << ", clean exits "
                  << tally.cleanExits << ", newest vertex dropped " << tally.newestDropped
                  << ", worst relative distance error " << tally.worstRelativeError << " (absolute: "
                  << tally.worstErrorInEpsilons << " eps x pair size; the tolerance allows 1e-4 relative + 16)\n";
        CHECK(tally.wrongOutsideBand == 0);
        CHECK(tally.distanceFailures == 0);
        CHECK(tally.maxIterations < 75);
        // Chapter 3 starts from the simplex: every intersecting answer hands over a tetrahedron
        // around the origin.
        CHECK(tally.tetrahedraHoldingOrigin == tally.intersecting);
    }
    CHECK(disagreeModes == 0);
}
