// What the fuzz targets found, pinned with the exact numbers of each case, so the case stays a
// test whatever the fuzz targets' byte encoding becomes (docs/reliability.md).
#include <catch2/catch.hpp>

#include "03_epa/narrowphase.h"

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
