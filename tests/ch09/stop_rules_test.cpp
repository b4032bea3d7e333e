// Stop rules: contact debug mode stops a drop on the frame its first contact appears (checked
// against the bodies' geometry, not against the rule's own bookkeeping), and again on the next
// body's; the simulation switch stops everything.
#include "04_pgs/chapter.h"
#include "09_debug/debug_session.h"

#include "03_epa/narrowphase.h"
#include "09_debug/scenes.h"
#include "app/registry.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

/// The gap between the body and the ground (index 0), by chapter 3's exact query: > 0 apart.
Real gapToGround(const World& world, int body) {
    const Body& ground = world.bodies[0];
    const Body& moving = world.bodies[std::size_t(body)];
    const ContactQuery query = collideShapes(ground.shape, ground.transform, moving.shape, moving.transform);
    return -query.depth;   // depth > 0 overlapping, < 0 minus the distance apart
}

}  // namespace

TEST_CASE("stop on a new contact: chapter 4's pipeline stops on the frame the box first overlaps", "[ch09][stop]") {
    // Chapter 4 has no speculative contacts: a contact appears when the shapes overlap at the
    // frame's collision search, that is at the poses the previous frame ended with.
    World world = buildDebugDrop();
    Pipeline pipeline = makeChapter04Pipeline(world);
    DebugSession session(world, std::move(pipeline));
    session.rules.stopOnNewContact = true;
    const int box = session.world().findBody("box");
    long stopFrame = -1;
    for (int frame = 0; frame < 120 && stopFrame < 0; ++frame)
        if (session.step() == StopReason::NewContact) stopFrame = session.world().frame;
    REQUIRE(stopFrame > 1);
    CHECK(session.paused);
    REQUIRE(session.newContacts().size() == 1);
    CHECK(session.newContacts()[0] == BodyPair{0, box});
    // The poses the stop frame's search saw (the end of the frame before) overlap; the ones before did not.
    CHECK(gapToGround(*session.history().find(stopFrame - 1), box) <= 0);
    CHECK(gapToGround(*session.history().find(stopFrame - 2), box) > 0);
}

TEST_CASE("stop on a new contact: through the latest pipeline, each body's first contact stops the run", "[ch09][stop]") {
    const Registry& registry = chapterRegistry();
    World world = buildDebugDrop();
    // The frames at which each pair first holds a contact, from a plain run.
    World plain = world;
    Pipeline plainPipeline = registry.makePipeline(plain);
    std::vector<long> firstContact(plain.bodies.size(), -1);
    for (int frame = 0; frame < 240; ++frame) {
        plainPipeline.step(plain);
        for (const BodyPair& pair : pairsInContact(plain))
            if (firstContact[std::size_t(pair.bodyB)] < 0) firstContact[std::size_t(pair.bodyB)] = plain.frame;
    }
    const int box = world.findBody("box"), ball = world.findBody("ball");
    REQUIRE(firstContact[std::size_t(box)] > 0);
    REQUIRE(firstContact[std::size_t(ball)] > firstContact[std::size_t(box)]);

    DebugSession session(world, registry.makePipeline(world));
    session.rules.stopOnNewContact = true;
    std::vector<long> stops;
    for (int frame = 0; frame < 240; ++frame) {
        if (session.step() != StopReason::NewContact) continue;
        const long stop = session.world().frame;
        stops.push_back(stop);
        // A speculative contact appears within the margin ahead of touching: the gap at the
        // stop frame's search is small (or already closed), the one a frame before is not closed.
        const int body = session.newContacts().front().bodyB;
        CHECK(gapToGround(*session.history().find(stop - 1), body) < Real(0.25));
        CHECK(gapToGround(*session.history().find(stop - 2), body) > 0);
        session.paused = false;   // Left Alt: go on
    }
    REQUIRE(stops.size() >= 2);
    CHECK(stops[0] == firstContact[std::size_t(box)]);
    CHECK(stops[1] == firstContact[std::size_t(ball)]);
}

TEST_CASE("the simulation switch: off, nothing steps", "[ch09][stop]") {
    const Registry& registry = chapterRegistry();
    World world = buildDebugDrop();
    DebugSession session(world, registry.makePipeline(world));
    session.simulationEnabled = false;
    CHECK(session.step() == StopReason::Disabled);
    CHECK(session.world().frame == 0);
    CHECK(session.history().size() == 1);
    session.simulationEnabled = true;
    CHECK(session.step() == StopReason::None);
    CHECK(session.world().frame == 1);
}
