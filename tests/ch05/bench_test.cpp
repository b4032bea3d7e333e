// `stepwise bench broadphase` in quick mode: its table, its plots and its summary lines.
#include "05_sap/benches.h"
#include "support/quick_bench.h"

#include <catch2/catch.hpp>

#include <map>
#include <string>

using namespace stepwise;

TEST_CASE("bench broadphase writes its table, both plots and the targets, and rejects an unwritable path",
          "[ch05][bench]") {
    const test::QuickBench run =
        test::runQuickBench(broadphaseBench(), "ch05_bench_test",
                            "part,density,shape,bodies,method,broadphase_ms,step_ms,sort_ms,candidates,axis_overlaps,contacts,"
                            "narrowphase_ms,solve_ms");
    std::map<std::string, int> rowsPerPart;
    std::map<std::string, double> candidates;  // "method bodies density" -> candidate pairs, scaling part
    for (const std::vector<std::string>& cell : run.rows) {
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
    CHECK(run.plotText.find(">10,000<") != std::string::npos);  // body counts as whole numbers (tick labels)
    CHECK(run.printed.find("crossover: sweep and prune's broadphase is faster from") != std::string::npos);
    CHECK(run.printed.find("targets (one thread, CPU time):") != std::string::npos);
    CHECK(test::rejectsUnwritablePath(broadphaseBench()));
}
