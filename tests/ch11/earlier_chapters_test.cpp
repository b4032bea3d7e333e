// Every earlier promise through chapter 11's pipeline. The scalar path gives the wide path's bits
// (fast_solve_test.cpp), so the promises run through the wide one.
#include "11_wide_solve/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("through chapter 11: the promises of chapters 1 to 4 hold", "[ch11][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(
        chapter, {{"chapter 11", [](World& world, ContactSearch) { return makeChapter11Pipeline(world); }}});
}
