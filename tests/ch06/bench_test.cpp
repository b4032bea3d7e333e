// `stepwise bench stacking` in quick mode: its table, its plots and its summary.
#include "06_manifolds/benches.h"
#include "support/quick_bench.h"

#include <catch2/catch.hpp>

#include <map>
#include <string>

using namespace stepwise;

TEST_CASE("bench stacking writes its table, its plots and the targets, and rejects an unwritable path", "[ch06][bench]") {
    const test::QuickBench run =
        test::runQuickBench(stackingBench(), "ch06_bench_test",
                            "part,scene,stabilisation,warm_starting,contacts,iterations,substeps,drift_m,sag_beyond_slop_m,"
                            "sink_per_contact_m,max_penetration_m,step_ms,stood");
    std::map<std::string, int> rowsPerPart;
    std::map<std::string, double> drift;  // "part scene stabilisation warm contacts iterations" -> drift
    for (const std::vector<std::string>& cell : run.rows) {
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
    CHECK(run.printed.find("targets at the default settings") != std::string::npos);
    CHECK(test::rejectsUnwritablePath(stackingBench()));
}
