// `stepwise bench broadphase` in quick mode: its table, its plots and its summary lines.
#include "05_sap/benches.h"

#include "app/bench_util.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace stepwise;

TEST_CASE("bench broadphase writes its table, both plots and the targets, and rejects an unwritable path",
          "[ch05][bench]") {
    const std::filesystem::path directory = std::filesystem::temp_directory_path();
    const std::string csv = (directory / "ch05_bench_test.csv").string();
    const std::string plot = (directory / "ch05_bench_test.svg").string();
    const std::string stepPlot = (directory / "ch05_bench_test-step.svg").string();
    std::ostringstream out;
    BenchOptions options;
    options.quick = true;
    options.csvPath = csv;
    options.plotPath = plot;
    options.out = &out;
    options.quiet = true;
    REQUIRE(runBench(broadphaseBench(), options) == 0);
    std::ifstream table(csv);
    std::string line;
    std::getline(table, line);
    CHECK(line == "part,density,shape,bodies,method,broadphase_ms,step_ms,sort_ms,candidates,axis_overlaps,contacts,"
                  "narrowphase_ms,solve_ms");
    std::map<std::string, int> rowsPerPart;
    std::map<std::string, double> candidates;  // "method bodies density" -> candidate pairs, scaling part
    while (std::getline(table, line)) {
        std::stringstream cells(line);
        std::vector<std::string> cell;
        for (std::string value; std::getline(cells, value, ',');) cell.push_back(value);
        REQUIRE(cell.size() >= 5);
        ++rowsPerPart[cell[0]];
        if (cell[0] == "scaling" && cell.size() > 8) candidates[cell[4] + " " + cell[3] + " " + cell[1]] = std::stod(cell[8]);
    }
    CHECK(rowsPerPart["crossover"] == 2 * 10 * 3);
    CHECK(rowsPerPart["scaling"] >= 20);
    CHECK(rowsPerPart["settled"] == 2);
    // Every broadphase found the same pairs (the mean per frame is the same number).
    CHECK(candidates["brute 10001 sparse"] == candidates["sap_incremental 10001 sparse"]);
    CHECK(candidates["sap_full 10001 dense"] == candidates["sap_incremental 10001 dense"]);
    CHECK(std::ifstream(plot).good());
    CHECK(std::ifstream(stepPlot).good());
    std::ifstream svg(plot);
    const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
    CHECK(text.find(">10,000<") != std::string::npos);  // body counts as whole numbers (tick labels)
    CHECK(out.str().find("crossover: sweep and prune's broadphase is faster from") != std::string::npos);
    CHECK(out.str().find("targets (one thread, CPU time):") != std::string::npos);
    const std::string summary = (directory / "ch05_bench_test-summary.svg").string();
    CHECK(std::ifstream(summary).good());
    for (const std::string& path : {csv, plot, stepPlot, summary}) std::remove(path.c_str());

    options.csvPath = "/nonexistent-dir/x.csv";
    CHECK(runBench(broadphaseBench(), options) == 2);
}
