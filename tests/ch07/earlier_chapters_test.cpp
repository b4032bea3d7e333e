// The promises of chapters 1 to 4 (tests/promises) through chapter 7's pipeline: with CCD as the
// planner decides, and with CCD forced on for every scene (so the TOI loop runs beside them and
// must not break them). Chapters 5 and 6 are held by the report comparison of pipeline_test.cpp
// and the golden hashes.
#include "07_ccd/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

void checkThroughChapter7(int chapter) {
    const std::vector<test::Promise> promises = test::promisesOfChapter(chapter);
    REQUIRE(!promises.empty());
    for (const test::Promise& promise : promises) {
        for (bool forced : {false, true}) {
            INFO("chapter " << chapter << ": " << promise.claim << (forced ? " (ccd on)" : " (ccd auto)"));
            promise.check([forced](World& world, ContactSearch search) {
                if (forced) world.settings.ccd = CcdMode::On;
                return makeChapter07Pipeline(world, makeChapter06Pipeline(world, ManifoldOptions{}, chooseStepOrder(world), search));
            });
        }
    }
}

}  // namespace

TEST_CASE("through chapter 7: chapter 1's promises hold", "[ch07][earlier]") { checkThroughChapter7(1); }
TEST_CASE("through chapter 7: chapter 2's promises hold", "[ch07][earlier]") { checkThroughChapter7(2); }
TEST_CASE("through chapter 7: chapter 3's promises hold", "[ch07][earlier]") { checkThroughChapter7(3); }
TEST_CASE("through chapter 7: chapter 4's promises hold", "[ch07][earlier]") { checkThroughChapter7(4); }
