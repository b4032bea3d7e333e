// Run reports: valid JSON, the contract's keys in the contract's order, and the same bytes for
// the same run (outside timing_ms), so reports can be diffed and hashed.

#include "support/json_keys.h"
#include "world/report.h"
#include "world/scene.h"
#include "support/temp_path.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace stepwise;
using Json = nlohmann::ordered_json;
using test::keysOf;

namespace {

// The contract's example scene: a box, and a ball moving down towards it.
World sampleWorld() { return loadSceneFile("tests/common/data/contract-scene.json"); }

RunStats sampleStats(const World& world) {
    RunStats stats;
    stats.frames = 3;
    stats.pipeline = {"integrate:semi_implicit_euler", "broadphase:brute", "narrowphase:gjk_epa", "solve:pgs"};
    stats.stepMs = {0.5, 0.25, 1.0};
    stats.stageMeanMs = {{"integrate", 0.01}, {"broadphase", 0.02}, {"narrowphase", 0.2}, {"solve", 0.3}};
    stats.maxPenetration = 0.004;
    stats.penetrationMeasured = true;
    stats.maxContacts = 2;
    stats.initialEnergy = computeEnergy(world);
    stats.finalEnergy = computeEnergy(world);
    return stats;
}

}  // namespace

TEST_CASE("median of odd, even, unsorted and empty lists", "[common][report]") {
    CHECK(median({}) == 0);
    CHECK(median({4}) == 4);
    CHECK(median({3, 1, 2}) == 2);
    CHECK(median({4, 1, 3, 2}) == 2.5);
    CHECK(median({5, 5, 1, 9, 7, 7}) == 6);
}

TEST_CASE("A report is valid JSON with the contract's keys in order", "[common][report]") {
    const World world = sampleWorld();
    const Json report = Json::parse(reportToJson(world, sampleStats(world), "stepwise test"));

    // Contract keys in contract order; the extensions sit next to what they qualify.
    const std::vector<std::string> expected = {"format", "version", "scene", "engine", "frames", "dt",
                                               "pipeline", "timing_ms", "max_penetration", "penetration_measured",
                                               "max_contacts", "energy", "bodies", "warnings"};
    CHECK(keysOf(report) == expected);
    CHECK(report["format"] == "stepwise-report");
    CHECK(report["version"] == 1);
    CHECK(report["scene"] == "two-box-stack");
    CHECK(report["engine"] == "stepwise test");
    CHECK(report["frames"] == 3);
    CHECK(report["dt"].get<double>() == Approx(0.0166666667));
    CHECK(report["pipeline"].size() == 4);
    CHECK(report["pipeline"][3] == "solve:pgs");

    const Json& timing = report["timing_ms"];
    CHECK(keysOf(timing) == std::vector<std::string>{"step_mean", "step_median", "step_max", "stages"});
    CHECK(timing["step_mean"].get<double>() == Approx(1.75 / 3).margin(1e-4));
    CHECK(timing["step_median"].get<double>() == 0.5);
    CHECK(timing["step_max"].get<double>() == 1.0);
    CHECK(timing["stages"]["solve"].get<double>() == 0.3);

    CHECK(report["max_penetration"].get<double>() == 0.004);
    CHECK(report["penetration_measured"] == true);
    CHECK(report["max_contacts"] == 2);
    CHECK(keysOf(report["energy"]).at(0) == "initial");
    CHECK(keysOf(report["energy"]).at(1) == "final");
    CHECK(report["energy"]["initial"].get<double>() == Approx(computeEnergy(world).total()));

    REQUIRE(report["bodies"].size() == 3);
    const Json& box = report["bodies"][1];
    CHECK(keysOf(box) == std::vector<std::string>{"name", "position", "orientation", "velocity", "angular_velocity"});
    CHECK(box["name"] == "b0");
    CHECK(box["position"] == Json::array({0, 0.5, 0}));
    CHECK(box["orientation"] == Json::array({0, 0, 0, 1}));
    CHECK(report["bodies"][2]["velocity"] == Json::array({0, -1, 0}));
    CHECK(report["warnings"].empty());
}

TEST_CASE("Static bodies report zero velocities, and arrays of numbers stay on one line", "[common][report]") {
    const World world = sampleWorld();
    const std::string text = reportToJson(world, sampleStats(world), "stepwise test");
    const Json report = Json::parse(text);
    CHECK(report["bodies"][0]["name"] == "ground");
    CHECK(report["bodies"][0]["velocity"] == Json::array({0, 0, 0}));
    CHECK(report["bodies"][0]["angular_velocity"] == Json::array({0, 0, 0}));
    CHECK_THAT(text, Catch::Contains("\"position\": [0, -0.5, 0]"));
    CHECK_THAT(text, Catch::Contains("\"orientation\": [0, 0, 0, 1]"));
    CHECK(text.back() == '\n');
}

TEST_CASE("Identical runs give byte-identical reports outside timing_ms", "[common][report]") {
    const World first = sampleWorld();
    const World second = sampleWorld();
    RunStats statsA = sampleStats(first);
    RunStats statsB = sampleStats(second);
    CHECK(reportToJson(first, statsA, "v") == reportToJson(second, statsB, "v"));

    statsB.stepMs = {9.0, 8.0, 7.5};
    statsB.stageMeanMs["solve"] = 4.2;
    const std::string textA = reportToJson(first, statsA, "v");
    const std::string textB = reportToJson(second, statsB, "v");
    CHECK(textA != textB);
    Json reportA = Json::parse(textA);
    Json reportB = Json::parse(textB);
    reportA.erase("timing_ms");
    reportB.erase("timing_ms");
    CHECK(reportA.dump() == reportB.dump());
}

TEST_CASE("A blown-up body is written as null and warned about", "[common][report]") {
    World world = sampleWorld();
    world.motionOf(2)->linearVelocity.y() = std::numeric_limits<Real>::quiet_NaN();
    RunStats stats = sampleStats(sampleWorld());
    stats.warnings = {"joints[0]: no stage handles distance joints yet"};
    const Json report = Json::parse(reportToJson(world, stats, "v"));
    CHECK(report["bodies"][2]["velocity"][1].is_null());
    REQUIRE(report["warnings"].size() == 2);
    CHECK(report["warnings"][0] == "joints[0]: no stage handles distance joints yet");
    CHECK_THAT(report["warnings"][1].get<std::string>(), Catch::Contains("\"ball\""));
}

TEST_CASE("writeReport writes the text and names the path when it cannot", "[common][report]") {
    const World world = sampleWorld();
    const RunStats stats = sampleStats(world);
    const auto path = test::tempPath("stepwise-report-test.json");
    writeReport(path.string(), world, stats, "v");
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    CHECK(text.str() == reportToJson(world, stats, "v"));
    std::filesystem::remove(path);

    try {
        writeReport("no/such/dir/report.json", world, stats, "v");
        FAIL("wrote into a missing directory");
    } catch (const std::runtime_error& error) {
        CHECK_THAT(error.what(), Catch::Contains("no/such/dir/report.json"));
    }
}

TEST_CASE("The report example in the docs has the keys a real report has, in order", "[common][report]") {
    std::ifstream file("docs/scene-format.md", std::ios::binary);
    std::ostringstream page;
    page << file.rdbuf();
    const std::string text = page.str();
    const std::regex block("```json\\n(\\{\\n  \"format\": \"stepwise-report\"[\\s\\S]*?)```");
    std::smatch match;
    REQUIRE(std::regex_search(text, match, block));
    const Json example = Json::parse(match[1].str());

    World world = sampleWorld();
    // The example is a run of the latest engine, whose broadphase stage (chapter 5) names itself.
    world.broadphase.used = BroadphaseMode::Brute;
    world.broadphase.reason = "auto";
    // ... and whose planner says whether continuous collision runs (chapter 7).
    RunStats stats = sampleStats(world);
    stats.planNotes["ccd"] = "off: auto";
    // ... and whether bodies sleep (chapter 10), and how many substeps its solve took.
    stats.planNotes["sleep"] = "on: islands below 0.05 m/s for 0.5 s sleep";
    world.step.iterationPlan.iterations = world.step.iterationPlan.mostIterations = 10;
    const Json report = Json::parse(reportToJson(world, stats, "v"));
    CHECK(keysOf(example) == keysOf(report));
    CHECK(keysOf(example["timing_ms"]) == keysOf(report["timing_ms"]));
    CHECK(keysOf(example["energy"]) == keysOf(report["energy"]));
    CHECK(keysOf(example["bodies"][0]) == keysOf(report["bodies"][0]));
    CHECK(example["bodies"][0] == report["bodies"][0]);  // the same ground, exactly
}
