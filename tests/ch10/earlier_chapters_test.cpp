// Every earlier promise through chapter 10's pipeline, with the fast solve wide and scalar, and with
// chapter 8's solve (the reference the bench compares against).
#include "10_speed/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

std::vector<test::PipelineVariant> throughChapter10() {
    std::vector<test::PipelineVariant> variants;
    SpeedOptions reference;
    reference.fastSolve = false;
    variants.push_back({"chapter 10, chapter 8's solve",
                        [reference](World& world, ContactSearch) { return makeChapter10Pipeline(world, reference); }});
    for (SolverPath path : {SolverPath::Wide, SolverPath::Scalar}) {
        SpeedOptions options;
        options.solverPath = path;
        variants.push_back({std::string("chapter 10, ") + toString(path),
                            [options](World& world, ContactSearch) { return makeChapter10Pipeline(world, options); }});
    }
    return variants;
}

}  // namespace

TEST_CASE("through chapter 10: the promises of chapters 1 to 4 hold", "[ch10][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    test::checkPromisesOfChapter(chapter, throughChapter10());
}
