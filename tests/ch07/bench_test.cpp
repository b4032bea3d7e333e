// `stepwise bench ccd` in quick mode: its table, its plots, and the page's claims in small.
#include "07_ccd/benches.h"
#include "support/quick_bench.h"

#include <catch2/catch.hpp>

#include <map>
#include <string>

using namespace stepwise;

TEST_CASE("bench ccd writes its table and plots, and CCD stops the tunnels that CCD off lets through", "[ch07][bench]") {
    const test::QuickBench run = test::runQuickBench(ccdBench(), "ch07_bench_test",
                                                     "method,speed_mps,shots,tunnelled,tunnel_rate,step_us,impacts_per_shot");
    std::map<std::string, int> tunnels;
    std::map<std::string, int> rows;
    for (const std::vector<std::string>& cell : run.rows) {
        REQUIRE(cell.size() == 7);
        tunnels[cell[0]] += std::stoi(cell[3]);
        ++rows[cell[0]];
    }
    CHECK(rows.size() == 6);
    for (const auto& [method, count] : rows) CHECK(count == 3);
    CHECK(tunnels["ccd on"] == 0);
    CHECK(tunnels["ccd off"] > 0);
    // Substeps alone do not stop them: contacts are searched once per frame (the page's numbers).
    CHECK(tunnels["16 substeps"] > 0);
    // Both time-of-impact methods find the same impacts on the same sweeps.
    const std::size_t methods = run.printed.find("time of impact, two ways");
    REQUIRE(methods != std::string::npos);
    CHECK(run.printed.find("conservative advancement", methods) != std::string::npos);
    CHECK(run.printed.find("separation roots", methods) != std::string::npos);
    CHECK(test::rejectsUnwritablePath(ccdBench()));
}
