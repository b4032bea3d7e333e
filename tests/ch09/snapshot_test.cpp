// Compact snapshots: a frame kept as the state the next step reads back (poses, velocities, the
// contact cache with its impulses, the sweep's order, the joints' impulses) restores into a world
// of the same structure and steps on bit for bit; it takes a fraction of a whole world; and a
// history whose structure changes mid-run (an edit of a mass) still rewinds exactly.
#include "09_debug/debug_session.h"
#include "ch09/snapshot_check.h"

#include "06_manifolds/scenes.h"
#include "08_joints/chapter.h"
#include "app/registry.h"
#include "support/registry_fixture.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace stepwise;

namespace {

const std::function<Pipeline(const World&)> kLatest = [](const World& world) {
    return chapterRegistry().makePipeline(world);
};

}  // namespace

TEST_CASE("snapshot: every small scene of chapters 1 to 9 restores and steps on bit for bit", "[ch09][snapshot]") {
    const int compared = test::forEachSmallScene(9, [&](const SceneEntry& scene, World world) {
        const auto make = [chapter = scene.chapter](const World& w) { return chapterRegistry().makePipeline(w, chapter); };
        const test::RestoreMismatch mismatch = test::firstRestoreMismatch(world, make, 24, {1, 12});
        INFO("restored frame " << mismatch.restoredAt << " into " << mismatch.into);
        CHECK(mismatch.frame == -1);
        return mismatch.restores > 0;
    });
    CHECK(compared >= 25);
}

TEST_CASE("snapshot: the scene files through chapter 9's pipeline restore bit for bit", "[ch09][snapshot]") {
    int compared = 0;
    for (const auto& item : std::filesystem::directory_iterator("scenes")) {
        if (item.path().extension() != ".json") continue;
        INFO(item.path().string());
        const World world = loadSceneFile(item.path().string(), chapterRegistry().sceneGenerators());
        const test::RestoreMismatch mismatch = test::firstRestoreMismatch(world, kLatest, 40, {3, 25});
        INFO("restored frame " << mismatch.restoredAt << " into " << mismatch.into);
        CHECK(mismatch.frame == -1);
        ++compared;
    }
    CHECK(compared >= 5);
}

TEST_CASE("snapshot: a pyramid's frame takes at most 128 bytes a body and 64 a contact point", "[ch09][snapshot]") {
    World world = buildPyramid(11);   // 66 boxes on the ground, resting on one another
    Pipeline pipeline = makeChapter08Pipeline(world);
    for (int frame = 0; frame < 6; ++frame) pipeline.step(world);
    WorldSnapshot snapshot;
    saveSnapshot(world, snapshot);
    const SnapshotSize size = snapshotSize(snapshot);
    INFO(size.perBody() << " bytes a body, " << size.perContactPoint() << " a contact point, "
                        << size.contactPoints << " points in " << snapshot.contacts.size() << " records");
    REQUIRE(size.contactPoints > 300);
    if (sizeof(Real) == 4) {   // the budget is stated for float; a double build doubles every Real
        CHECK(size.perBody() <= 128);
        CHECK(size.perContactPoint() <= 64);
    }
    // Against a whole copy of the world (its vectors' capacities): less than half.
    CHECK((size.bodyBytes + size.contactBytes + size.fixedBytes + size.jointBytes) * 2 < worldBytes(world));
}

TEST_CASE("history: an edit of a mass mid-run takes a new base; every kept frame still rewinds exactly", "[ch09][snapshot][history]") {
    const Registry& registry = chapterRegistry();
    World start = registry.findScene("debug-drop")->build();
    DebugSession session(start, registry.makePipeline(start), 40);
    for (int frame = 0; frame < 20; ++frame) session.step();
    const int box = session.world().findBody("box");
    REQUIRE(box >= 0);
    BodyEdit heavier = currentState(session.world(), box);
    heavier.mass *= 4;
    heavier.inertiaLocal *= 4;
    session.edit(heavier);
    for (int frame = 0; frame < 15; ++frame) session.step();
    CHECK(session.history().baseCount() == 2);
    // A plain run with the same edit at the same frame gives every frame's reference.
    World plain = start;
    Pipeline pipeline = registry.makePipeline(plain);
    std::vector<std::uint64_t> hashes{stateHash(plain)};
    for (int frame = 0; frame < 35; ++frame) {
        if (frame == 20) applyEdit(plain, heavier);
        pipeline.step(plain);
        hashes.push_back(stateHash(plain));
    }
    REQUIRE(session.frameHashes().back() == hashes.back());
    // Each kept frame, before the edit and after, rewinds to its own state and steps on to the
    // frames that followed it (the edit of frame 20 is part of frame 20's live world only, so the
    // check steps on from the frames after it).
    for (long frame = session.history().oldestFrame(); frame <= session.history().newestFrame(); ++frame) {
        INFO("frame " << frame);
        REQUIRE(session.rewindTo(frame));
        CHECK(stateHash(session.world()) == hashes[static_cast<std::size_t>(frame)]);
        const Motion* motion = session.world().motionOf(box);
        CHECK(motion->mass == (frame <= 20 ? heavier.mass / 4 : heavier.mass));
        if (frame > 20 && frame < 35) {
            session.step();
            CHECK(stateHash(session.world()) == hashes[static_cast<std::size_t>(frame + 1)]);
        }
    }
    session.resume();
    CHECK(stateHash(session.world()) == hashes.back());
    // Once the frames of the old structure fall out of the ring, its base goes with them.
    for (int frame = 0; frame < 40; ++frame) session.step();
    CHECK(session.history().baseCount() == 1);
}

TEST_CASE("snapshot: restoring into a world of another structure is refused with a reason", "[ch09][snapshot]") {
    World world = buildPyramid(3);
    WorldSnapshot snapshot;
    saveSnapshot(world, snapshot);
    World other = buildPyramid(4);
    CHECK_THROWS_AS(restoreSnapshot(snapshot, other), std::invalid_argument);
    CHECK_FALSE(sameStructure(world, other));
    CHECK(sameStructure(world, structureOf(world)));
}

TEST_CASE("history: rebase() makes the next frame take a new base, the kept frames keep theirs", "[ch09][snapshot][history]") {
    World world = buildPyramid(3);
    History history(8);
    history.record(world);
    world.bodies[1].material.friction = 0;   // a change sameStructure does not look at
    history.rebase();
    ++world.frame;
    history.record(world);
    CHECK(history.baseCount() == 2);
    CHECK(history.at(0).bodies[1].material.friction != 0);
    CHECK(history.at(1).bodies[1].material.friction == 0);
}
