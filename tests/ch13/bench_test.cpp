// `stepwise bench worlds` in quick mode: 200 bodies dropped on a 20,000-triangle terrain mesh, with
// Bullet beside the engine where the peer was built. Its findings, not its timings: both engines
// ran and were timed, no body of the engine's went through the ground or off it, and its settled
// pile lies within twice the slop but for a body or two (the page gives the full run's numbers).
#include "13_worlds/bench_worlds.h"
#include "support/quick_bench.h"
#include "world/settings.h"

#ifdef STEPWISE_HAVE_BULLET
#include "peers/bullet_peer.h"
#endif

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace stepwise;

TEST_CASE("bench worlds: a pile lands on a terrain mesh, none through it, settled within twice the slop", "[ch13][bench]") {
#ifdef STEPWISE_HAVE_BULLET
    setPeerEngine(peers::bulletPeerEngine());
    const std::size_t engines = 2;
#else
    const std::size_t engines = 1;
#endif
    const test::QuickBench run = test::runQuickBench(
        worldsBench(), "ch13_bench_test",
        "scene,engine,bodies,triangles,frames,ms_median,ms_p95,broadphase_ms,narrowphase_ms,solve_ms,"
        "x_faster_than_peer,tunnelled,left_terrain,max_penetration_m,bodies_over_bound,contact_depth_m,twice_slop_m");
    INFO(run.printed);
    REQUIRE(run.rows.size() == engines);
    const double twiceSlop = 2 * double(Settings{}.slop);
    for (const std::vector<std::string>& cells : run.rows) {
        INFO(cells[1]);
        REQUIRE(cells.size() == 17);
        CHECK(cells[2] == "200");
        CHECK(cells[3] == "20000");
        CHECK(std::stod(cells[5]) > 0);  // timed
        CHECK(std::stod(cells[6]) >= std::stod(cells[5]));
        CHECK(std::stod(cells[13]) >= 0);  // the deepest body into the ground, from the poses
        CHECK(std::stod(cells[15]) >= 0);  // the deepest contact, as the engine has it
        CHECK(std::stod(cells[16]) == Approx(twiceSlop));
    }
    const std::vector<std::string>& engine = run.rows[0];
    CHECK(engine[1] == "chapter 13");
    CHECK(engine[11] == "0");  // no body through the ground
    CHECK(engine[12] == "0");  // none rolled off it
    // Settled, the pile lies at the slop; a body or two, on its side across several triangles,
    // reaches the bound (the pair's one manifold of four points holds its face at the deepest
    // triangle's normal). Sinking or passing through would be decimetres.
    CHECK(std::stoi(engine[14]) <= 4);  // 2% of the pile deeper than twice the slop at once, at most
    CHECK(std::stod(engine[13]) < 2 * twiceSlop);
    if (engines == 2) CHECK(!engine[10].empty());  // the speed ratio, from both engines' medians
    CHECK(run.printed.find("targets:") != std::string::npos);
}
