// Support maps: each returns a point of the shape that no other point beats along the direction.

#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace stepwise;

namespace {

// The support value s(d).d must equal the largest d.x over sample points of the shape's surface
// (corners for polytopes), and the support point must lie in the shape.
std::vector<Vec3> boxCorners(const Vec3& h) {
    std::vector<Vec3> corners;
    for (int c = 0; c < 8; ++c)
        corners.emplace_back((c & 1) ? h.x() : -h.x(), (c & 2) ? h.y() : -h.y(), (c & 4) ? h.z() : -h.z());
    return corners;
}

}  // namespace

TEST_CASE("box support: extents and vertex loop give equally far points", "[ch02][support]") {
    Random random(7);
    const Shape box = Shape::box(Vec3(Real(0.3), Real(1.2), Real(0.05)));
    for (int i = 0; i < 500; ++i) {
        Vec3 d = random.unitVector();
        if (i % 5 == 0) d[i % 3] = 0;  // ties: a zero component makes a whole face or edge farthest
        const Vec3 byExtents = localSupport(box, d, SupportMode::Extents);
        const Vec3 byVertices = localSupport(box, d, SupportMode::Vertices);
        Real best = -kRealMax;
        for (const Vec3& corner : boxCorners(box.halfExtents)) best = std::max(best, corner.dot(d));
        CHECK(byExtents.dot(d) == Approx(best).margin(1e-6));
        CHECK(byVertices.dot(d) == Approx(best).margin(1e-6));
        CHECK((byExtents.cwiseAbs() - box.halfExtents).norm() == Approx(0).margin(1e-6));  // a corner
    }
}

TEST_CASE("sphere, capsule and hull supports", "[ch02][support]") {
    Random random(8);
    const Shape sphere = Shape::sphere(Real(0.7));
    const Shape capsule = Shape::capsule(Real(0.2), Real(0.5));
    const std::vector<Vec3> points = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1),
                                      Vec3(0, 0, -1), Vec3(Real(0.2), Real(0.2), Real(0.2))};  // an interior point too
    const Shape hull = Shape::convex(points);
    for (int i = 0; i < 200; ++i) {
        const Vec3 d = random.unitVector() * Real(random.uniform(0.01, 10));
        const Vec3 unit = d.normalized();
        CHECK((localSupport(sphere, d) - Real(0.7) * unit).norm() == Approx(0).margin(1e-6));
        const Vec3 end(0, unit.y() >= 0 ? Real(0.5) : Real(-0.5), 0);
        CHECK((localSupport(capsule, d) - (end + Real(0.2) * unit)).norm() == Approx(0).margin(1e-6));
        Real best = -kRealMax;
        for (const Vec3& p : points) best = std::max(best, p.dot(d));
        CHECK(localSupport(hull, d).dot(d) == Approx(best).margin(1e-5));
    }
}

TEST_CASE("supports of a zero, tiny or NaN direction are defined points", "[ch02][support][degenerate]") {
    const Shape shapes[] = {Shape::box(Vec3(1, 2, 3)), Shape::sphere(1), Shape::capsule(Real(0.5), 1),
                            Shape::convex({Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(-1, -1, -1)})};
    const Vec3 directions[] = {Vec3::Zero(), Vec3::Constant(std::numeric_limits<Real>::denorm_min()),
                               Vec3::Constant(std::numeric_limits<Real>::quiet_NaN())};
    for (const Shape& shape : shapes)
        for (const Vec3& d : directions)
            for (SupportMode mode : {SupportMode::Extents, SupportMode::Vertices}) {
                const Vec3 s = localSupport(shape, d, mode);
                CHECK(s.allFinite());
                CHECK(s.norm() <= boundingRadius(shape) * Real(1.0001));
            }
    // A convex shape without a hull (malformed input) answers the origin, not a crash.
    Shape broken;
    broken.type = ShapeType::Convex;
    CHECK(localSupport(broken, Vec3::UnitX()) == Vec3::Zero());
}

TEST_CASE("Minkowski support is the difference of the two supports", "[ch02][support]") {
    Random random(9);
    const BoxPair pair = randomBoxPair(random, 0.1, 1.0, Vec3(Real(1e4), 0, Real(-1e4)));
    const test::BoxPairProxies proxies(pair, SupportMode::Extents);
    for (int i = 0; i < 50; ++i) {
        const Vec3 d = random.unitVector();
        const SupportPoint point = minkowskiSupport(proxies.a, proxies.b, d);
        CHECK((point.onA - proxies.a.support(d)).norm() == Approx(0).margin(1e-6));
        CHECK((point.onB - proxies.b.support(-d)).norm() == Approx(0).margin(1e-6));
        // w is computed relative to the positions: compare it with the exact difference in double.
        const oracle::Vec3d exact = (proxies.a.transform.position.cast<double>() - proxies.b.transform.position.cast<double>()) +
                                    (proxies.a.transform.rotation.cast<double>() *
                                         localSupport(proxies.shapeA, proxies.a.transform.rotateInverse(d)).cast<double>() -
                                     proxies.b.transform.rotation.cast<double>() *
                                         localSupport(proxies.shapeB, proxies.b.transform.rotateInverse(-d)).cast<double>());
        CHECK((point.w.cast<double>() - exact).norm() < 1e-5);
    }
}
