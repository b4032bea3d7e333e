// Every earlier promise through chapter 11's pipeline, with the wide and the scalar path.
#include "11_wide_solve/chapter.h"
#include "promises/promises.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("through chapter 11: the promises of chapters 1 to 4 hold", "[ch11][earlier]") {
    const int chapter = GENERATE(1, 2, 3, 4);
    std::vector<test::PipelineVariant> variants;
    for (SolverPath path : {SolverPath::Wide, SolverPath::Scalar}) {
        WideSolveOptions wide;
        wide.solverPath = path;
        variants.push_back({std::string("chapter 11, ") + toString(path), [wide](World& world, ContactSearch) {
                                return makeChapter11Pipeline(world, SkipWorkOptions{}, wide);
                            }});
    }
    test::checkPromisesOfChapter(chapter, variants);
}
