// The history and the rewind: a session rewound, stepped speculatively and resumed carries on
// exactly as a run that never rewound, bit for bit, in scenes with contacts, joints and
// continuous collision; re-stepping from a kept frame reproduces the frames that followed it.
#include "09_debug/debug_session.h"

#include "app/registry.h"
#include "world/state_hash.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

DebugSession sessionOf(const std::string& scene) {
    const Registry& registry = chapterRegistry();
    World world = registry.findScene(scene)->build();
    Pipeline pipeline = registry.makePipeline(world);
    return DebugSession(std::move(world), std::move(pipeline));
}

std::uint64_t hashAfter(const std::string& scene, int frames) {
    const Registry& registry = chapterRegistry();
    World world = registry.findScene(scene)->build();
    Pipeline pipeline = registry.makePipeline(world);
    for (int frame = 0; frame < frames; ++frame) pipeline.step(world);
    return stateHash(world);
}

}  // namespace

TEST_CASE("history: a ring of the last frames, the oldest overwritten", "[ch09][history]") {
    World world;
    History history(4);
    CHECK(history.empty());
    CHECK(history.oldestFrame() == -1);
    for (long frame = 0; frame < 6; ++frame) {
        world.frame = frame;
        history.record(world);
    }
    CHECK(history.size() == 4);
    CHECK(history.oldestFrame() == 2);
    CHECK(history.newestFrame() == 5);
    CHECK_FALSE(history.find(1));
    REQUIRE(history.find(3));
    CHECK(history.find(3)->frame == 3);
    CHECK(history.at(0).frame == 2);
    CHECK(history.bytes() >= 4 * sizeof(WorldSnapshot));
    CHECK(history.baseCount() == 1);   // one structure, kept once
    history.clear();
    CHECK(history.empty());
    CHECK(History(0).capacity() == 1);   // a ring of at least one frame, never a division by zero
}

TEST_CASE("rewind k frames, step speculatively, resume: the live run goes on bit for bit", "[ch09][history]") {
    // Contacts (a drop and a stack), joints (the ragdoll pile), continuous collision (the gun).
    const std::string scene = GENERATE(as<std::string>{}, "debug-drop", "debug-jitter", "joints-ragdoll-pile", "ccd-gun",
                                       "joints-platform");
    INFO(scene);
    const int rewindBy = GENERATE(1, 37, 119);
    DebugSession session = sessionOf(scene);
    for (int frame = 0; frame < 130; ++frame) session.step();
    const std::uint64_t live = stateHash(session.world());
    REQUIRE(session.history().size() == kHistoryFrames);
    REQUIRE(session.rewindBy(rewindBy));
    CHECK(session.rewound());
    CHECK(session.world().frame == 130 - rewindBy);
    // Re-stepping from the kept frame gives the frames that followed it, bit for bit.
    for (int frame = 0; frame < rewindBy; ++frame) {
        session.step();
        REQUIRE(stateHash(session.world()) == stateHash(*session.history().find(session.world().frame)));
    }
    // Speculate further than the live run went, then go back to it.
    for (int frame = 0; frame < 20; ++frame) session.step();
    CHECK(session.history().newestFrame() == 130);   // speculative frames are not recorded
    session.resume();
    CHECK_FALSE(session.rewound());
    CHECK(stateHash(session.world()) == live);
    for (int frame = 0; frame < 40; ++frame) session.step();
    CHECK(stateHash(session.world()) == hashAfter(scene, 170));
    CHECK(session.frameHashes().size() == 170);
}

TEST_CASE("rewind: edits while rewound are speculative, live edits survive a rewind", "[ch09][history]") {
    DebugSession session = sessionOf("debug-drop");
    for (int frame = 0; frame < 20; ++frame) session.step();
    const int box = session.world().findBody("box");
    // A live edit after the last live frame: it is part of the live state a resume restores.
    session.edit(moveEdit(session.world(), box, Transform{Vec3(0, 3, 0), Quat::Identity()}));
    const std::uint64_t edited = stateHash(session.world());
    REQUIRE(session.rewindBy(10));
    session.edit(moveEdit(session.world(), box, Transform{Vec3(5, 5, 5), Quat::Identity()}));
    session.step();
    session.resume();
    CHECK(stateHash(session.world()) == edited);
    CHECK(session.edits().size() == 1);   // the speculative edit is not logged
    CHECK(session.world().bodies[std::size_t(box)].transform.position == Vec3(0, 3, 0));
}

TEST_CASE("rewind: frames outside the history are refused, and nothing changes", "[ch09][history]") {
    DebugSession session = sessionOf("debug-drop");
    for (int frame = 0; frame < 150; ++frame) session.step();
    const std::uint64_t live = stateHash(session.world());
    CHECK(session.history().oldestFrame() == 150 - kHistoryFrames + 1);
    CHECK_FALSE(session.rewindTo(5));
    CHECK_FALSE(session.rewindTo(151));
    CHECK_FALSE(session.rewound());
    CHECK(stateHash(session.world()) == live);
    // Asking for more than is kept stops at the oldest frame.
    REQUIRE(session.rewindBy(1000));
    CHECK(session.world().frame == session.history().oldestFrame());
    CHECK(session.liveFrame() == 150);
    session.resume();
    CHECK(stateHash(session.world()) == live);
}
