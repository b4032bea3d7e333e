// `stepwise bench joints` in quick mode: its table, its plots, and the page's claims in small.
#include "08_joints/benches.h"
#include "08_joints/joint_solver.h"
#include "support/quick_bench.h"

#include <catch2/catch.hpp>

#include <map>
#include <string>

using namespace stepwise;

namespace {

// Columns of the bench's table.
enum Column { kCase, kOrder, kFeedback, kWarm, kIterations, kSubsteps, kSweeps, kSeconds, kStepMs, kLargest, kFinal, kErrorM, kErrorRad };

}  // namespace

TEST_CASE("bench joints writes its table and plots: more iterations stretch a chain less, rigid rows fail", "[ch08][bench]") {
    const test::QuickBench run = test::runQuickBench(
        jointsBench(), "ch08_bench_test",
        "case,order,feedback,warm_starting,iterations,substeps,joint_sweeps,seconds,step_ms,largest_stretch,final_stretch,"
        "joint_error_m,joint_error_rad");
    std::map<std::string, double> largest;  // swinging chain at 1 substep, default order: by iterations
    double rigidLargest = -1;
    double pileError = -1;
    for (const std::vector<std::string>& cell : run.rows) {
        REQUIRE(cell.size() == 13);
        const bool plain = cell[kOrder] == toString(kDefaultJointOrder) && cell[kWarm] == "on" && cell[kSweeps] == "1" && cell[kSubsteps] == "1";
        if (cell[kCase] == "swinging_chain" && plain && cell[kFeedback] == "soft") largest[cell[kIterations]] = std::stod(cell[kLargest]);
        if (cell[kFeedback] == "baumgarte") rigidLargest = std::stod(cell[kLargest]);
        if (cell[kCase] == "ragdoll_pile" && plain && cell[kIterations] == "10") pileError = std::stod(cell[kErrorM]);
        CHECK(std::stod(cell[kStepMs]) > 0);
    }
    // More iterations, less stretch; the default stays under the chapter's 2%.
    REQUIRE(largest.count("2") == 1);
    REQUIRE(largest.count("10") == 1);
    REQUIRE(largest.count("40") == 1);
    CHECK(largest["40"] < largest["10"]);
    CHECK(largest["10"] < largest["2"]);
    CHECK(largest["10"] < 0.02);
    // Rigid Baumgarte rows: the hanging chain stretches by a fifth or more (float: past twice its
    // length, and the run stops; double: 82% in 3 s), against 0.14% with the soft rows.
    CHECK(rigidLargest > 0.2);
    // A settled ragdoll pile holds its joints within a millimetre.
    CHECK(pileError >= 0);
    CHECK(pileError < 1e-3);
    CHECK(run.printed.find("what a direct solve would buy") != std::string::npos);
    CHECK(test::rejectsUnwritablePath(jointsBench()));
}
