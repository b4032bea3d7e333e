#include "09_debug/recording.h"

#include "09_debug/debug_session.h"
#include "app/runner.h"
#include "world/json_reader.h"
#include "world/report.h"
#include "world/scene.h"
#include "world/state_hash.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace stepwise {

namespace {

constexpr const char* kFormat = "stepwise-recording";
constexpr int kVersion = 1;

// Recordings must give back the exact bits: numbers are written as doubles (every float is one),
// which JSON prints with enough digits to read back unchanged, never through tidyNumber.
Json exact(const Vec3& v) { return Json::array({double(v.x()), double(v.y()), double(v.z())}); }
Json exact(const Quat& q) { return Json::array({double(q.x()), double(q.y()), double(q.z()), double(q.w())}); }

Real exactNumber(const JsonCursor& cursor) {
    if (!cursor.json().is_number()) cursor.fail("must be a number");
    const double value = cursor.json().get<double>();
    if (!std::isfinite(value) || std::abs(value) > double(kRealMax)) cursor.fail("must be a finite number");
    return Real(value);
}
Vec3 exactVec3(const JsonCursor& cursor) {
    if (!cursor.json().is_array() || cursor.json().size() != 3) cursor.fail("must be an array of 3 numbers [x, y, z]");
    return Vec3(exactNumber(cursor.element(0)), exactNumber(cursor.element(1)), exactNumber(cursor.element(2)));
}
Quat exactQuat(const JsonCursor& cursor) {
    if (!cursor.json().is_array() || cursor.json().size() != 4) cursor.fail("must be an array of 4 numbers [x, y, z, w]");
    return Quat(exactNumber(cursor.element(3)), exactNumber(cursor.element(0)), exactNumber(cursor.element(1)),
                exactNumber(cursor.element(2)));
}

Json exact(const Mat3& m) {
    Json rows = Json::array();
    for (int row = 0; row < 3; ++row) rows.push_back(exact(Vec3(m.row(row).transpose())));
    return rows;
}
Mat3 exactMat3(const JsonCursor& cursor) {
    if (cursor.arraySize() != 3) cursor.fail("must be 3 rows of 3 numbers");
    Mat3 m;
    for (int row = 0; row < 3; ++row) m.row(row) = exactVec3(cursor.element(std::size_t(row))).transpose();
    return m;
}

ExactBodyState exactStateOf(const World& world, int body) {
    ExactBodyState state;
    state.transform = world.bodies[std::size_t(body)].transform;
    if (const Motion* motion = world.motionOf(body)) {
        state.linearVelocity = motion->linearVelocity;
        state.angularVelocity = motion->angularVelocity;
        state.mass = motion->mass;
        state.inverseMass = motion->inverseMass;
        state.localCenter = motion->localCenter;
        state.inertiaLocal = motion->inertiaLocal;
        state.inverseInertiaLocal = motion->inverseInertiaLocal;
    }
    return state;
}

std::vector<ExactBodyState> exactStatesOf(const World& world) {
    std::vector<ExactBodyState> states;
    for (int body = 0; body < static_cast<int>(world.bodies.size()); ++body) states.push_back(exactStateOf(world, body));
    return states;
}

/// Appends where a body is and how it moves, the fields a body state and an edit share, in
/// the order the files have always had them.
void addMotionJson(Json& json, const Transform& transform, const Vec3& linearVelocity, const Vec3& angularVelocity) {
    json["position"] = exact(transform.position);
    json["orientation"] = exact(transform.rotation);
    json["linear_velocity"] = exact(linearVelocity);
    json["angular_velocity"] = exact(angularVelocity);
}

Json stateToJson(const ExactBodyState& state) {
    Json json = Json::object();
    addMotionJson(json, state.transform, state.linearVelocity, state.angularVelocity);
    json.update(Json{{"mass", double(state.mass)},
                     {"inverse_mass", double(state.inverseMass)},
                     {"local_center", exact(state.localCenter)},
                     {"inertia", exact(state.inertiaLocal)},
                     {"inverse_inertia", exact(state.inverseInertiaLocal)}});
    return json;
}

ExactBodyState stateFromJson(const JsonCursor& entry) {
    entry.expectObject({"position", "orientation", "linear_velocity", "angular_velocity", "mass", "inverse_mass",
                        "local_center", "inertia", "inverse_inertia"});
    ExactBodyState state;
    state.transform.position = exactVec3(entry.child("position"));
    state.transform.rotation = exactQuat(entry.child("orientation"));
    if (std::abs(state.transform.rotation.norm() - 1) > Real(1e-3)) entry.child("orientation").fail("must be a unit quaternion");
    state.linearVelocity = exactVec3(entry.child("linear_velocity"));
    state.angularVelocity = exactVec3(entry.child("angular_velocity"));
    state.mass = exactNumber(entry.child("mass"));
    state.inverseMass = exactNumber(entry.child("inverse_mass"));
    if (state.mass < 0 || state.inverseMass < 0) entry.child("mass").fail("must be >= 0");
    state.localCenter = exactVec3(entry.child("local_center"));
    state.inertiaLocal = exactMat3(entry.child("inertia"));
    state.inverseInertiaLocal = exactMat3(entry.child("inverse_inertia"));
    return state;
}

Json editToJson(const World& world, const BodyEdit& edit) {
    Json json = {{"frame", edit.frame}, {"body", world.bodies.at(static_cast<std::size_t>(edit.body)).name}};
    addMotionJson(json, edit.transform, edit.linearVelocity, edit.angularVelocity);
    json["mass"] = double(edit.mass);
    json["inertia"] = exact(edit.inertiaLocal);
    return json;
}

std::uint64_t parseHash(const JsonCursor& cursor) {
    const std::string text = cursor.string();
    char* end = nullptr;
    const unsigned long long value = std::strtoull(text.c_str(), &end, 16);
    if (text.size() != 18 || text.compare(0, 2, "0x") != 0 || !end || *end != '\0')
        cursor.fail("must be a hash \"0x\" followed by 16 hex digits (got \"" + text + "\")");
    return value;
}

// A frame's body hashes as one string, 8 hex digits a body, in scene order: a tenth of the size
// of a JSON array of numbers.
std::string bodyHashText(const std::vector<std::uint32_t>& hashes) {
    std::string text;
    char digits[9];
    for (std::uint32_t hash : hashes) {
        std::snprintf(digits, sizeof digits, "%08x", static_cast<unsigned>(hash));
        text += digits;
    }
    return text;
}

std::vector<std::uint32_t> parseBodyHashes(const JsonCursor& cursor, std::size_t bodies) {
    const std::string text = cursor.string();
    if (text.size() != 8 * bodies || text.find_first_not_of("0123456789abcdef") != std::string::npos)
        cursor.fail("must be 8 lower-case hex digits per body of the scene (" + std::to_string(8 * bodies) + " digits)");
    std::vector<std::uint32_t> hashes;
    for (std::size_t body = 0; body < bodies; ++body)
        hashes.push_back(static_cast<std::uint32_t>(std::strtoul(text.substr(8 * body, 8).c_str(), nullptr, 16)));
    return hashes;
}

std::vector<std::uint32_t> bodyHashesOf(const World& world) {
    std::vector<std::uint32_t> hashes;
    for (std::size_t body = 0; body < world.bodies.size(); ++body) hashes.push_back(bodyStateHash(world, body));
    return hashes;
}

}  // namespace

Recording recordingOf(const DebugSession& session, int chapter) {
    Recording recording;
    recording.chapter = chapter;
    recording.sceneJson = saveSceneToString(session.startWorld());
    recording.start = exactStatesOf(session.startWorld());
    recording.edits = session.edits();
    recording.frameHashes = session.frameHashes();
    return recording;
}

// [ch09-record-run]
Recording recordRun(const Registry& registry, const std::string& sceneNameOrPath, int chapter, long frames) {
    Recording recording;
    recording.chapter = chapter;
    World world = loadSceneOrBuiltin(registry, sceneNameOrPath);
    recording.sceneJson = saveSceneToString(world);
    recording.start = exactStatesOf(world);
    Pipeline pipeline = registry.makePipeline(world, chapter);
    RunOptions options;
    options.frames = frames;
    options.maxChapter = chapter;
    options.afterFrame = [&](World& stepped) {
        recording.frameHashes.push_back(stateHash(stepped));
        recording.bodyHashes.push_back(bodyHashesOf(stepped));
    };
    const RunStats stats = runHeadless(world, pipeline, registry, options);
    recording.reportJson = reportToJson(world, stats, engineVersion());
    return recording;
}
// [ch09-record-run]

std::string recordingToJson(const Recording& recording) {
    const World scene = loadSceneFromString(recording.sceneJson, "recording scene");
    Json json = {{"format", kFormat}, {"version", kVersion}, {"engine", engineVersion()}, {"chapter", recording.chapter}};
    json["frames"] = recording.frameHashes.size();
    json["scene"] = Json::parse(recording.sceneJson);
    json["start"] = Json::array();
    for (const ExactBodyState& state : recording.start) json["start"].push_back(stateToJson(state));
    json["edits"] = Json::array();
    for (const BodyEdit& edit : recording.edits) json["edits"].push_back(editToJson(scene, edit));
    json["frame_hashes"] = Json::array();
    for (std::uint64_t hash : recording.frameHashes) json["frame_hashes"].push_back(hexHash(hash));
    if (!recording.bodyHashes.empty()) {
        json["body_hashes"] = Json::array();
        for (const std::vector<std::uint32_t>& frame : recording.bodyHashes) json["body_hashes"].push_back(bodyHashText(frame));
    }
    if (!recording.reportJson.empty()) json["report"] = Json::parse(recording.reportJson);
    return json.dump(2) + "\n";
}

Recording recordingFromJson(const std::string& text, const std::string& source) {
    const Json json = parseStrictJson(text, source);
    const JsonCursor root(json, "");
    if (!json.is_object()) root.fail(source + " must be a JSON object (a recording: docs/scene-format.md)");
    root.expectObject({"format", "version", "engine", "chapter", "frames", "scene", "start", "edits", "frame_hashes",
                       "body_hashes", "report"});
    if (root.child("format").string() != kFormat) root.child("format").fail(std::string("must be \"") + kFormat + "\"");
    if (root.child("version").integer(1, 1000) != kVersion) root.child("version").fail("must be 1 (this program reads version 1)");
    const std::string engine = root.child("engine").string();
    if (engine != engineVersion())
        root.child("engine").fail("recorded by " + engine + ", but this is " + engineVersion() +
                                  ": the frame hashes hold the exact bits of that build and cannot be met here");
    Recording recording;
    recording.chapter = root.child("chapter").integer(1, 99);
    const JsonCursor scene = root.child("scene");
    if (!scene.json().is_object()) scene.fail("must be a scene object (docs/scene-format.md)");
    recording.sceneJson = scene.json().dump();
    const World world = loadSceneFromString(recording.sceneJson, source + " scene");
    const JsonCursor start = root.child("start");
    if (start.arraySize() != world.bodies.size())
        start.fail("must hold one state per body of the scene (" + std::to_string(world.bodies.size()) + ")");
    for (std::size_t i = 0; i < world.bodies.size(); ++i) recording.start.push_back(stateFromJson(start.element(i)));
    const JsonCursor hashes = root.child("frame_hashes");
    const std::size_t frames = hashes.arraySizeAtMost(std::size_t(100000000));
    for (std::size_t i = 0; i < frames; ++i) recording.frameHashes.push_back(parseHash(hashes.element(i)));
    if (root.child("frames").integer(0, 100000000) != static_cast<int>(frames))
        root.child("frames").fail("must equal the number of frame_hashes (" + std::to_string(frames) + ")");
    if (const auto bodyHashes = root.optional("body_hashes")) {
        if (bodyHashes->arraySize() != frames) bodyHashes->fail("must hold one entry per frame (" + std::to_string(frames) + ")");
        for (std::size_t i = 0; i < frames; ++i)
            recording.bodyHashes.push_back(parseBodyHashes(bodyHashes->element(i), world.bodies.size()));
    }
    const JsonCursor edits = root.child("edits");
    long previousFrame = -1;
    for (std::size_t i = 0; i < edits.arraySize(); ++i) {
        const JsonCursor entry = edits.element(i);
        entry.expectObject({"frame", "body", "position", "orientation", "linear_velocity", "angular_velocity", "mass", "inertia"});
        BodyEdit edit;
        edit.frame = entry.child("frame").integer(0, 100000000);
        if (edit.frame < previousFrame) entry.child("frame").fail("edits must be in frame order");
        previousFrame = edit.frame;
        const std::string name = entry.child("body").string();
        edit.body = world.findBody(name);
        if (edit.body < 0) entry.child("body").fail("no body named \"" + name + "\" in the recording's scene");
        edit.transform.position = exactVec3(entry.child("position"));
        edit.transform.rotation = exactQuat(entry.child("orientation"));
        edit.linearVelocity = exactVec3(entry.child("linear_velocity"));
        edit.angularVelocity = exactVec3(entry.child("angular_velocity"));
        edit.mass = exactNumber(entry.child("mass"));
        edit.inertiaLocal = exactMat3(entry.child("inertia"));
        const std::string problem = validateEdit(world, edit);
        if (!problem.empty()) entry.fail(problem);
        recording.edits.push_back(edit);
    }
    if (const auto report = root.optional("report")) {
        if (!report->json().is_object()) report->fail("must be a run report object");
        recording.reportJson = report->json().dump(2);
    }
    return recording;
}

Recording readRecordingFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw SceneError("", "cannot read recording '" + path + "'");
    std::stringstream text;
    text << in.rdbuf();
    return recordingFromJson(text.str(), path);
}

void writeRecordingFile(const std::string& path, const Recording& recording) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error("cannot write recording '" + path + "'");
    out << recordingToJson(recording);
    if (!out) throw std::runtime_error("writing recording '" + path + "' failed");
}

std::string comparableReport(const std::string& reportJson) {
    if (reportJson.empty()) return "";
    Json report = Json::parse(reportJson);
    report.erase("timing_ms");
    return report.dump(2);
}

World startingWorld(const Registry& registry, const Recording& recording) {
    World world = loadSceneFromString(recording.sceneJson, "recording scene", registry.sceneGenerators());
    if (recording.start.size() != world.bodies.size())
        throw SceneError("start", "holds " + std::to_string(recording.start.size()) + " states for " +
                                      std::to_string(world.bodies.size()) + " bodies");
    for (std::size_t body = 0; body < world.bodies.size(); ++body) {
        const ExactBodyState& state = recording.start[body];
        world.bodies[body].transform = state.transform;
        if (Motion* motion = world.motionOf(int(body))) {
            motion->linearVelocity = state.linearVelocity;
            motion->angularVelocity = state.angularVelocity;
            motion->mass = state.mass;
            motion->inverseMass = state.inverseMass;
            motion->localCenter = state.localCenter;
            motion->inertiaLocal = state.inertiaLocal;
            motion->inverseInertiaLocal = state.inverseInertiaLocal;
        }
    }
    return world;
}

// [ch09-replay]
ReplayResult replay(const Registry& registry, const Recording& recording) {
    World world = startingWorld(registry, recording);
    Pipeline pipeline = registry.makePipeline(world, recording.chapter);
    ReplayResult result;
    std::size_t nextEdit = 0;
    RunOptions options;
    options.frames = static_cast<long>(recording.frameHashes.size());
    options.maxChapter = recording.chapter;
    options.beforeFrame = [&](World& stepped) {
        for (; nextEdit < recording.edits.size() && recording.edits[nextEdit].frame <= stepped.frame; ++nextEdit)
            applyEdit(stepped, recording.edits[nextEdit]);
    };
    options.afterFrame = [&](World& stepped) {
        const std::uint64_t hash = stateHash(stepped);
        const std::size_t index = static_cast<std::size_t>(result.frames++);
        if (result.firstMismatch < 0 && hash != recording.frameHashes[index]) {
            result.firstMismatch = result.frames;
            result.expectedHash = recording.frameHashes[index];
            result.actualHash = hash;
            if (index < recording.bodyHashes.size()) {
                const std::vector<std::uint32_t> actual = bodyHashesOf(stepped);
                for (std::size_t body = 0; body < actual.size() && result.firstBody < 0; ++body)
                    if (actual[body] != recording.bodyHashes[index][body]) result.firstBody = static_cast<int>(body);
            }
        }
    };
    const RunStats stats = runHeadless(world, pipeline, registry, options);
    result.reportJson = reportToJson(world, stats, engineVersion());
    result.reportMatches = !recording.reportJson.empty() &&
                           comparableReport(result.reportJson) == comparableReport(recording.reportJson);
    return result;
}
// [ch09-replay]

}  // namespace stepwise
