// Every earlier promise through chapter 12's pipeline: the planner's substeps and the shock sweep.
// (With the wide solve off, chapter 12 runs chapter 10's pipeline, whose suite runs them too.)
#include "12_planner/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("through chapter 12: the promises of chapters 1 to 4 hold", "[ch12][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(
        chapter, {{"chapter 12", [](World& world, ContactSearch) { return makeChapter12Pipeline(world); }}});
}
