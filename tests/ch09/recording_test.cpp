// Record then replay: the same report and every frame's state hash met, for scenes with contacts,
// joints and continuous collision, with hand edits, and for a demo session's recording of every
// built-in scene; a tampered recording names the frame where it parts; a malformed one names the
// JSON path of what is wrong.
#include "09_debug/recording.h"

#include "09_debug/debug_session.h"
#include "app/registry.h"
#include "support/registry_fixture.h"
#include "support/scene_rejection.h"
#include "world/json_reader.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("record then replay gives an identical report and meets every frame's hash", "[ch09][record]") {
    const std::string scene = GENERATE(as<std::string>{}, "debug-drop", "joints-gallery", "ccd-gun", "pyramid-20");
    INFO(scene);
    const Registry& registry = chapterRegistry();
    const Recording recording = recordRun(registry, scene, registry.lastChapter(), 150);
    REQUIRE(recording.frameHashes.size() == 150);
    // Through the file format, as a user would replay it.
    const Recording read = recordingFromJson(recordingToJson(recording));
    CHECK(read.frameHashes == recording.frameHashes);
    CHECK(read.bodyHashes == recording.bodyHashes);
    const ReplayResult result = replay(registry, read);
    CHECK(result.frames == 150);
    CHECK(result.firstMismatch == -1);
    CHECK(result.reportMatches);
    CHECK(comparableReport(result.reportJson) == comparableReport(recording.reportJson));
}

TEST_CASE("a demo session's recording replays exactly, hand edits included, for every built-in scene", "[ch09][record]") {
    const Registry& registry = chapterRegistry();
    // The stress and pyramid scenes are left out: the run above covers size.
    const int replayed = test::forEachSmallScene(registry.lastChapter(), [&](const SceneEntry& entry, World world) {
        Pipeline pipeline = registry.makePipeline(world);
        DebugSession session(std::move(world), std::move(pipeline));
        for (int frame = 0; frame < 40; ++frame) session.step();
        // Poke the first dynamic body as the gizmo and the inspector would, then run on.
        const World& now = session.world();
        int poked = -1;
        for (std::size_t i = 0; i < now.bodies.size() && poked < 0; ++i)
            if (now.bodies[i].type == BodyType::Dynamic) poked = int(i);
        if (poked >= 0) {
            BodyEdit heavier = currentState(now, poked);
            heavier.mass *= 2;
            heavier.inertiaLocal *= 2;
            heavier.linearVelocity += Vec3(0, 1, 0);
            session.edit(heavier);
            Transform lifted = session.world().bodies[std::size_t(poked)].transform;
            lifted.position.y() += Real(0.5);
            session.edit(moveEdit(session.world(), poked, lifted));
        }
        for (int frame = 0; frame < 20; ++frame) session.step();
        const Recording recording = recordingFromJson(recordingToJson(recordingOf(session, 99)), entry.name);
        CHECK(recording.edits.size() == (poked >= 0 ? 2u : 0u));
        const ReplayResult result = replay(registry, recording);
        CHECK(result.frames == 60);
        CHECK(result.firstMismatch == -1);
        return true;
    });
    CHECK(replayed >= 25);
}

TEST_CASE("a replay that parts from its recording names the frame", "[ch09][record]") {
    const Registry& registry = chapterRegistry();
    Recording recording = recordRun(registry, "debug-drop", registry.lastChapter(), 60);
    recording.frameHashes[41] ^= 1;
    const ReplayResult result = replay(registry, recording);
    CHECK(result.firstMismatch == 42);
    CHECK(result.expectedHash == recording.frameHashes[41]);
    CHECK(result.actualHash == (recording.frameHashes[41] ^ 1));
    CHECK(result.firstBody == -1);  // every body's own hash is met: only the frame's was changed
}

TEST_CASE("a replay that parts from its recording names the first body that differs", "[ch09][record]") {
    const Registry& registry = chapterRegistry();
    Recording recording = recordRun(registry, "debug-drop", registry.lastChapter(), 60);
    REQUIRE(recording.bodyHashes.size() == 60);
    REQUIRE(recording.bodyHashes[41].size() >= 2);
    recording.frameHashes[41] ^= 1;
    recording.bodyHashes[41][1] ^= 1;
    const ReplayResult result = replay(registry, recordingFromJson(recordingToJson(recording)));
    CHECK(result.firstMismatch == 42);
    CHECK(result.firstBody == 1);
}

namespace {

/// What reading the recording text is rejected with: the SceneError's lines, "" when it is read.
std::string rejectionOf(const std::string& text) {
    return test::rejectionMessage([&] { recordingFromJson(text); });
}

}  // namespace

TEST_CASE("malformed recordings are rejected with the JSON path of what is wrong", "[ch09][record]") {
    const Registry& registry = chapterRegistry();
    const std::string good = recordingToJson(recordRun(registry, "debug-drop", registry.lastChapter(), 3));
    const auto rejection = [&](const std::function<void(Json&)>& spoil) {
        Json json = Json::parse(good);
        spoil(json);
        return rejectionOf(json.dump());
    };
    CHECK(rejectionOf("{ \"format\": ").find("malformed JSON") != std::string::npos);
    CHECK(rejectionOf("[1, 2]").find("must be a JSON object") != std::string::npos);
    CHECK(rejection([](Json& j) { j["format"] = "stepwise-scene"; }).find("format") != std::string::npos);
    CHECK(rejection([](Json& j) { j["version"] = 7; }).find("version") != std::string::npos);
    CHECK(rejection([](Json& j) { j["engine"] = "stepwise 0.0 (other)"; }).find("cannot be met here") != std::string::npos);
    CHECK(rejection([](Json& j) { j["frame_hashes"][1] = "0x12"; }).find("frame_hashes[1]") != std::string::npos);
    CHECK(rejection([](Json& j) { j["frames"] = 9; }).find("frames") != std::string::npos);
    CHECK(rejection([](Json& j) { j["scene"]["bodies"][1]["shape"]["box"]["half_extents"][0] = -1; })
              .find("bodies[1].shape.box.half_extents[0]") != std::string::npos);
    const Json edit = {{"frame", 1},      {"body", "box"},          {"position", {0, 1, 0}},      {"orientation", {0, 0, 0, 1}},
                       {"linear_velocity", {0, 0, 0}}, {"angular_velocity", {0, 0, 0}}, {"mass", 2},
                       {"inertia", {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}};
    CHECK(rejection([&](Json& j) { j["edits"] = Json::array({edit}); }).empty());
    CHECK(rejection([&](Json& j) { j["edits"] = Json::array({edit}); j["edits"][0]["body"] = "crate"; }).find("edits[0].body") != std::string::npos);
    CHECK(rejection([&](Json& j) { j["edits"] = Json::array({edit}); j["edits"][0]["mass"] = -2; }).find("mass must be positive") != std::string::npos);
    CHECK(rejection([&](Json& j) { j["edits"] = Json::array({edit}); j["edits"][0]["inertia"][0][1] = 0.5; }).find("symmetric") != std::string::npos);
    CHECK(rejection([&](Json& j) { j["edits"] = Json::array({edit}); j["edits"][0]["orientation"] = {0, 0, 0, 3}; }).find("unit") != std::string::npos);
    CHECK(rejection([&](Json& j) { j["edits"] = Json::array({edit, edit}); j["edits"][1]["frame"] = 0; }).find("frame order") != std::string::npos);
    CHECK(rejection([&](Json& j) { j["edits"] = Json::array({edit}); j["edits"][0]["colour"] = "red"; }).find("colour") != std::string::npos);
}
