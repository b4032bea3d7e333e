// The cases that break naive EPA: nested boxes, coplanar faces, crossing edges, extreme sizes,
// touching and invalid input. Every query must end as a contact with finite values or as an
// explicit "no contact"; never NaN, never a hang.
#include "03_epa/narrowphase.h"
#include "ch03/random_pairs.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace stepwise;
using stepwise::test::finiteQuery;
using stepwise::Random;

namespace {

/// Runs a box pair and checks it against the SAT oracle: depth to `relative` of the exact
/// depth (plus a few ulps of the size), normal a direction of least overlap, points on surfaces.
ContactQuery checkBoxes(const Vec3& halfA, const Transform& poseA, const Vec3& halfB, const Transform& poseB,
                        double relative = 1e-5) {
    const ContactQuery query = collideShapes(Shape::box(halfA), poseA, Shape::box(halfB), poseB);
    const oracle::SatResult sat =
        oracle::boxSat(oracle::makeOracleBox(halfA, poseA), oracle::makeOracleBox(halfB, poseB));
    const double size = halfA.norm() + halfB.norm();
    INFO("exact depth " << sat.depth << ", got " << query.depth << " via " << query.routine);
    REQUIRE(finiteQuery(query));
    REQUIRE(sat.overlap);
    CHECK(query.intersect);
    const double slack = relative * sat.depth + 64 * double(kEpsilon) * size;
    CHECK(std::abs(double(query.depth) - sat.depth) <= slack);
    const double along = test::boxOverlapAlong(query.normal, halfA, poseA, halfB, poseB);
    CHECK(std::abs(along - sat.depth) <= slack);
    CHECK(std::abs(test::boxSurfaceDistance(query.pointA, halfA, poseA)) <= 1e-4 * size);
    CHECK(std::abs(test::boxSurfaceDistance(query.pointB, halfB, poseB)) <= 1e-4 * size);
    CHECK((query.pointA - query.pointB - query.depth * query.normal).norm() <= Real(1e-4 * size));
    return query;
}

Transform at(const Vec3& position, const Quat& rotation = Quat::Identity()) {
    Transform transform;
    transform.position = position;
    transform.rotation = rotation;
    return transform;
}

Quat about(const Vec3& axis, Real angle) { return Quat(Eigen::AngleAxis<Real>(angle, axis.normalized())); }

}  // namespace

TEST_CASE("A box deep inside another leaves through the nearest face", "[ch03][epa][degenerate]") {
    const Vec3 big(2, Real(1.5), 1);
    const Vec3 small(Real(0.1), Real(0.2), Real(0.15));
    Random random(21u);
    for (int i = 0; i < 200; ++i) {
        const Vec3 inside(Real(random.uniform(-1.8, 1.8)), Real(random.uniform(-1.2, 1.2)), Real(random.uniform(-0.8, 0.8)));
        checkBoxes(big, at(Vec3::Zero()), small, at(inside, random.rotation()));
        checkBoxes(small, at(inside, random.rotation()), big, at(Vec3::Zero()));
    }
    // Dead centre, axis-aligned: the three face axes are far from tied, z wins.
    const ContactQuery centred = checkBoxes(big, at(Vec3::Zero()), small, at(Vec3::Zero()));
    CHECK(std::abs(centred.normal.z()) == Approx(1));
}

TEST_CASE("Identical coincident boxes: every axis ties", "[ch03][epa][degenerate]") {
    Random random(22u);
    for (int i = 0; i < 50; ++i) {
        const Transform pose = at(Vec3(Real(random.uniform(-5, 5)), 0, 0), random.rotation());
        const ContactQuery cube = checkBoxes(Vec3::Ones(), pose, Vec3::Ones(), pose);
        CHECK(cube.depth == Approx(2).epsilon(1e-5));
    }
}

TEST_CASE("Exactly aligned faces: a box resting into another with flush sides", "[ch03][epa][degenerate]") {
    // Same x and z extents, sides flush: A - B has whole faces through the polytope's points.
    for (Real overlap : {Real(0.5), Real(0.1), Real(1e-3)}) {
        const ContactQuery stacked =
            checkBoxes(Vec3(1, Real(0.5), 1), at(Vec3::Zero()), Vec3(1, Real(0.5), 1), at(Vec3(0, 1 - overlap, 0)), 1e-4);
        CHECK(stacked.normal.y() == Approx(1).epsilon(1e-5));
        CHECK(stacked.depth == Approx(overlap).epsilon(1e-3));
    }
    // A grid of aligned boxes at offsets that put faces, edges and corners exactly in line.
    for (int x = -2; x <= 2; ++x) {
        for (int y = -2; y <= 2; ++y) {
            for (int z = -1; z <= 1; ++z) {
                const Vec3 offset(Real(0.25) * x, Real(0.25) * y, Real(0.25) * z);
                checkBoxes(Vec3(Real(0.5), Real(0.5), Real(0.5)), at(Vec3::Zero()), Vec3(Real(0.25), Real(0.5), Real(0.25)),
                           at(offset), 1e-4);
            }
        }
    }
}

TEST_CASE("Crossing edges: boxes turned 45 degrees about perpendicular axes", "[ch03][epa][degenerate]") {
    const Quat alongX = about(Vec3::UnitX(), kPi / 4), alongZ = about(Vec3::UnitZ(), kPi / 4);
    for (Real gap : {Real(0.3), Real(0.05), Real(0.001)}) {
        // Edge of A along z on top, edge of B along x below: they cross, an edge-edge contact.
        const Real height = 2 * std::sqrt(Real(2)) * Real(0.5) - gap;
        const ContactQuery query =
            checkBoxes(Vec3::Constant(Real(0.5)), at(Vec3::Zero(), alongZ), Vec3::Constant(Real(0.5)),
                       at(Vec3(0, height, 0), alongX), 1e-4);
        CHECK(query.normal.y() == Approx(1).epsilon(1e-4));
        CHECK(query.depth == Approx(gap).epsilon(1e-3));
    }
}

TEST_CASE("Tiny and huge boxes keep their relative accuracy", "[ch03][epa][degenerate]") {
    Random random(23u);
    for (double scale : {1e-3, 1.0, 1e3}) {
        for (int i = 0; i < 100; ++i) {
            const Vec3 halfA = Real(scale) * Vec3(Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)));
            const Vec3 halfB = Real(scale) * Vec3(Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)));
            const Transform poseA = at(Real(scale) * Vec3(Real(random.uniform(-3, 3)), 0, 0), random.rotation());
            const Transform poseB = at(poseA.position + Real(random.uniform(0, 0.7) * scale) * random.unitVector(), random.rotation());
            checkBoxes(halfA, poseA, halfB, poseB, 1e-3);
        }
    }
    // A pebble on a slab 10^6 times larger.
    const Vec3 slab(1000, 1, 1000), pebble = Vec3::Constant(Real(1e-3));
    const ContactQuery query = checkBoxes(slab, at(Vec3(0, -1, 0)), pebble, at(Vec3(3, Real(0.0005), -7), about(Vec3::UnitY(), Real(0.3))), 1e-2);
    CHECK(query.normal.y() == Approx(1).epsilon(1e-4));
}

TEST_CASE("Touching and nearly touching boxes give a defined, tiny answer", "[ch03][epa][degenerate]") {
    for (Real gap : {Real(0), Real(1e-7), Real(-1e-7), Real(1e-5), Real(-1e-5)}) {
        const ContactQuery query =
            collideShapes(Shape::box(Vec3::Ones()), at(Vec3::Zero()), Shape::box(Vec3::Ones()), at(Vec3(Real(0.3), 2 + gap, 0)));
        INFO("gap " << gap << " depth " << query.depth);
        REQUIRE(finiteQuery(query));
        CHECK(std::abs(query.depth + gap) <= Real(2e-5));
        if (query.intersect) CHECK(query.normal.y() == Approx(1).epsilon(1e-3));
    }
}

TEST_CASE("Invalid input is an explicit no-contact, never NaN", "[ch03][epa][degenerate]") {
    const Real nan = std::numeric_limits<Real>::quiet_NaN(), inf = std::numeric_limits<Real>::infinity();
    const Shape box = Shape::box(Vec3::Ones());
    const Transform origin;
    const auto expectInvalid = [](const ContactQuery& query) {
        CHECK_FALSE(query.intersect);
        CHECK(std::string(query.routine) == "invalid");
        CHECK(isFinite(query.depth));
        CHECK(isFinite(query.normal));
    };
    expectInvalid(collideShapes(box, at(Vec3(nan, 0, 0)), box, origin));
    expectInvalid(collideShapes(box, origin, box, at(Vec3(0, inf, 0))));
    Transform badRotation;
    badRotation.rotation = Quat(nan, 0, 0, 1);
    expectInvalid(collideShapes(box, badRotation, box, origin));
    expectInvalid(collideShapes(Shape::box(Vec3(1, 0, 1)), origin, box, origin));
    expectInvalid(collideShapes(Shape::sphere(-1), origin, box, origin));
    expectInvalid(collideShapes(Shape::sphere(nan), origin, Shape::sphere(1), origin));
    Shape hullless;
    hullless.type = ShapeType::Convex;
    expectInvalid(collideShapes(hullless, origin, box, origin));
}

TEST_CASE("Random nasty poses: right-angle turns, flush offsets, mixed sizes", "[ch03][epa][degenerate]") {
    // Rotations by multiples of 90 degrees and offsets on a coarse grid put many support points
    // exactly on shared planes and lines: coplanar faces, repeated points, zero-area triangles.
    Random random(24u);
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const auto quarterTurns = [&] {
            return (about(Vec3::UnitX(), Real(kPi / 2 * int(random.uniform(0, 4)))) *
                    about(Vec3::UnitY(), Real(kPi / 2 * int(random.uniform(0, 4))))).normalized();
        };
        const auto gridSize = [&] { return Real(0.25 * (1 + int(random.uniform(0, 4)))); };
        const Vec3 halfA(gridSize(), gridSize(), gridSize()), halfB(gridSize(), gridSize(), gridSize());
        const Vec3 offset(Real(0.125 * int(random.uniform(-8, 9))), Real(0.125 * int(random.uniform(-8, 9))),
                          Real(0.125 * int(random.uniform(-8, 9))));
        const Transform poseA = at(Vec3::Zero(), quarterTurns()), poseB = at(offset, quarterTurns());
        const oracle::SatResult sat = oracle::boxSat(oracle::makeOracleBox(halfA, poseA), oracle::makeOracleBox(halfB, poseB));
        if (!sat.overlap || sat.depth < 1e-3) {
            const ContactQuery query = collideShapes(Shape::box(halfA), poseA, Shape::box(halfB), poseB);
            CHECK(finiteQuery(query));
            continue;
        }
        const ContactQuery query = checkBoxes(halfA, poseA, halfB, poseB, 1e-4);
        CHECK(query.epaIterations <= EpaSettings{}.maxIterations);
        ++checked;
    }
    CHECK(checked > 500);
}

TEST_CASE("a sphere grazing a hull reads as touching, with the points where they touch", "[ch03][epa]") {
    // Found in the settling pile of the engine bench: GJK sees the pair touch, no tetrahedron can
    // be built around the origin, and the fallback's directions missed the true normal: 7.8 cm deep.
    const std::vector<Vec3> corners = {Vec3(0, Real(0.5), 0),     Vec3(0, 0, Real(0.35)),  Vec3(Real(0.35), 0, 0),
                                       Vec3(0, 0, Real(-0.35)),   Vec3(0, Real(-0.5), 0),  Vec3(Real(-0.35), 0, 0)};
    const Shape hull = Shape::convex(corners);
    const Transform hullPose{Vec3(Real(5.39495707), Real(1.1857748), Real(0.235774994)),
                             Quat(Real(-0.549575627), Real(0.541845202), Real(0.210488096), Real(-0.600054264)).normalized()};
    const Transform spherePose{Vec3(Real(5.93552208), Real(1.72309566), Real(0.564188659)), Quat::Identity()};
    const ContactQuery query = collideShapes(hull, hullPose, Shape::sphere(Real(0.5)), spherePose);
    REQUIRE(finiteQuery(query));
    // The sphere's centre is its radius from the hull (to the float's precision of GJK's distance).
    const ContactQuery centre = collideShapes(hull, hullPose, Shape::sphere(Real(1e-3)), spherePose);
    const Real trueDepth = Real(0.5) - (-centre.depth + Real(1e-3));
    INFO("depth " << query.depth << ", the centre says " << trueDepth);
    CHECK(std::abs(query.depth - std::max(trueDepth, Real(0))) < Real(1e-3));
    CHECK((query.pointA - query.pointB).norm() < Real(1e-3));
    CHECK(std::abs((query.pointB - spherePose.position).norm() - Real(0.5)) < Real(1e-3));
}

namespace {

/// The least reach of A - B over all directions, in double: the depth of an overlapping hull and
/// box (the box in the hull's frame, axis-aligned). A - B is a polytope whose face normals are
/// A's face normals, B's and the cross products of an edge of each; every plane through three
/// corners of A and every line through two of them times B's axes covers those, and any extra
/// direction only adds an upper bound, so the least reach over the list is exact.
double leastReach(const std::vector<Eigen::Vector3d>& cornersA, const std::vector<Eigen::Vector3d>& cornersB) {
    const auto reach = [&](const Eigen::Vector3d& d) {
        double far = -1e300, near = 1e300;
        for (const Eigen::Vector3d& p : cornersA) far = std::max(far, p.dot(d));
        for (const Eigen::Vector3d& p : cornersB) near = std::min(near, p.dot(d));
        return far - near;
    };
    double best = 1e300;
    const auto tryAxis = [&](const Eigen::Vector3d& axis) {
        if (axis.norm() < 1e-12) return;
        best = std::min({best, reach(axis.normalized()), reach(-axis.normalized())});
    };
    const std::size_t n = cornersA.size();
    for (int k = 0; k < 3; ++k) tryAxis(Eigen::Vector3d::Unit(k));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            for (int k = 0; k < 3; ++k) tryAxis((cornersA[j] - cornersA[i]).cross(Eigen::Vector3d::Unit(k)));
            for (std::size_t l = j + 1; l < n; ++l) tryAxis((cornersA[j] - cornersA[i]).cross(cornersA[l] - cornersA[i]));
        }
    return best;
}

}  // namespace

TEST_CASE("a needle hull through a small box: GJK's thin tetrahedron still holds the origin", "[ch03][epa][degenerate]") {
    // Found by fuzz_narrowphase: a hull 27 m long and 25 cm across, a 5.8 cm box at its origin,
    // 3.4 cm outside the hull, overlapping it by 2.27 mm. GJK's tetrahedron around the origin is
    // thin (its volume 21 rounding errors of the product of its edges) but every sign is clear;
    // called flat, it gave GJK a face 1 mm from the origin until the loop stalled, EPA found no
    // tetrahedron and the pair read as only touching, with A's point 3 mm inside A.
    const std::vector<Vec3> corners = {
        {Real(-0.000736827089), Real(-5.75346088), Real(-0.08875072)},  {Real(0.0641665459), Real(-2.68687224), Real(-0.0800795928)},
        {Real(-0.0703765601), Real(13.4911318), Real(0.112587079)},     {Real(-0.109548934), Real(-12.0477695), Real(-0.128036723)},
        {Real(-0.120633371), Real(1.09669828), Real(-0.0210574754)},    {Real(-0.118872635), Real(11.3152866), Real(-0.126456454)},
        {Real(-0.143792897), Real(-13.554575), Real(-0.143792897)},     {Real(-0.0769545436), Real(10.5140896), Real(-0.0912454948)}};
    const Real half = Real(0.0290673971);
    const Transform pose{Vec3(-100, -100, -100), Quat(Real(-0.5), Real(-0.5), Real(-0.5), Real(-0.5))};
    const Shape needle = Shape::convex(corners);
    const ContactQuery query = collideShapes(needle, pose, Shape::box(Vec3::Constant(half)), pose);
    REQUIRE(finiteQuery(query));
    // Both shapes share one pose, so the truth can be found in that pose's frame.
    std::vector<Eigen::Vector3d> cornersA, cornersB;
    for (const Vec3& corner : corners) cornersA.push_back(corner.cast<double>());
    for (int i = 0; i < 8; ++i) cornersB.emplace_back(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half);
    const double trueDepth = leastReach(cornersA, cornersB);
    INFO("depth " << query.depth << " via " << query.routine << ", true depth " << trueDepth);
    REQUIRE(trueDepth > 2e-3);
    CHECK(query.intersect);
    CHECK(std::abs(double(query.depth) - trueDepth) < 2e-5);
    // The points on the surfaces: A's inside every face plane and on one, B's on the box.
    const Vec3 localA = pose.applyInverse(query.pointA);
    double outsideA = -1e300;
    for (const HullFace& face : needle.hull->faces) outsideA = std::max(outsideA, double(face.normal.dot(localA) - face.offset));
    CHECK(std::abs(outsideA) < 1e-4);
    CHECK(std::abs(test::boxSurfaceDistance(query.pointB, Vec3::Constant(half), pose)) < 1e-4);
}
