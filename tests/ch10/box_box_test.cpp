// Chapter 10's box-box query: the fifteen separating axes give chapter 3's answer (GJK and EPA)
// for overlapping boxes, a lower bound of the gap for separated ones, and chapter 6 builds the
// same manifolds from either.
#include "06_manifolds/manifold.h"
#include "10_skip_work/box_box.h"
#include "10_skip_work/chapter.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace stepwise;

namespace {

/// A box of random size (5 cm to 1 m half extents) at a random pose within `spread` of the origin.
struct RandomBoxes {
    std::mt19937 random{20261126u};
    std::uniform_real_distribution<double> unit{-1.0, 1.0};

    Shape shape() {
        return Shape::box(Vec3(Real(0.05 + 0.475 * (1 + unit(random))), Real(0.05 + 0.475 * (1 + unit(random))),
                               Real(0.05 + 0.475 * (1 + unit(random)))));
    }
    Transform pose(double spread) {
        Quat turn(Real(unit(random)), Real(unit(random)), Real(unit(random)), Real(unit(random)));
        if (turn.norm() < Real(1e-3)) turn = Quat::Identity();
        return Transform{Vec3(Real(spread * unit(random)), Real(spread * unit(random)), Real(spread * unit(random))),
                         turn.normalized()};
    }
};

}  // namespace

TEST_CASE("box-box by separating axes: the depth and normal EPA finds, for overlapping boxes", "[ch10][narrowphase]") {
    RandomBoxes boxes;
    int overlapping = 0, sameNormal = 0, separated = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const Shape a = boxes.shape(), b = boxes.shape();
        const Transform ta = boxes.pose(0.2), tb = boxes.pose(1.2);
        const ContactQuery sat = boxBoxQuery(a, ta, b, tb);
        const ContactQuery reference = collideShapes(a, ta, b, tb);
        INFO("trial " << trial << ": sat depth " << sat.depth << ", reference " << reference.depth);
        REQUIRE(std::string(sat.routine) == "box_box_sat");
        CHECK(std::abs(sat.normal.norm() - 1) < Real(1e-4));
        if (reference.intersect) {
            // Overlapping, the witnesses are one depth apart along the normal (apart, they are only
            // the supporting features' nearest points, which chapter 6 does not use).
            CHECK((sat.pointA - sat.pointB - sat.depth * sat.normal).norm() < Real(1e-3));
            ++overlapping;
            CHECK(sat.intersect);
            CHECK(std::abs(sat.depth - reference.depth) < Real(1e-4) * (1 + reference.depth));
            // Two axes may overlap by the same depth; then either normal is right.
            if (sat.normal.dot(reference.normal) > Real(0.999)) ++sameNormal;
        } else {
            ++separated;
            CHECK(!sat.intersect);
            // The largest separation on any axis is at most the distance (equal when a face separates).
            CHECK(-sat.depth <= -reference.depth + Real(1e-4));
        }
    }
    CHECK(overlapping > 200);
    CHECK(separated > 200);
    CHECK(sameNormal >= overlapping * 95 / 100);
}

TEST_CASE("box-box by separating axes: chapter 6 builds the same manifolds from it", "[ch10][narrowphase]") {
    const Shape unit = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
    const Shape slab = Shape::box(Vec3(3, Real(0.25), 3));
    struct Case {
        const char* name;
        Transform ta, tb;
        int points;
    };
    const Quat tilt(Eigen::AngleAxis<Real>(Real(0.3), Vec3(1, 0, 1).normalized()));
    const Quat crossed(Eigen::AngleAxis<Real>(Real(M_PI / 4), Vec3::UnitX()));
    const Quat crossedOther(Eigen::AngleAxis<Real>(Real(M_PI / 4), Vec3::UnitZ()));
    // The tilted box's lowest corner 1 cm into the slab's top (y = 0.25).
    const Mat3 tiltAxes = tilt.toRotationMatrix();
    const Real tiltReach = Real(0.5) * (std::abs(tiltAxes(1, 0)) + std::abs(tiltAxes(1, 1)) + std::abs(tiltAxes(1, 2)));
    const Case cases[] = {
        {"resting face on face", Transform{Vec3(0, 0, 0), Quat::Identity()}, Transform{Vec3(0, Real(0.74), 0), Quat::Identity()}, 4},
        {"a corner in the slab", Transform{Vec3(0, 0, 0), Quat::Identity()}, Transform{Vec3(0, Real(0.24) + tiltReach, 0), tilt}, 1},
        {"two edges crossed", Transform{Vec3(0, 0, 0), crossed}, Transform{Vec3(0, Real(1.4), 0), crossedOther}, 1},
        {"a hair apart, within the margin", Transform{Vec3(0, 0, 0), Quat::Identity()}, Transform{Vec3(0, Real(0.752), 0), Quat::Identity()}, 4},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const Shape& a = c.points == 4 || std::string(c.name) == "a corner in the slab" ? slab : unit;
        const Real keep = Real(0.01);
        Contact fromSat, fromReference;
        ManifoldOptions options;
        REQUIRE(buildManifold(a, c.ta, unit, c.tb, boxBoxQuery(a, c.ta, unit, c.tb), keep, options, fromSat, nullptr));
        REQUIRE(buildManifold(a, c.ta, unit, c.tb, collideShapes(a, c.ta, unit, c.tb), keep, options, fromReference, nullptr));
        CHECK(fromSat.pointCount == c.points);
        REQUIRE(fromSat.pointCount == fromReference.pointCount);
        CHECK(fromSat.normal.dot(fromReference.normal) > Real(0.9999));
        for (int i = 0; i < fromSat.pointCount; ++i) {
            CHECK(fromSat.points[i].featureId == fromReference.points[i].featureId);
            CHECK(std::abs(fromSat.points[i].depth - fromReference.points[i].depth) < Real(1e-5));
            CHECK((fromSat.points[i].pointA - fromReference.points[i].pointA).norm() < Real(1e-5));
        }
    }
}

TEST_CASE("box-box by separating axes: a broken box gets chapter 3's refusal", "[ch10][narrowphase]") {
    const Shape good = Shape::box(Vec3(Real(0.5), Real(0.5), Real(0.5)));
    Shape flat = good;
    flat.halfExtents.y() = 0;
    const Transform here{Vec3::Zero(), Quat::Identity()};
    CHECK(std::string(boxBoxQuery(flat, here, good, here).routine) == std::string(collideShapes(flat, here, good, here).routine));
    const Transform nowhere{Vec3(std::nan(""), 0, 0), Quat::Identity()};
    CHECK(std::string(boxBoxQuery(good, nowhere, good, here).routine) ==
          std::string(collideShapes(good, nowhere, good, here).routine));
}

TEST_CASE("chapter 10's narrowphase gives a pile the same contacts with the box-box query as without", "[ch10][narrowphase]") {
    // Ten boxes dropped in a heap: after a second, the two runs' contacts agree pair for pair
    // within round-off (the queries differ in their last bits, the manifolds they lead to do not).
    std::string bodies = R"({"name": "ground", "type": "static", "shape": {"box": {"half_extents": [10, 0.5, 10]}}, "position": [0, -0.5, 0]})";
    for (int i = 0; i < 10; ++i)
        bodies += R"(, {"name": "box)" + std::to_string(i) + R"(", "shape": {"box": {"half_extents": [0.3, 0.2, 0.4]}}, "position": [)" +
                  std::to_string(0.1 * (i % 3)) + ", " + std::to_string(0.5 + 0.45 * i) + ", " + std::to_string(0.07 * (i % 4)) +
                  R"(], "orientation": [0, )" + std::to_string(std::sin(0.05 * i)) + ", 0, " + std::to_string(std::cos(0.05 * i)) + "]}";
    const World scene = loadSceneFromString(R"({"name": "heap", "bodies": [)" + bodies + "]}");
    World fast = scene, general = scene;
    SkipWorkOptions withSat, without;
    without.boxBoxQuery = false;
    Pipeline fastPipeline = makeChapter10Pipeline(fast, withSat), generalPipeline = makeChapter10Pipeline(general, without);
    for (int frame = 0; frame < 60; ++frame) {
        fastPipeline.step(fast);
        generalPipeline.step(general);
    }
    REQUIRE(fast.contacts.size() == general.contacts.size());
    Real worstPose = 0;
    for (std::size_t i = 0; i < fast.bodies.size(); ++i)
        worstPose = std::max(worstPose, (fast.bodies[i].transform.position - general.bodies[i].transform.position).norm());
    INFO("largest difference of a box's position: " << worstPose << " m");
    CHECK(worstPose < Real(0.01));
}
