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
