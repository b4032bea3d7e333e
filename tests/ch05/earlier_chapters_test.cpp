// The promises of chapters 1 to 4 (tests/promises), kept through chapter 5's pipeline: each
// scenario claim of the earlier suites, run with the broadphase stage in front of the
// narrowphase, once with brute force and once with sweep and prune.
#include "05_sap/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

void checkThroughChapter5(int chapter) {
    const std::vector<test::Promise> promises = test::promisesOfChapter(chapter);
    REQUIRE(!promises.empty());
    for (const test::Promise& promise : promises) {
        for (BroadphaseMode mode : {BroadphaseMode::Brute, BroadphaseMode::Sap}) {
            INFO("chapter " << chapter << ": " << promise.claim << " (broadphase " << toString(mode) << ")");
            promise.check([mode](World& world, ContactSearch search) {
                world.settings.broadphase = mode;
                return makeChapter05Pipeline(world, chooseStepOrder(world), search);
            });
        }
    }
}

}  // namespace

TEST_CASE("through chapter 5: chapter 1's promises hold", "[ch05][earlier]") { checkThroughChapter5(1); }
TEST_CASE("through chapter 5: chapter 2's promises hold", "[ch05][earlier]") { checkThroughChapter5(2); }
TEST_CASE("through chapter 5: chapter 3's promises hold", "[ch05][earlier]") { checkThroughChapter5(3); }
TEST_CASE("through chapter 5: chapter 4's promises hold", "[ch05][earlier]") { checkThroughChapter5(4); }
