#include "02_gjk/study.h"

#include "02_gjk/random_pairs.h"

namespace stepwise {

const char* variantName(int variant) {
    switch (variant) {
        case kExtents: return "extents";
        case kVertices: return "vertices";
        case kExtentsBarycentricSum: return "extents, barycentric-sum face point";
        default: return "?";
    }
}

std::vector<double> nearContactGaps() {
    std::vector<double> gaps;
    for (double magnitude : {1e-2, 1e-3, 1e-4, 3e-5, 1e-5, 1e-6, 1e-7}) gaps.push_back(magnitude);
    for (double magnitude : {1e-7, 1e-6, 1e-5, 3e-5, 1e-4, 1e-3, 1e-2}) gaps.push_back(-magnitude);
    return gaps;
}

std::vector<GapClassification> classifyNearContact(std::uint32_t seed, const std::vector<double>& gaps, int pairsPerGap) {
    Random random(seed);
    std::vector<GapClassification> rows;
    for (double gap : gaps) {
        GapClassification row;
        row.gap = gap;
        // [ch02-near-contact]
        for (int index = 0; index < pairsPerGap; ++index) {
            const BoxPair pair = nearContactBoxPair(random, gap);
            if (pair.exactGap == 0) continue;  // rounding landed exactly on contact: no truth to test
            ++row.pairs;
            const Shape boxA = Shape::box(pair.halfExtentsA);
            const Shape boxB = Shape::box(pair.halfExtentsB);
            row.touchingTolerance += gjkTolerances(ConvexProxy{&boxA, pair.poseA}, ConvexProxy{&boxB, pair.poseB}).touching;
            for (int m = 0; m < kVariantCount; ++m) {
                const SupportMode mode = m == kVertices ? SupportMode::Vertices : SupportMode::Extents;
                const FacePoint facePoint = m == kExtentsBarycentricSum ? FacePoint::BarycentricSum : FacePoint::Projection;
                const GjkResult result = gjkIntersect(ConvexProxy{&boxA, pair.poseA, mode},
                                                      ConvexProxy{&boxB, pair.poseB, mode}, 75, facePoint);
                if (result.intersect != (pair.exactGap < 0)) ++row.wrong[m];
                if (result.exit != GjkExit::Intersect && result.exit != GjkExit::Separated) ++row.nonCleanExits[m];
                if (result.newestDropped > 0) ++row.newestDropped[m];
            }
        }
        // [ch02-near-contact]
        if (row.pairs > 0) row.touchingTolerance /= row.pairs;
        rows.push_back(row);
    }
    return rows;
}

}  // namespace stepwise
