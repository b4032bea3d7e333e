// `stepwise bench stacking` in quick mode: its table, its plots and its summary.
#include "06_manifolds/benches.h"

#include "app/bench_util.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace stepwise;

TEST_CASE("bench stacking writes its table, its plots and the targets, and rejects an unwritable path", "[ch06][bench]") {
    const std::filesystem::path directory = std::filesystem::temp_directory_path();
    const std::string csv = (directory / "ch06_bench_test.csv").string();
    const std::string plot = (directory / "ch06_bench_test.svg").string();
    std::ostringstream out;
    BenchOptions options;
    options.quick = true;
    options.csvPath = csv;
    options.plotPath = plot;
    options.out = &out;
    options.quiet = true;
    REQUIRE(runBench(stackingBench(), options) == 0);
    std::ifstream table(csv);
    std::string line;
    std::getline(table, line);
    CHECK(line == "part,scene,stabilisation,warm_starting,contacts,iterations,substeps,drift_m,sag_beyond_slop_m,"
                  "sink_per_contact_m,max_penetration_m,step_ms,stood");
    std::map<std::string, int> rowsPerPart;
    std::map<std::string, double> drift;  // "part scene stabilisation warm contacts iterations" -> drift
    while (std::getline(table, line)) {
        std::stringstream cells(line);
        std::vector<std::string> cell;
        for (std::string value; std::getline(cells, value, ',');) cell.push_back(value);
        REQUIRE(cell.size() == 13);
        ++rowsPerPart[cell[0]];
        drift[cell[0] + " " + cell[1] + " " + cell[2] + " " + cell[3] + " " + cell[4] + " " + cell[5]] = std::stod(cell[7]);
    }
    CHECK(rowsPerPart["iterations"] == 6 * 3);
    CHECK(rowsPerPart["substeps"] == 4 * 2);
    CHECK(rowsPerPart["pyramids"] == 4 * 2);
    CHECK(rowsPerPart["targets"] == 5 * 3);
    // The default stands its stack; without warm starting it drifts more (the page's claim).
    CHECK(drift["targets stack-16 relax on manifold 10"] < 0.01);
    CHECK(drift["targets stack-16 relax off manifold 10"] > drift["targets stack-16 relax on manifold 10"]);
    CHECK(out.str().find("targets at the default settings") != std::string::npos);
    std::vector<std::string> files = {csv, plot};
    for (const char* suffix : {"-sag", "-penetration", "-substeps", "-summary"})
        files.push_back((directory / (std::string("ch06_bench_test") + suffix + ".svg")).string());
    for (const std::string& path : files) {
        CHECK(std::ifstream(path).good());
        std::remove(path.c_str());
    }

    options.csvPath = "/nonexistent-dir/x.csv";
    CHECK(runBench(stackingBench(), options) == 2);
}
