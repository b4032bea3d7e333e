// Chapter 9's compact snapshots through the latest chapter's pipeline: the state a frame keeps
// (poses, velocities, the contact cache with chapter 10's built poses, sleep timers and flags, the
// sweep's axis and order, the joints' impulses, the planner's last plan) restores into a world of
// the same structure and steps on bit for bit. Sleeping, the contact cache, the planner, the wide
// solve, continuous collision, kinematic paths, joints, compounds, meshes and height fields all
// take part. STEPWISE_SNAPSHOT_ALL=1 runs every built-in scene (through its own chapter's
// pipeline and through the latest) instead of the representative few.
#include "ch09/snapshot_check.h"

#include "app/registry.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

using namespace stepwise;

namespace {

const std::function<Pipeline(const World&)> kLatest = [](const World& world) { return chapterRegistry().makePipeline(world); };

bool everyScene() {
    const char* all = std::getenv("STEPWISE_SNAPSHOT_ALL");
    return all && std::string(all) == "1";
}

void checkScene(const std::string& name, const World& world, const std::function<Pipeline(const World&)>& make,
                long frames, const std::vector<long>& at, const test::Poke& poke = {}) {
    INFO(name);
    const test::RestoreMismatch mismatch = test::firstRestoreMismatch(world, make, frames, at, poke);
    INFO("restored frame " << mismatch.restoredAt << " into " << mismatch.into);
    CHECK(mismatch.frame == -1);
    CHECK(mismatch.restores == 2 * static_cast<int>(at.size()));
}

}  // namespace

TEST_CASE("snapshot: scenes of every kind through the latest pipeline restore and step on bit for bit", "[snapshot]") {
    // Stacks and piles (the contact cache, the planner, the wide solve), a gun and a spinning rod
    // (continuous collision), joints and a kinematic platform, round bodies, a mesh's seams.
    const std::vector<std::string> kinds = {"stack-16",         "card-house",   "heavy-on-light", "pgs-sphere-pit",
                                            "ccd-gun",          "ccd-spinning-rod", "joints-gallery", "joints-platform",
                                            "joints-rotator",   "debug-jitter", "epa-contact-gallery", "worlds-seams",
                                            "worlds-cylinders"};
    const Registry& registry = chapterRegistry();
    for (const std::string& name : kinds) {
        const SceneEntry* scene = registry.findScene(name);
        REQUIRE(scene);
        checkScene(name, scene->build(), kLatest, 40, {2, 21});
    }
}

TEST_CASE("snapshot: every scene file through the latest pipeline restores bit for bit", "[snapshot]") {
    const Registry& registry = chapterRegistry();
    std::vector<std::filesystem::path> files;
    for (const auto& item : std::filesystem::directory_iterator("scenes"))
        if (item.path().extension() == ".json") files.push_back(item.path());
    std::sort(files.begin(), files.end());
    for (const auto& file : files)
        checkScene(file.string(), loadSceneFile(file.string(), registry.sceneGenerators()), kLatest, 40, {2, 21});
    CHECK(files.size() >= 5);
}

TEST_CASE("snapshot: sleepers restore asleep, with their timers, and wake as they did", "[snapshot]") {
    // The cylinders fall asleep within a second and a half; a frame taken while they sleep
    // restores them asleep, and a push at frame 100 wakes the same island in both runs.
    const World world = chapterRegistry().findScene("worlds-cylinders")->build();
    World settled = world;
    Pipeline pipeline = kLatest(settled);
    for (int frame = 0; frame < 90; ++frame) pipeline.step(settled);
    int sleepers = 0;
    for (const Motion& motion : settled.motions) sleepers += motion.asleep ? 1 : 0;
    REQUIRE(sleepers > 0);
    const auto push = [](World& w, long stepped) {
        if (stepped != 100) return;
        for (const Motion& motion : w.motions)
            if (motion.asleep) {
                wakeBody(w, motion.bodyIndex);
                w.motionOf(motion.bodyIndex)->linearVelocity += Vec3(1, 2, 0);
                return;
            }
    };
    checkScene("worlds-cylinders", world, kLatest, 130, {60, 95, 101}, push);
}

TEST_CASE("snapshot: every built-in scene, its own chapter's pipeline and the latest (STEPWISE_SNAPSHOT_ALL=1)", "[snapshot]") {
    if (!everyScene()) return;
    const Registry& registry = chapterRegistry();
    for (const SceneEntry& scene : registry.scenes()) {
        const World world = scene.build();
        if (world.bodies.size() > 260) continue;
        const auto own = [chapter = scene.chapter](const World& w) { return chapterRegistry().makePipeline(w, chapter); };
        checkScene(scene.name + " (its chapter)", world, own, 90, {2, 45, 70});
        checkScene(scene.name + " (latest)", world, kLatest, 90, {2, 45, 70});
    }
}

TEST_CASE("snapshot: 2,100 boxes through the latest pipeline take at most 128 bytes a body and 64 a contact point", "[snapshot]") {
    const SceneEntry* scene = chapterRegistry().findScene("speed-pyramids");
    REQUIRE(scene);
    World world = scene->build();
    Pipeline pipeline = kLatest(world);
    for (int frame = 0; frame < 3; ++frame) pipeline.step(world);   // every pyramid stands on its contacts
    WorldSnapshot snapshot;
    saveSnapshot(world, snapshot);
    const SnapshotSize size = snapshotSize(snapshot);
    INFO(size.perBody() << " bytes a body, " << size.perContactPoint() << " a contact point, " << size.contactPoints
                        << " points in " << snapshot.contacts.size() << " records, " << snapshot.builtPoses.size()
                        << " built poses");
    REQUIRE(size.bodies > 2000);
    REQUIRE(size.contactPoints > 10000);
    const double realScale = double(sizeof(Real)) / 4;   // the budget is stated for float
    CHECK(size.perBody() <= 128 * realScale);
    CHECK(size.perContactPoint() <= 64 * realScale);
    // Against a whole copy of the world: well under half.
    CHECK((size.bodyBytes + size.contactBytes + size.fixedBytes + size.jointBytes) * 2 < worldBytes(world));
}
