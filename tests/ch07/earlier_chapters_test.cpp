// The promises of chapters 1 to 4 (tests/promises) through chapter 7's pipeline: with CCD as the
// planner decides, and with CCD forced on for every scene (so the TOI loop runs beside them and
// must not break them). Chapters 5 and 6 are held by the report comparison of pipeline_test.cpp
// and the golden hashes.
#include "07_ccd/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

std::vector<test::PipelineVariant> throughChapter7() {
    const auto chapter7 = [](World& world, ContactSearch search) {
        return makeChapter07Pipeline(world, makeChapter06Pipeline(world, ManifoldOptions{}, chooseStepOrder(world), search));
    };
    const auto ccdOnEverywhere = [chapter7](World& world, ContactSearch search) {
        world.settings.ccd = CcdMode::On;
        return chapter7(world, search);
    };
    return {{"ccd auto", chapter7}, {"ccd on", ccdOnEverywhere}};
}

}  // namespace

TEST_CASE("through chapter 7: the promises of chapters 1 to 4 hold", "[ch07][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(chapter, throughChapter7());
}
