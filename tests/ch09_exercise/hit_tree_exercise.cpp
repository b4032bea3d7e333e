// Exercise check for chapter 9 (`ctest -L ch09-exercise`): rewrite buildHitTree in
// chapters/09_debug/hit_tree.cpp from the page (one pair node per contact record that holds
// points, in the cache's order, one manifold under it, one node per point with the midpoint of
// its two surface points, its depth and the last solve's impulses), and run this. The tree of
// three chapter 9 scenes, stepped through chapter 8's pipeline, is compared with the contact
// cache it comes from, field by field; a record without points must not appear.
#include "08_joints/chapter.h"
#include "09_debug/hit_tree.h"
#include "09_debug/scenes.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

void checkTree(const World& world) {
    const HitTree tree = buildHitTree(world);
    std::size_t p = 0;
    int points = 0;
    for (const Contact& contact : world.contacts) {
        if (contact.pointCount <= 0) continue;
        REQUIRE(p < tree.pairs.size());
        const HitPair& pair = tree.pairs[p++];
        CHECK(pair.bodyA == contact.bodyA);
        CHECK(pair.bodyB == contact.bodyB);
        CHECK(pair.nameA == world.bodies[static_cast<std::size_t>(contact.bodyA)].name);
        CHECK(pair.nameB == world.bodies[static_cast<std::size_t>(contact.bodyB)].name);
        REQUIRE(pair.manifolds.size() == 1);
        const HitManifold& manifold = pair.manifolds[0];
        CHECK(manifold.normal == contact.normal);
        REQUIRE(manifold.points.size() == static_cast<std::size_t>(contact.pointCount));
        for (int i = 0; i < contact.pointCount; ++i) {
            const ContactPoint& source = contact.points[i];
            const HitPoint& point = manifold.points[static_cast<std::size_t>(i)];
            CHECK(point.pointA == source.pointA);
            CHECK(point.pointB == source.pointB);
            CHECK((point.position - Real(0.5) * (source.pointA + source.pointB)).norm() <= Real(1e-6));
            CHECK(point.depth == source.depth);
            CHECK(point.normalImpulse == source.normalImpulse);
            CHECK(point.tangentImpulse[0] == source.tangentImpulse[0]);
            CHECK(point.tangentImpulse[1] == source.tangentImpulse[1]);
            CHECK(point.featureId == source.featureId);
            CHECK(point.persisted == source.persisted);
            ++points;
        }
    }
    CHECK(tree.pairs.size() == p);
    CHECK(tree.pointCount() == points);
}

}  // namespace

TEST_CASE("exercise: the hit tree lists the contact cache's pairs and points", "[ch09-exercise]") {
    struct Case {
        World (*build)();
        int frames;
    };
    for (const Case& scene : {Case{buildDebugDrop, 90}, Case{buildDebugJitter, 60}, Case{buildDebugHullOnBox, 120}}) {
        World world = scene.build();
        Pipeline pipeline = makeChapter08Pipeline(world);
        for (int frame = 0; frame < scene.frames; ++frame) pipeline.step(world);
        INFO(world.name << " at frame " << world.frame);
        REQUIRE(!world.contacts.empty());
        checkTree(world);
        // A record the cache keeps without points (a pair that drew apart) has no node.
        Contact empty = world.contacts.front();
        empty.pointCount = 0;
        world.contacts.insert(world.contacts.begin(), empty);
        checkTree(world);
    }
}
