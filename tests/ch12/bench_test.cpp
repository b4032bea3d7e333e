// `stepwise bench speed` in quick mode (without the Bullet peer, which only the `stepwise` program
// links): its tables and plots, and the page's claims in small: each optimisation pays, the
// pyramids stand, a settled pile of boxes and hulls costs less asleep.
#include "12_planner/benches.h"
#include "support/quick_bench.h"
#include "support/temp_path.h"

#include <catch2/catch.hpp>

#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace stepwise;

// Tagged without-peer: the `stepwise` program runs this bench beside Bullet, so the docs build runs
// it itself rather than taking this run's files (tests/CMakeLists.txt: stepwise_discover_tests).
TEST_CASE("bench speed writes its tables and plots: every optimisation pays, pyramids stand", "[ch12][bench][without-peer]") {
    const test::QuickBench run = test::runQuickBench(
        speedBench(), "ch10_bench_test",
        "scene,bodies,configuration,frames,ms_median,ms_q1,ms_q3,broadphase_ms,narrowphase_ms,solve_ms,ns_per_body,"
        "max_sideways_m,lowest_m,max_penetration_m,joint_error_m,joint_error_rad,x_faster_than_peer,depth_beyond_true_m,overlap_unseen_m,joint_gap_mean_m");
    // 6 contact scenes x 6 configurations, 4 joint scenes x 3 (the fast step, its scalar solve,
    // chapter 8's solve), no peer here.
    REQUIRE(run.rows.size() == 48);
    const std::vector<std::string> jointScenes = {"ragdoll pile", "20-link chain", "joints sandbox", "100 ragdolls"};
    std::map<std::string, std::map<std::string, std::vector<std::string>>> rowOf;
    std::map<std::string, std::map<std::string, double>> ms;  // scene -> configuration -> ms per step
    std::map<std::string, std::map<std::string, double>> sideways;  // ... -> largest sideways move, m
    for (const std::vector<std::string>& cells : run.rows) {
        REQUIRE(cells.size() >= 14);  // the last column, times faster than the peer, is empty here
        ms[cells[0]][cells[2]] = std::stod(cells[4]);
        rowOf[cells[0]][cells[2]] = cells;
        sideways[cells[0]][cells[2]] = std::stod(cells[11]);
        CHECK(std::stod(cells[12]) > 0);  // nothing fell through the ground
        // The pyramids stand: no box 5 cm sideways (the measure), 1 cm with chapter 10's step
        // (the scalar order, bottom row first, drifts most: 2.4 cm in float, 3.4 cm in double).
        // Without the shock sweep, at the substeps the planner takes with it, they sway further.
        const bool swaying = cells[2] == "no shock sweep";
        const bool pyramid = cells[0] == "pyramid 100 rows" || cells[0] == "ten 20-row pyramids" ||
                             cells[0] == "touching 100 rows" || cells[0] == "ten touching 20-row";
        if (pyramid && !swaying) CHECK(std::stod(cells[11]) < (cells[2] == "fast step" ? 0.01 : 0.05));
    }
    for (const char* pyramid : {"pyramid 100 rows", "ten 20-row pyramids", "touching 100 rows", "ten touching 20-row"}) {
        INFO(pyramid);
        CHECK(ms[pyramid]["fast step"] < ms[pyramid]["scalar solve"]);
        CHECK(ms[pyramid]["fast step"] < ms[pyramid]["no contact cache"]);
        CHECK(ms[pyramid]["fast step"] < ms[pyramid]["chapter 8's solve"]);
        CHECK(sideways[pyramid]["fast step"] < sideways[pyramid]["no shock sweep"]);  // the sweep buys accuracy
    }
    // The pile of unlike masses keeps its contacts within twice the slop (5 mm) of the surface.
    CHECK(std::stod(rowOf["unlike pile"]["fast step"][13]) < 0.01);
    // No contact point reads deeper than its shapes overlap (checked in every frame between the
    // contact search and the solve): the rule is a millimetre; chapter 6 keeps within its face
    // tolerance, half of it, and these scenes read under 0.31 mm. A reference face held while it
    // reads deeper (tests/ch06/held_face_test.cpp) makes the mixed pile read 0.57 mm: the check is
    // at half a millimetre, where a millimetre would let that pass.
    for (const char* scene : {"pyramid 100 rows", "touching 100 rows", "mixed pile", "unlike pile"}) {
        INFO(scene);
        CHECK(std::stod(rowOf[scene]["fast step"][17]) < 0.0005);
        // Nor does any pair overlap more than chapter 6's face tolerance (half a millimetre) and
        // the swing a carried record allows (1 mm, ContactCacheRule) beyond its contact's deepest
        // point: a capsule clipped against a face whose edge it overhangs, a face clip that cut off
        // the deepest corner, or a record carried while a corner it does not hold swung in further,
        // would show here as centimetres. The touching pyramids read up to about 1 mm.
        CHECK(std::stod(rowOf[scene]["fast step"][18]) < 0.0015);
    }
    for (const std::string& scene : jointScenes) {
        INFO(scene);
        REQUIRE(rowOf[scene].size() == 3);
        // Joints in the fast solve: faster than chapter 8's solve (the chain at the 18 substeps its
        // sag asks for, chapter 8's at ten, about even), the same outcome on the scalar path.
        if (scene != "20-link chain") CHECK(ms[scene]["fast step"] < ms[scene]["chapter 8's solve"]);
        for (std::size_t column : {11u, 12u, 13u, 14u, 15u, 19u}) CHECK(rowOf[scene]["fast step"][column] == rowOf[scene]["scalar solve"][column]);
        // Each second's largest anchor gap, averaged over the run: a joint scene's every solve has
        // one. The quick run's two seconds are mostly the landing, in which a falling ragdoll's
        // joints part by up to 3 cm on either solve (a second's largest gap).
        for (const auto& [configuration, cells] : rowOf[scene]) {
            INFO(configuration);
            REQUIRE(cells.size() == 20);
            CHECK(std::stod(cells[19]) > 0);
            CHECK(std::stod(cells[19]) < 0.05);
        }
    }
    // The profile's last column: the share of joint row builds a joint kept its last substep's rows
    // (chapter 11). A falling pile keeps most, and so does a swinging chain of distance joints.
    std::map<std::string, double> kept;
    std::istringstream printed(run.printed);
    bool inProfile = false;
    for (std::string line; std::getline(printed, line);) {
        if (line.find("joint_rows_kept") != std::string::npos) inProfile = true;
        if (!inProfile || line.empty()) continue;
        const std::size_t end = line.find_last_not_of(' ');
        for (const std::string& scene : jointScenes)
            if (line.rfind(scene + " ", 0) == 0) kept[scene] = std::stod(line.substr(line.find_last_of(' ', end) + 1));
    }
    REQUIRE(kept.size() == jointScenes.size());
    CHECK(kept["ragdoll pile"] > 0.5);
    CHECK(kept["100 ragdolls"] > 0.5);
    CHECK(kept["20-link chain"] > 0.5);  // its links swing less than kJointRowsKeptTurn in most substeps
    // The unlike pile dropped again (speed-drops.csv): drop 0 is the table's own drop, to the digit;
    // every drop lands (a finite depth, on the ground's side of a metre).
    std::vector<std::vector<std::string>> drops;
    std::istringstream again(run.printed);
    bool inDrops = false;
    for (std::string line; std::getline(again, line);) {
        if (line.rfind("drop ", 0) == 0) inDrops = true;
        else if (inDrops && (line.empty() || !std::isdigit(static_cast<unsigned char>(line[0])))) inDrops = false;
        else if (inDrops) {
            std::istringstream cells(line);
            std::vector<std::string> row;
            for (std::string cell; cells >> cell;) row.push_back(cell);
            drops.push_back(row);
        }
    }
    REQUIRE(drops.size() == 3);
    CHECK(drops[0][2] == rowOf["unlike pile"]["fast step"][13]);
    for (const std::vector<std::string>& drop : drops) {
        REQUIRE(drop.size() == 4);
        CHECK(std::stod(drop[2]) > 0);
        CHECK(std::stod(drop[2]) < 1);
    }
    CHECK(run.printed.find("deepest contact after 5 s over 3 drops") != std::string::npos);
    CHECK(run.printed.find("Bullet skipped") != std::string::npos);
    CHECK(run.printed.find("angular-pile-300") != std::string::npos);
    CHECK(run.printed.find("ragdoll-field-20") != std::string::npos);  // the ragdolls asleep and awake
}

TEST_CASE("bench speed --only prints the chosen scenes and refuses to write files", "[ch12][bench]") {
    BenchOptions options;
    options.quick = options.quiet = true;
    std::ostringstream out;
    options.out = &out;
    options.only = "20-link chain";
    options.csvPath = test::tempPath("speed-only-refused.csv").string();
    CHECK(runBench(speedBench(), options) == 2);
    CHECK(!std::filesystem::exists(options.csvPath));
    options.csvPath.clear();
    REQUIRE(runBench(speedBench(), options) == 0);
    CHECK(out.str().find("20-link chain") != std::string::npos);
    CHECK(out.str().find("pyramid") == std::string::npos);
}
