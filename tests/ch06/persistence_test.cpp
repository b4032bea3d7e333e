// Chapter 6's persistence: feature ids that survive a small motion, matching that carries the
// impulses (by id, then by anchor distance), the life cycle of a pair's record, and the stage in a
// running pipeline (chapter 5's, with updateManifolds as its narrowphase).
#include "ch06/manifold_fixture.h"
#include "05_sap/chapter.h"
#include "06_manifolds/manifold.h"
#include "06_manifolds/persistence.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace stepwise;
using namespace stepwise::test;

namespace {

std::vector<std::uint32_t> sortedIds(const Contact& contact) {
    std::vector<std::uint32_t> ids;
    for (int i = 0; i < contact.pointCount; ++i) ids.push_back(contact.points[i].featureId);
    std::sort(ids.begin(), ids.end());
    return ids;
}

struct Configuration {
    const char* name;
    Shape shapeA;
    Transform ta;
    Shape shapeB;
    Transform tb;
    int points;
};

std::vector<Configuration> configurations() {
    const Real lift = Real(0.25) + Real(0.5) * std::sqrt(Real(2)) - Real(0.01);
    const Real reach = Real(0.5) * std::sqrt(Real(2));
    return {
        {"face-face, on the slab", kSlab, pose(Vec3::Zero()), kUnitBox,
         pose(Vec3(Real(0.1), Real(0.74), Real(-0.05)), axisAngle(Vec3::UnitY(), 20)), 4},
        {"face-face, over a corner (crossings)", kSlab, pose(Vec3::Zero()), kUnitBox,
         pose(Vec3(Real(0.85), Real(0.74), Real(0.6)), axisAngle(Vec3::UnitY(), 30)), 4},
        {"edge-face", kSlab, pose(Vec3::Zero()), kUnitBox,
         pose(Vec3(Real(0.1), lift, Real(0.05)), axisAngle(Vec3::UnitZ(), 45)), 2},
        {"edge-face over the rim", kSlab, pose(Vec3::Zero()), kUnitBox,
         pose(Vec3(0, lift, Real(0.55)), axisAngle(Vec3::UnitY(), 15) * axisAngle(Vec3::UnitX(), 45)), 2},
        {"edge-edge", kUnitBox, pose(Vec3::Zero(), axisAngle(Vec3::UnitZ(), 45)), kUnitBox,
         pose(Vec3(Real(0.05), 2 * reach - Real(0.01), Real(-0.03)), axisAngle(Vec3::UnitX(), 45)), 1},
        {"capsule on the slab", kSlab, pose(Vec3::Zero()), Shape::capsule(Real(0.2), Real(0.5)),
         pose(Vec3(Real(0.1), Real(0.44), 0), axisAngle(Vec3::UnitZ(), 90)), 2},
    };
}

}  // namespace

// [ch06-test-ids-survive]
TEST_CASE("feature ids survive a small motion: 1 mm and 0.5 degrees give the same ids", "[ch06][persistence]") {
    const Vec3 moves[] = {Vec3(Real(0.001), 0, 0), Vec3(0, 0, Real(-0.001)), Vec3(0, Real(0.001), 0),
                          Vec3(Real(-0.0007), Real(-0.0005), Real(0.0005))};
    const Vec3 axes[] = {Vec3::UnitY(), Vec3::UnitX(), Vec3::UnitZ(), Vec3(1, 1, 1), Vec3(-1, 2, 0)};
    // Half a degree tilts a 1 m face by 9 mm: corners that rise keep their ids as speculative
    // points within a once-per-frame search's margin.
    const Real kKeep = Real(0.02);
    for (const Configuration& configuration : configurations()) {
        INFO(configuration.name);
        Contact before;
        REQUIRE(collideManifold(configuration.shapeA, configuration.ta, configuration.shapeB, configuration.tb, kKeep, before));
        REQUIRE(before.pointCount == configuration.points);
        const std::vector<std::uint32_t> ids = sortedIds(before);
        REQUIRE(std::adjacent_find(ids.begin(), ids.end()) == ids.end());  // distinct
        REQUIRE(std::find(ids.begin(), ids.end(), 0u) == ids.end());       // all known
        for (const Vec3& move : moves) {
            for (const Vec3& axis : axes) {
                for (double degrees : {0.5, -0.5}) {
                    Transform moved = configuration.tb;
                    moved.position += move;
                    moved.rotation = axisAngle(axis, degrees) * moved.rotation;
                    Contact after;
                    INFO("move " << move.transpose() << ", turn " << degrees << " about " << axis.transpose());
                    // As the stage does: last step's record holds the reference face.
                    REQUIRE(collideManifold(configuration.shapeA, configuration.ta, configuration.shapeB, moved, kKeep,
                                            after, ManifoldOptions{}, &before));
                    CHECK(sortedIds(after) == ids);
                }
            }
        }
    }
}
// [ch06-test-ids-survive]

TEST_CASE("matching carries the impulses, friction re-expressed in the new tangent basis", "[ch06][persistence]") {
    Contact before;
    REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), kUnitBox, pose(Vec3(Real(0.1), Real(0.74), 0), axisAngle(Vec3::UnitY(), 20)), 0, before));
    REQUIRE(before.pointCount == 4);
    Vec3 oldT1, oldT2;
    tangentBasis(before.normal, oldT1, oldT2);
    for (int i = 0; i < before.pointCount; ++i) {
        before.points[i].normalImpulse = Real(1 + i);
        before.points[i].tangentImpulse[0] = Real(0.5) * Real(i);
        before.points[i].tangentImpulse[1] = Real(-0.25);
    }
    // Both bodies turn by 3 degrees about z: the normal turns with them, the same corners touch.
    const Quat turn = axisAngle(Vec3::UnitZ(), 3);
    Contact after;
    REQUIRE(collideManifold(kSlab, pose(Vec3::Zero(), turn), kUnitBox,
                            pose(turn * Vec3(Real(0.1), Real(0.74), 0), turn * axisAngle(Vec3::UnitY(), 20)), 0, after));
    REQUIRE((after.normal - before.normal).norm() > Real(0.04));
    REQUIRE(matchContactPoints(after, before, Real(0.01)) == 4);
    Vec3 newT1, newT2;
    tangentBasis(after.normal, newT1, newT2);
    for (int i = 0; i < after.pointCount; ++i) {
        const ContactPoint& point = after.points[i];
        int k = 0;
        while (before.points[k].featureId != point.featureId) ++k;
        CHECK(point.persisted);
        CHECK(point.normalImpulse == before.points[k].normalImpulse);
        // The friction vector, turned with the bodies, is the same vector in the bodies' frame.
        const Vec3 oldFriction = before.points[k].tangentImpulse[0] * oldT1 + before.points[k].tangentImpulse[1] * oldT2;
        const Vec3 newFriction = point.tangentImpulse[0] * newT1 + point.tangentImpulse[1] * newT2;
        // Only the part of the old friction that lies in the new contact plane survives.
        const Vec3 expected = oldFriction - after.normal.dot(oldFriction) * after.normal;
        CHECK((newFriction - expected).norm() < 1e-5);
    }
}

TEST_CASE("matching falls back to the anchor distance when the ids differ", "[ch06][persistence]") {
    Contact before;
    REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), kUnitBox, pose(Vec3(0, Real(0.74), 0)), 0, before));
    REQUIRE(before.pointCount == 4);
    for (int i = 0; i < 4; ++i) {
        before.points[i].normalImpulse = Real(10 + i);
        before.points[i].featureId = makeFeatureId(makeFeature(FeatureKind::Core, 100 + static_cast<std::uint32_t>(i)), 0);  // ids no new point has
    }
    SECTION("a 5 mm slide: the same points, by distance") {
        Contact after;
        REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), kUnitBox, pose(Vec3(Real(0.005), Real(0.74), 0)), 0, after));
        CHECK(matchContactPoints(after, before, Real(0.01)) == 4);
        for (int i = 0; i < 4; ++i) {
            CHECK(after.points[i].persisted);
            // Each point took the impulse of the old point nearest to it on B (its corner).
            int nearest = 0;
            for (int k = 1; k < 4; ++k)
                if ((before.points[k].localAnchorB - after.points[i].localAnchorB).norm() <
                    (before.points[nearest].localAnchorB - after.points[i].localAnchorB).norm())
                    nearest = k;
            CHECK(after.points[i].normalImpulse == before.points[nearest].normalImpulse);
        }
    }
    SECTION("matched points come back in the slots of the points they continue") {
        Contact after;
        REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), kUnitBox, pose(Vec3(Real(0.002), Real(0.74), 0)), 0, after));
        std::reverse(after.points, after.points + after.pointCount);  // as a new tilt might order them
        REQUIRE(matchContactPoints(after, before, Real(0.01)) == 4);
        for (int i = 0; i < 4; ++i) {
            CHECK(after.points[i].normalImpulse == before.points[i].normalImpulse);
            CHECK((after.points[i].localAnchorB - before.points[i].localAnchorB).norm() < 0.005);
        }
    }
    SECTION("a 2 cm slide: too far on A's face, nothing carried") {
        Contact after;
        REQUIRE(collideManifold(kSlab, pose(Vec3::Zero()), kUnitBox, pose(Vec3(Real(0.02), Real(0.74), 0)), 0, after));
        CHECK(matchContactPoints(after, before, Real(0.01)) == 0);
        for (int i = 0; i < 4; ++i) {
            CHECK_FALSE(after.points[i].persisted);
            CHECK(after.points[i].normalImpulse == 0);
        }
    }
}

namespace {

World boxOnGround(Real overlap) {
    World world = test::makeWorld();
    test::addGround(world);
    test::addBox(world, Vec3(0, Real(0.5) - overlap, 0), Vec3(Real(0.5), Real(0.5), Real(0.5)));
    world.candidatePairs = {BodyPair{0, 1}};
    return world;
}

}  // namespace

TEST_CASE("a box resting exactly on the ground is a contact, moving or not, and one two slops above is not",
          "[ch06][persistence]") {
    for (const Real gap : {Real(0), Real(0.002)}) {
        World world = boxOnGround(-gap);
        updateManifolds(world, 0);
        INFO("gap " << gap);
        REQUIRE(world.contacts.size() == 1);
        CHECK(world.contacts[0].pointCount == 4);
    }
    World above = boxOnGround(-2 * test::makeWorld().settings.slop);
    updateManifolds(above, 0);
    CHECK(above.contacts.empty());
}

TEST_CASE("the record's life cycle: kept a few searches while the bounds overlap, then dropped", "[ch06][persistence]") {
    World world = boxOnGround(Real(0.01));
    ManifoldOptions options;
    REQUIRE(updateManifolds(world, 0, options) == 1);
    REQUIRE(world.contacts.size() == 1);
    REQUIRE(world.contacts[0].pointCount == 4);
    REQUIRE(world.pairs.size() == 1);
    for (int i = 0; i < 4; ++i) {
        CHECK_FALSE(world.contacts[0].points[i].persisted);
        world.contacts[0].points[i].normalImpulse = Real(2.5);
    }
    updateManifolds(world, 0, options);
    REQUIRE(world.contacts.size() == 1);
    for (int i = 0; i < 4; ++i) {
        CHECK(world.contacts[0].points[i].persisted);
        CHECK(world.contacts[0].points[i].normalImpulse == Real(2.5));
    }

    SECTION("out of reach, still a candidate: kept keepSteps searches, riding on the bodies, then dropped") {
        world.bodies[1].transform.position.y() += Real(0.05);
        for (int search = 1; search <= options.keepSteps; ++search) {
            updateManifolds(world, 0, options);
            REQUIRE(world.contacts.size() == 1);
            CHECK(world.pairs.empty());
            CHECK(world.contacts[0].missedSteps == search);
            CHECK(world.contacts[0].points[0].depth == Approx(-0.04).margin(1e-5));
            CHECK(world.contacts[0].points[0].normalImpulse == Real(2.5));
        }
        updateManifolds(world, 0, options);
        CHECK(world.contacts.empty());
    }
    SECTION("back in reach within keepSteps: the same points, with what they carried") {
        world.bodies[1].transform.position.y() += Real(0.05);
        updateManifolds(world, 0, options);
        world.bodies[1].transform.position.y() -= Real(0.05);
        updateManifolds(world, 0, options);
        REQUIRE(world.contacts.size() == 1);
        CHECK(world.contacts[0].missedSteps == 0);
        for (int i = 0; i < 4; ++i) CHECK(world.contacts[0].points[i].normalImpulse == Real(2.5));
    }
    SECTION("no longer a candidate: dropped at once") {
        world.candidatePairs.clear();
        updateManifolds(world, 0, options);
        CHECK(world.contacts.empty());
    }
    SECTION("a broken pose: dropped, no crash") {
        world.bodies[1].transform.position.x() = std::numeric_limits<Real>::quiet_NaN();
        updateManifolds(world, 0, options);
        CHECK(world.contacts.empty());
        CHECK(world.pairs.empty());
    }
    SECTION("keepSteps 0: dropped at the first miss") {
        options.keepSteps = 0;
        world.bodies[1].transform.position.y() += Real(0.05);
        updateManifolds(world, 0, options);
        CHECK(world.contacts.empty());
    }
}

TEST_CASE("counts and labels: what the demo and the bench show", "[ch06][persistence]") {
    World world = boxOnGround(Real(0.01));
    updateManifolds(world, 0);
    ManifoldStats stats = countManifolds(world);
    CHECK(stats.contacts == 1);
    CHECK(stats.points == 4);
    CHECK(stats.persistedPoints == 0);
    updateManifolds(world, 0);
    stats = countManifolds(world);
    CHECK(stats.persistedPoints == 4);
    CHECK(stats.speculativePoints == 0);
    world.bodies[1].transform.position.y() += Real(0.05);
    updateManifolds(world, 0);
    stats = countManifolds(world);
    CHECK(stats.keptRecords == 1);
    CHECK(stats.speculativePoints == 4);
    // The ground's top face (3) against the box's corner 5 (x > 0, z > 0, y < 0: bits 1 and 4).
    CHECK(featureIdLabel(makeFeatureId(makeFeature(FeatureKind::Face, 3), makeFeature(FeatureKind::Vertex, 5))) == "f3/v5");
    CHECK(featureIdLabel(makeFeatureId(makeFeature(FeatureKind::Edge, 2 * 128 + 6), 0)) == "e2-6/?");
    const std::string label = featureIdLabel(world.contacts[0].points[0].featureId);
    CHECK(label.substr(0, 3) == "f3/");
}

TEST_CASE("a falling box gets speculative points before it lands", "[ch06][persistence]") {
    World world = boxOnGround(Real(-0.02));  // 2 cm above the ground
    world.settings.substeps = 4;
    test::setVelocity(world, 1, Vec3(0, -3, 0));
    updateManifolds(world, 0);
    CHECK(world.contacts.empty());  // every substep searched: nothing yet
    updateManifolds(world, 3);      // once per frame, 3 substeps ahead: 3 m/s covers 3.75 cm
    REQUIRE(world.contacts.size() == 1);
    CHECK(world.pairs.empty());
    REQUIRE(world.contacts[0].pointCount == 4);
    for (int i = 0; i < 4; ++i) CHECK(world.contacts[0].points[i].depth == Approx(-0.02).margin(1e-5));
}

namespace {

/// Chapter 5's pipeline with updateManifolds as its narrowphase, and without chapter 4's drop rule
/// (the record's life cycle replaces it).
Pipeline manifoldPipeline(const World& world, const ManifoldOptions& options) {
    Pipeline pipeline = makeChapter05Pipeline(world, StepOrder::SplitIntegration, ContactSearch::EverySubstep);
    pipeline.find(stage_group::kNarrowphase)->run = [options](World& stepWorld, Real) {
        updateManifolds(stepWorld, 0, options);
    };
    pipeline.remove(stageName(stage_group::kContacts, "drop_unloaded"));
    return pipeline;
}

}  // namespace

TEST_CASE("in a pipeline: a box dropped on the ground settles flat on four persistent points", "[ch06][persistence]") {
    World world = test::makeWorld();
    test::addGround(world);
    const int box = test::addBox(world, Vec3(0, Real(0.7), 0), Vec3(Real(0.5), Real(0.5), Real(0.5)), BodyType::Dynamic,
                                 axisAngle(Vec3(1, 0, 1), 4));
    Pipeline pipeline = manifoldPipeline(world, ManifoldOptions{});
    test::simulate(world, pipeline, 2.0);
    REQUIRE(world.contacts.size() == 1);
    const Contact& contact = world.contacts[0];
    CHECK(contact.pointCount == 4);
    for (int i = 0; i < contact.pointCount; ++i) CHECK(contact.points[i].persisted);
    const Quat rotation = world.bodies[static_cast<std::size_t>(box)].transform.rotation;
    const Real tilt = std::acos(std::min(Real(1), std::abs((rotation * Vec3::UnitY()).y())));
    // Resting on four points whose depths Baumgarte leaves anywhere within the slop, a 1 m box may
    // lean by up to slop / 1 m.
    CHECK(tilt < world.settings.slop);
    CHECK(world.motionOf(box)->angularVelocity.norm() < Real(0.01));
    const Vec3 position = world.bodies[static_cast<std::size_t>(box)].transform.position;
    CHECK(position.y() == Approx(0.5).margin(0.01));
    CHECK(world.motionOf(box)->linearVelocity.norm() < Real(0.01));
}
