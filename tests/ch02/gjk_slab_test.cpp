// A small box resting on a large one: the commonest pair of a scene (a crate on the ground) and
// the hardest shape for GJK's simplex, since A - B is then a slab 40 m wide and about a metre
// thick, and the tetrahedra near the origin are slivers millimetres thick. Against the oracle.

#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace stepwise;
using namespace stepwise::test;

namespace {

/// A box of edges 0.2..1.2 m resting on a face, at a random place over a 40 m ground box (top face
/// y = 0), lowered so that its lowest corner lies `depth` below the top (< 0: above it).
BoxPair boxOnGround(Random& random, double depth) {
    BoxPair pair;
    pair.halfExtentsA = Vec3(20, Real(0.5), 20);
    pair.poseA = Transform{Vec3(0, Real(-0.5), 0), Quat::Identity()};
    pair.halfExtentsB = Vec3(random.uniformReal(Real(0.1), Real(0.6)), random.uniformReal(Real(0.1), Real(0.6)),
                             random.uniformReal(Real(0.1), Real(0.6)));
    // Resting on a face, as boxes on the ground do: a random face down, a random heading, and a
    // tilt of up to half a degree (a random rotation is almost never this close to flat, and the
    // flat ones are the slivers).
    const int face = static_cast<int>(random.uniform() * 6) % 6;
    const Vec3 faceAxis = face < 2 ? Vec3::UnitX() : face < 4 ? Vec3::UnitZ() : Vec3::UnitY();
    const Real faceAngle = face < 4 ? Real(face % 2 ? 1.5707963 : -1.5707963) : Real(face == 5 ? 3.1415927 : 0);
    const Quat heading(Eigen::AngleAxis<Real>(random.uniformReal(0, Real(6.2831853)), Vec3::UnitY()));
    const Quat tilt(Eigen::AngleAxis<Real>(random.uniformReal(0, Real(0.0087)), random.unitVector()));
    const Quat rotation = (tilt * heading * Quat(Eigen::AngleAxis<Real>(faceAngle, faceAxis))).normalized();
    const Mat3 axes = rotation.toRotationMatrix();
    // The lowest corner's height below the centre: the half extents along the world's up axis.
    double reach = 0;
    for (int k = 0; k < 3; ++k) reach += std::abs(double(axes(1, k))) * double(pair.halfExtentsB[k]);
    const Real x = random.uniformReal(-15, 15), z = random.uniformReal(-15, 15);
    pair.poseB = Transform{Vec3(x, Real(reach - depth), z), rotation};
    return pair;
}

}  // namespace

TEST_CASE("a small box on a 40 m ground box: GJK agrees with the oracle on touching and apart",
          "[ch02][gjk][scale]") {
    Random random(0x51AB);
    int checked = 0;
    for (const double depth : {-3e-3, -1e-3, 1e-3, 3e-3, 1e-2}) {
        for (int index = 0; index < 2000; ++index) {
            const BoxPair pair = boxOnGround(random, depth);
            const oracle::OracleBox ground = oracleA(pair), box = oracleB(pair);
            const double exact = oracle::boxSignedDistance(ground, box);  // < 0: overlap
            const BoxPairProxies proxies(pair, SupportMode::Extents);
            const GjkTolerances tolerances = gjkTolerances(proxies.a, proxies.b);
            // Beyond twice the touching tolerance (plus the pose's own float rounding) the
            // answer is clear-cut.
            const double clear = 2 * double(tolerances.touching) + 1e-5;
            if (std::abs(exact) < clear) continue;
            ++checked;
            const GjkResult intersect = gjkIntersect(proxies.a, proxies.b);
            const GjkDistanceResult distance = gjkDistance(proxies.a, proxies.b);
            INFO("depth " << depth << ", pair " << index << ": oracle " << exact << ", gjk " << intersect.intersect
                          << " (" << toString(intersect.exit) << "), distance " << distance.separated << " "
                          << distance.distance << " (" << toString(distance.exit) << ")");
            CHECK(intersect.intersect == (exact < 0));
            CHECK(distance.separated == (exact > 0));
            // A walk that ends cleanly has the distance; one stopped by a rounding floor, with its
            // gap proven by a support plane, has the distance of two points of the shapes: never
            // less than the distance.
            const double tolerance = distanceTolerance(exact, 41);
            if (exact > 0 && distance.exit == GjkExit::Separated) CHECK(double(distance.distance) == Approx(exact).margin(tolerance));
            if (exact > 0) CHECK(double(distance.distance) >= exact - tolerance);
        }
    }
    CHECK(checked > 8000);
}

namespace {

/// The distance from the origin to the hull of `points` (separated), in double, by brute force:
/// every vertex, every edge's and every triangle's closest point, kept when no point of the set
/// lies beyond its support plane.
double hullDistanceFromOrigin(const std::vector<Eigen::Vector3d>& points) {
    double best = std::numeric_limits<double>::max();
    const auto consider = [&](const Eigen::Vector3d& x) {
        const double squared = x.squaredNorm();
        if (squared == 0) return;
        for (const Eigen::Vector3d& p : points)
            if (p.dot(x) < squared * (1 - 1e-9)) return;
        best = std::min(best, std::sqrt(squared));
    };
    const std::size_t n = points.size();
    for (std::size_t i = 0; i < n; ++i) {
        consider(points[i]);
        for (std::size_t j = i + 1; j < n; ++j) {
            const Eigen::Vector3d ab = points[j] - points[i];
            const double t = -points[i].dot(ab) / ab.squaredNorm();
            if (t > 0 && t < 1) consider(points[i] + t * ab);
            for (std::size_t k = j + 1; k < n; ++k) {
                const Eigen::Vector3d ac = points[k] - points[i];
                const Eigen::Vector3d normal = ab.cross(ac);
                const double normalSquared = normal.squaredNorm();
                if (normalSquared < 1e-30) continue;
                const Eigen::Vector3d x = normal * (normal.dot(points[i]) / normalSquared);
                const double v = normal.dot(ac.cross(points[i])) / normalSquared;
                const double w = normal.dot(points[i].cross(ab)) / normalSquared;
                if (v >= 0 && w >= 0 && v + w <= 1) consider(x);
            }
        }
    }
    return best;
}

}  // namespace

TEST_CASE("a 1.2 mm box 9 mm from a 56 m slab: the distance query finds the gap", "[ch02][gjk][scale]") {
    // Found by fuzz_narrowphase (tests/fuzz/regressions/narrowphase/tiny-box-beside-thin-slab): the
    // nearest feature of A - B is a segment whose ends lie about 40 m from the origin. A float sum
    // of them carries eps |p|, which turns the closest point by eps |p| / |v|, and the support
    // plane it points at misses the 9 mm gap: the float walk stopped on a rounding floor and the
    // pair read as touching, its points 8.8 mm apart. The second walk, its closest point in double,
    // finds the gap.
    const std::vector<Vec3> corners = {
        Vec3(Real(15.7181301), Real(-0.00279964437), Real(-13.5600805)),
        Vec3(Real(27.9950047), Real(0.00279972982), Real(27.8147392)),
        Vec3(Real(27.9949608), Real(0.00279972982), Real(27.9676456)),
        Vec3(Real(-3.79030108), Real(0.00223821169), Real(-22.0898056)),
        Vec3(Real(-27.9950047), Real(-0.00279972982), Real(-27.9950047)),
        Vec3(Real(-27.8360462), Real(-0.000896216428), Real(-27.9950047))};
    const Real half = Real(0.000616979029);
    const Shape slab = Shape::convex(corners);
    const Shape box = Shape::box(Vec3::Constant(half));
    const Transform pose{Vec3::Constant(-100), Quat(Real(-0.5), Real(-0.5), Real(-0.5), Real(-0.5))};
    // Exact, in the frame both share: A - B's points are the slab's corners less the box's.
    std::vector<Eigen::Vector3d> difference;
    for (const Vec3& corner : slab.hull->vertices)
        for (int k = 0; k < 8; ++k) {
            const Eigen::Vector3d offset(k & 1 ? half : -half, k & 2 ? half : -half, k & 4 ? half : -half);
            difference.push_back(corner.cast<double>() - offset);
        }
    const double exact = hullDistanceFromOrigin(difference);
    REQUIRE(exact == Approx(0.0087872).margin(1e-6));
    const ConvexProxy a{&slab, pose, SupportMode::Extents}, b{&box, pose, SupportMode::Extents};
    const GjkDistanceResult distance = gjkDistance(a, b);
    INFO("distance " << distance.distance << " m, exact " << exact << " m, exit " << static_cast<int>(distance.exit));
    CHECK(distance.separated);
    CHECK(std::abs(double(distance.distance) - exact) < 2e-5);
    // The witness points are the gap apart, along the axis.
    CHECK(std::abs(double((distance.pointB - distance.pointA).norm()) - exact) < 2e-5);
}

TEST_CASE("a stalled walk beside a sliver of A - B still finds the gap", "[ch02][gjk][scale]") {
    // A 56 m hull (two of its seven points the same, two 0.5 mm apart) and a 1.2 mm box whose
    // centre lies 6.9 mm outside it, 100 m from the origin (a fuzz_narrowphase find): the boolean
    // walk stalls on a tetrahedron whose support plane towards the origin does not separate.
    const std::vector<Vec3> points = {
        {Real(28.0050468), Real(27.994957), Real(27.9898319)},  {Real(27.994957), Real(-27.9870796), Real(-21.8470459)},
        {Real(0.0240386482), Real(-21.8470459), Real(-27.9884357)}, {Real(-27.984869), Real(-27.994957), Real(-27.994957)},
        {Real(28.0045738), Real(27.994957), Real(27.994957)},   {Real(-27.984869), Real(-27.994957), Real(-27.994957)},
        {Real(-24.4106827), Real(-28.0024471), Real(-24.4817524)}};
    const Shape hull = Shape::convex(points);
    const Shape speck = Shape::box(Vec3::Constant(Real(0.000616979029)));
    Transform pose;
    pose.position = Vec3(-100, -100, -100);
    pose.rotation = Quat(Real(-0.5), Real(-0.5), Real(-0.5), Real(-0.5));
    const ConvexProxy a{&hull, pose}, b{&speck, pose};
    const GjkDistanceResult distance = gjkDistance(a, b);
    REQUIRE(distance.separated);
    CHECK(distance.distance == Approx(0.00704).margin(0.0002));
    CHECK_FALSE(gjkIntersect(a, b).intersect);
    CHECK_FALSE(gjkIntersect(b, a).intersect);
}
