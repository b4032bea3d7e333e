// Every earlier promise through chapter 10's pipeline: skipping work changes the cost, not the answer.
#include "10_skip_work/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("through chapter 10: the promises of chapters 1 to 4 hold", "[ch10][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(
        chapter, {{"chapter 10", [](World& world, ContactSearch) { return makeChapter10Pipeline(world); }}});
}
