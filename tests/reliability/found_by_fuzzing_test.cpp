// What the fuzz targets found, pinned with the exact numbers of each case, so the case stays a
// test whatever the fuzz targets' byte encoding becomes (docs/reliability.md).
#include <catch2/catch.hpp>

#include "03_epa/narrowphase.h"

#include <algorithm>
#include <vector>

using namespace stepwise;

TEST_CASE("a needle hull overlapping a small box by a centimetre is found intersecting", "[reliability][gjk]") {
    // fuzz_narrowphase: GJK took a Minkowski triangle thinner than 0.3 degrees for a sliver,
    // stopped as degenerate and reported the pair separated by 1.4 mm. The box's centre lies
    // 9.4 mm inside the hull.
    const std::vector<Vec3> needle = {
        Vec3(Real(-0.000870409072), Real(1.7983954), Real(-0.0619223677)),
        Vec3(Real(0.0336492956), Real(6.65491915), Real(-0.00542088225)),
        Vec3(Real(0.0777806714), Real(9.58265877), Real(-0.0229201037)),
        Vec3(Real(0.0521936528), Real(-1.71604407), Real(0.0777784511)),
        Vec3(Real(-0.022357408), Real(-4.20951128), Real(-0.0777806714)),
        Vec3(Real(0.0700441152), Real(-9.63109398), Real(0.0359330587)),
        Vec3(Real(-0.0777806714), Real(-9.63109493), Real(-0.0777806714)),
        Vec3(Real(-0.0570391603), Real(-7.06280279), Real(0.0119463429)),
        Vec3(Real(-0.0777806714), Real(-9.63109493), Real(-0.0777806714)),
    };
    Transform pose;
    pose.position = Vec3(-100, -100, -100);
    pose.rotation = Quat(Real(-0.5), Real(-0.5), Real(-0.5), Real(-0.5));  // w, x, y, z
    const Real half = Real(0.00413234392);
    for (const bool closedForms : {true, false}) {
        CollideOptions options;
        options.closedForms = closedForms;
        const ContactQuery query = collideShapes(Shape::convex(needle), pose, Shape::box(Vec3(half, half, half)), pose, options);
        CHECK(query.intersect);
        CHECK(query.depth > Real(0.009));  // at least as deep as the box's centre lies inside
        CHECK(query.depth < Real(0.03));
    }
}

namespace {

/// Distance from a world point to a capsule's core segment, m (the surface is at the radius).
double distanceToCore(const Vec3& point, Real halfHeight, const Transform& pose) {
    const Eigen::Vector3d local = (pose.rotation.cast<double>().conjugate() *
                                   (point.cast<double>() - pose.position.cast<double>()));
    const double along = std::clamp(local.y(), -double(halfHeight), double(halfHeight));
    return (local - Eigen::Vector3d(0, along, 0)).norm();
}

}  // namespace

TEST_CASE("two capsules whose axes cross get points on both surfaces", "[reliability][closed-form]") {
    // fuzz_narrowphase: the closest points of two crossing axes came out a few rounding errors
    // apart, and the normal followed that noise instead of the axes' common perpendicular,
    // leaving pointA 5.7 cm inside a capsule of radius 19 cm.
    Transform poseA, poseB;
    poseA.position = poseB.position = Vec3(Real(78.8279037), -100, Real(74.7887802));
    poseA.rotation = Quat(Real(-0.544439733), Real(-0.465428591), Real(0.436516911), Real(-0.544439733));
    poseB.rotation = Quat(Real(0.265866578), Real(-0.367850661), Real(0.772461832), Real(0.444188684));
    const Real radiusA = Real(0.19312495), halfA = Real(0.380705774);
    const Real radiusB = Real(0.00208671344), halfB = Real(0.0127871437);
    const ContactQuery query =
        collideShapes(Shape::capsule(radiusA, halfA), poseA, Shape::capsule(radiusB, halfB), poseB);
    REQUIRE(query.intersect);
    CHECK(query.depth == Approx(double(radiusA + radiusB)).epsilon(1e-4));
    CHECK(distanceToCore(query.pointA, halfA, poseA) == Approx(double(radiusA)).epsilon(1e-3));
    CHECK(distanceToCore(query.pointB, halfB, poseB) == Approx(double(radiusB)).epsilon(1e-2));
}
