// Chapter 9 adds no stage, so its promise to the earlier chapters is that looking does not touch:
// every registered scene of chapters 1 to 8, run in a debug session that records every frame and
// rewinds, speculates and resumes halfway, ends in the very state a plain run of the same
// pipeline does, bit for bit, with the same report.
#include "09_debug/debug_session.h"

#include "app/registry.h"
#include "app/runner.h"
#include "support/report_compare.h"
#include "support/registry_fixture.h"
#include "world/state_hash.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("scenes of chapters 1 to 8: a session that rewinds and resumes ends where a plain run does", "[ch09][earlier]") {
    const Registry& registry = chapterRegistry();
    const int compared = test::forEachSmallScene(8, [&](const SceneEntry&, World plain) {
        DebugSession session(plain, registry.makePipeline(plain));
        for (int frame = 0; frame < 60; ++frame) session.step();
        REQUIRE(session.rewindBy(30));
        for (int frame = 0; frame < 45; ++frame) session.step();
        session.resume();
        for (int frame = 0; frame < 60; ++frame) session.step();

        Pipeline pipeline = registry.makePipeline(plain);
        RunOptions options;
        options.frames = 120;
        const RunStats stats = runHeadless(plain, pipeline, registry, options);
        CHECK(stateHash(session.world()) == stateHash(plain));
        // The report's state part (bodies, energies) from the session's world with the plain run's statistics.
        CHECK(test::reportWithoutTimingsAndNotes(session.world(), stats) == test::reportWithoutTimingsAndNotes(plain, stats));
        return true;
    });
    CHECK(compared >= 20);
}
