// `stepwise bench debug` in quick mode: its tables and plots, and the page's claims in small:
// recording a frame costs a fraction of stepping it, and the GJK ray cast meets the closed forms
// once its iteration cap is high enough.
#include "09_debug/benches.h"
#include "support/quick_bench.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

using namespace stepwise;

TEST_CASE("bench debug writes its tables and plots: history is cheap, GJK ray casts converge", "[ch09][bench]") {
    const test::QuickBench run = test::runQuickBench(
        debugBench(), "ch09_bench_test",
        "bodies,step (ms),record (ms),record / step,bytes per frame,120 frames (MB),rewind 60 + 60 steps + resume (ms)");
    REQUIRE(run.rows.size() == 3);
    for (const std::vector<std::string>& cells : run.rows) {
        REQUIRE(cells.size() == 7);
        CHECK(std::stod(cells[2]) < std::stod(cells[1]));   // recording a frame costs less than stepping it
        CHECK(std::stod(cells[4]) > 1000);                  // a snapshot: more than a kilobyte a frame, the contacts' most of it
    }
    CHECK(run.printed.find("ray casts") != std::string::npos);
    CHECK(run.printed.find("snapshot") != std::string::npos);
    // The last GJK row per shape (cap 64) deviates from the closed form by less than a micrometre
    // and calls (almost) every ray as the closed form does.
    int converged = 0;
    std::istringstream lines(run.printed);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream cells(line);
        std::vector<std::string> words;
        for (std::string word; cells >> word;) words.push_back(word);
        if (words.size() == 7 && words[1] == "GJK" && words[2] == "64") {
            CHECK(std::stod(words[5]) <= 2);          // at most a couple of grazes of 2,000 rays called otherwise
            CHECK(std::stod(words[6]) < 1e-6);
            ++converged;
        }
    }
    CHECK(converged == 4);
}
