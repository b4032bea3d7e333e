// The promises of chapters 1 to 4 (tests/promises), kept through chapter 6's pipeline: each
// scenario claim of the earlier suites, run with manifolds, warm starting and the default
// stabilisation, once with up to four points per pair and once with chapter 3's one.
#include "06_manifolds/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

void checkThroughChapter6(int chapter) {
    const std::vector<test::Promise> promises = test::promisesOfChapter(chapter);
    REQUIRE(!promises.empty());
    for (const test::Promise& promise : promises) {
        for (bool multiPoint : {true, false}) {
            INFO("chapter " << chapter << ": " << promise.claim << " (" << (multiPoint ? "manifold" : "one point") << ")");
            promise.check([multiPoint](World& world, ContactSearch search) {
                ManifoldOptions options;
                options.multiPoint = multiPoint;
                return makeChapter06Pipeline(world, options, chooseStepOrder(world), search);
            });
        }
    }
}

}  // namespace

TEST_CASE("through chapter 6: chapter 1's promises hold", "[ch06][earlier]") { checkThroughChapter6(1); }
TEST_CASE("through chapter 6: chapter 2's promises hold", "[ch06][earlier]") { checkThroughChapter6(2); }
TEST_CASE("through chapter 6: chapter 3's promises hold", "[ch06][earlier]") { checkThroughChapter6(3); }
TEST_CASE("through chapter 6: chapter 4's promises hold", "[ch06][earlier]") { checkThroughChapter6(4); }
