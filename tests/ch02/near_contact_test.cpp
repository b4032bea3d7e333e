// Near-contact pairs: the construction is checked against the oracle, then the false positives
// and negatives of each box support map are counted (the same study the bench prints).

#include "02_gjk/study.h"
#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <iostream>

using namespace stepwise;
using namespace stepwise::test;

TEST_CASE("near-contact pairs have the gap they were built with", "[ch02][oracle][near-contact]") {
    Random random(41);
    for (double gap : nearContactGaps()) {
        for (int index = 0; index < 40; ++index) {
            const BoxPair pair = nearContactBoxPair(random, gap);
            const oracle::OracleBox boxA = oracleA(pair), boxB = oracleB(pair);
            const double exactSigned = oracle::boxSignedDistance(boxA, boxB);
            INFO("gap " << gap << ", built " << pair.exactGap << ", oracle " << exactSigned);
            CHECK((exactSigned < 0) == (pair.exactGap < 0));
            if (gap > 0) CHECK(exactSigned == Approx(pair.exactGap).margin(1e-12));
        }
    }
}

TEST_CASE("near contact: false positives and negatives of each box support map", "[ch02][gjk][near-contact]") {
    const std::vector<GapClassification> rows = classifyNearContact(0xC1A55u, nearContactGaps(), 400);
    std::cout << "[ch02] near-contact pairs (Real = " << (sizeof(Real) == 4 ? "float" : "double")
              << "): gap, touching tolerance, then wrong/unclean/dropped for";
    for (int variant = 0; variant < kVariantCount; ++variant) std::cout << " [" << variantName(variant) << "]";
    std::cout << "\n";
    int totals[kVariantCount] = {};
    for (const GapClassification& row : rows) {
        std::cout << "[ch02]   " << row.gap << "  " << row.touchingTolerance;
        for (int variant = 0; variant < kVariantCount; ++variant) {
            std::cout << "  " << row.wrong[variant] << "/" << row.nonCleanExits[variant] << "/" << row.newestDropped[variant];
            totals[variant] += row.wrong[variant];
        }
        std::cout << "\n";
        // Outside the 1e-4 m band both support maps are right, and exit cleanly (separating
        // plane or tetrahedron found). The barycentric-sum variant is the bench's counterexample
        // and is only reported, not held to this.
        if (std::abs(row.gap) >= 1e-4) {
            CHECK(row.wrong[kExtents] == 0);
            CHECK(row.wrong[kVertices] == 0);
            CHECK(row.nonCleanExits[kExtents] == 0);
            CHECK(row.nonCleanExits[kVertices] == 0);
        }
        // Closer than the touching tolerance counts as contact: a separated pair that near is
        // reported as touching by design, by both maps alike.
        if (row.gap > 0 && row.gap < 0.5 * row.touchingTolerance) {
            CHECK(row.wrong[kExtents] == row.pairs);
            CHECK(row.wrong[kVertices] == row.pairs);
        }
    }
    std::cout << "[ch02]   total wrong:";
    for (int variant = 0; variant < kVariantCount; ++variant) std::cout << " " << variantName(variant) << " " << totals[variant] << ";";
    std::cout << "\n";
}
