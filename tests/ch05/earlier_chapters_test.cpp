// The promises of chapters 1 to 4 (tests/promises), kept through chapter 5's pipeline: each
// scenario claim of the earlier suites, run with the broadphase stage in front of the
// narrowphase, once with brute force and once with sweep and prune.
#include "05_sap/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

std::vector<test::PipelineVariant> throughChapter5() {
    return test::variantsOver(
        {BroadphaseMode::Brute, BroadphaseMode::Sap}, [](BroadphaseMode mode) { return std::string("broadphase ") + toString(mode); },
        [](BroadphaseMode mode, World& world, ContactSearch search) {
            world.settings.broadphase = mode;
            return makeChapter05Pipeline(world, chooseStepOrder(world), search);
        });
}

}  // namespace

TEST_CASE("through chapter 5: the promises of chapters 1 to 4 hold", "[ch05][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(chapter, throughChapter5());
}
