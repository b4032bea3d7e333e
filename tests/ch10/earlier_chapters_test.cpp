// Every earlier promise through chapter 10's pipeline as registered (chapter 8's solve until the
// fast solve is the default), and through the fast solve, wide and scalar, for the promises it
// keeps today: chapters 1 to 3. Chapter 4's bounce heights are its known gap (docs/ch10_speed.md).
#include "10_speed/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

std::vector<test::PipelineVariant> throughChapter10() {
    std::vector<test::PipelineVariant> variants;
    for (SolverPath path : {SolverPath::Wide, SolverPath::Scalar}) {
        SpeedOptions options;
        options.fastSolve = true;
        options.solverPath = path;
        variants.push_back({std::string("chapter 10, ") + toString(path),
                            [options](World& world, ContactSearch) { return makeChapter10Pipeline(world, options); }});
    }
    return variants;
}

}  // namespace

TEST_CASE("through chapter 10: the promises of chapters 1 to 4 hold", "[ch10][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(
        chapter, {{"chapter 10", [](World& world, ContactSearch) { return makeChapter10Pipeline(world); }}});
}

TEST_CASE("through chapter 10's fast solve: the promises of chapters 1 to 3 hold", "[ch10][earlier]") {
    const int chapter = GENERATE(1, 2, 3);
    test::checkPromisesOfChapter(chapter, throughChapter10());
}
