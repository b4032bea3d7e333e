// Chapter 10's contact cache carries a face contact of two boxes that slid along the face
// (faceContactSlides): the block sliding down the reference ramp keeps its manifold instead of
// building it every frame, and ends where it ends when every frame builds it; a block whose corner
// nears the edge of what it slides on is built again. A carried record's points follow their
// bodies four at a time with chapter 3's bits.
#include "03_epa/chapter.h"
#include "10_skip_work/chapter.h"
#include "10_skip_work/contact_cache.h"
#include "10_skip_work/follow_corners.h"
#include "math/random.h"
#include "math/same_bits.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

namespace {

int bodyNamed(const World& world, const std::string& name) {
    for (std::size_t i = 0; i < world.bodies.size(); ++i)
        if (world.bodies[i].name == name) return static_cast<int>(i);
    return -1;
}

/// A 1 m box standing on a 4 m slab.
World boxOnSlab() {
    return loadSceneFromString(R"({
      "format": "stepwise-scene", "version": 1, "name": "slab",
      "bodies": [
        {"name": "slab", "type": "static", "shape": {"box": {"half_extents": [2, 0.5, 2]}}, "position": [0, -0.5, 0]},
        {"name": "box", "shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, 0.5, 0], "mass": 1}
      ]})");
}

}  // namespace

TEST_CASE("a block sliding down a ramp keeps its manifold and slides as when it is built every frame", "[ch10][cache]") {
    const World start = loadSceneFile("scenes/reference/ramp.json");
    World cached = start, built = start;
    SkipWorkOptions everyFrame;
    everyFrame.contactCache.enabled = false;
    Pipeline cachedPipeline = makeChapter10Pipeline(cached, SkipWorkOptions{});
    Pipeline builtPipeline = makeChapter10Pipeline(built, everyFrame);
    int rebuiltFrames = 0;
    for (int frame = 0; frame < 60; ++frame) {
        cachedPipeline.step(cached);
        builtPipeline.step(built);
        if (frame > 2 && cached.step.manifoldsRebuilt > 0) ++rebuiltFrames;
    }
    const int slides = bodyNamed(start, "block_slides");
    const Vec3 travelled = cached.bodies[std::size_t(slides)].transform.position - start.bodies[std::size_t(slides)].transform.position;
    const Real apart = (cached.bodies[std::size_t(slides)].transform.position - built.bodies[std::size_t(slides)].transform.position).norm();
    INFO("travelled " << travelled.norm() << " m; cached and built apart by " << apart << " m");
    CHECK(travelled.norm() > Real(1));  // 1.18 m down the slope in the second
    CHECK(apart < Real(1e-4));
    CHECK(rebuiltFrames == 0);  // once settled on the face, no frame builds it again
}

TEST_CASE("a face contact slides only while its corners stay inside the face it slides on", "[ch10][cache]") {
    // A 1 m box on a 4 m slab; the contact built where it stands, then the box moved along x.
    World world = boxOnSlab();
    Pipeline pipeline = makeChapter10Pipeline(world, SkipWorkOptions{});
    pipeline.step(world);
    REQUIRE(world.contacts.size() == 1);
    const Contact built = world.contacts[0];
    REQUIRE(built.referenceSide != 0);
    REQUIRE(built.pointCount == 4);
    const ContactCacheRule rule;
    const auto slidTo = [&](Real x, Real turn) {
        Body box = world.bodies[1];
        box.transform.position.x() = x;
        box.transform.rotation = Quat(Eigen::AngleAxis<Real>(turn, Vec3::UnitY())) * box.transform.rotation;
        return faceContactSlides(built, world.bodies[0], box, rule);
    };
    CHECK(slidTo(Real(0.5), 0));           // 0.5 m along: every corner well inside
    CHECK(slidTo(Real(1.49), 0));          // corners 1 cm from the slab's edge
    CHECK_FALSE(slidTo(Real(1.4995), 0));  // within the rule's 1 mm of it: built again
    CHECK_FALSE(slidTo(Real(1.8), 0));     // hanging over the edge: the clip would cut
    CHECK_FALSE(slidTo(Real(0.5), Real(0.1)));  // turned 5.7 degrees: other corners, other depths
    // Carried, the corners stay with the box and the slab's points face them at the same depth.
    Contact standing = built;  // where the points are now, the box unmoved
    followContact(world.bodies[0], world.bodies[1], standing);
    Contact carried = built;
    Body box = world.bodies[1];
    box.transform.position.x() += Real(0.5);
    slideFaceContact(carried, world.bodies[0], box);
    for (int i = 0; i < carried.pointCount; ++i) {
        CHECK((carried.points[i].pointB - (standing.points[i].pointB + Vec3(Real(0.5), 0, 0))).norm() < Real(1e-5));
        CHECK(carried.points[i].depth == Approx(standing.points[i].depth).margin(1e-6));
        CHECK((carried.points[i].pointA - carried.points[i].pointB - carried.points[i].depth * carried.normal).norm() < Real(1e-5));
    }
}

TEST_CASE("a record is built again once a corner it may not hold can have swung 1 mm", "[ch10][cache]") {
    // The rule's 2 degrees are Jolt's; a unit box turned 2 degrees swings its far corner 3 cm, and
    // a corner that is not among the record's points (a box tipping over an edge, a hull's fifth
    // corner) would sink that far unseen. B's turn times its bounding radius is held to the 1 mm.
    World world = boxOnSlab();
    Pipeline pipeline = makeChapter10Pipeline(world, SkipWorkOptions{});
    pipeline.step(world);
    REQUIRE(world.contacts.size() == 1);
    const World settled = world;
    const ContactCacheRule rule;
    const auto searchTurned = [&](Real degrees) {
        World turned = settled;
        Transform& pose = turned.bodies[1].transform;
        pose.rotation = Quat(Eigen::AngleAxis<Real>(degrees * kDegree, Vec3::UnitZ())) * pose.rotation;
        ContactCacheScratch scratch;
        return updateManifoldsCached(turned, 1, ManifoldOptions{}, rule, scratch);
    };
    const ContactCacheStats slight = searchTurned(Real(0.03));  // the far corner swings 0.45 mm
    CHECK(slight.reused == 1);
    CHECK(slight.rebuilt == 0);
    const ContactCacheStats tipped = searchTurned(Real(0.3));  // 4.5 mm, well within 2 degrees
    CHECK(tipped.reused == 0);
    CHECK(tipped.rebuilt == 1);
}

TEST_CASE("a carried record's points follow their bodies four at a time as chapter 3 follows them, bit for bit",
          "[ch10][cache]") {
    // followCorners (the cache's follow of a box or hull pair) against chapter 3's followContact,
    // one point at a time: random poses, anchors and normals, one to four points.
    Random random(17);
    const auto point = [&](Real size) {
        return Vec3(random.uniformReal(-size, size), random.uniformReal(-size, size), random.uniformReal(-size, size));
    };
    Body a, b;
    a.shape = Shape::box(Vec3(Real(0.5), Real(0.3), Real(0.7)));
    b.shape = Shape::box(Vec3(Real(1.5), Real(0.5), Real(1)));
    int compared = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        a.transform = Transform{point(20), random.rotation()};
        b.transform = Transform{point(20), random.rotation()};
        Contact contact;
        contact.bodyA = 0, contact.bodyB = 1;
        contact.pointCount = 1 + trial % 4;
        contact.normal = random.unitVector();
        for (int i = 0; i < contact.pointCount; ++i) {
            contact.points[i].localAnchorA = point(1);
            contact.points[i].localAnchorB = point(2);
        }
        Contact expected = contact;
        followContact(a, b, expected);
        followCorners(a, b, contact);
        for (int i = 0; i < contact.pointCount; ++i) {
            CHECK(sameBits(contact.points[i].pointA, expected.points[i].pointA));
            CHECK(sameBits(contact.points[i].pointB, expected.points[i].pointB));
            CHECK(sameBits(contact.points[i].depth, expected.points[i].depth));
            ++compared;
        }
    }
    CHECK(compared == 5000);
}
