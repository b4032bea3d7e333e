#pragma once
// The scenario promises of the earlier chapters, each written once as a function of the
// pipeline under test, so that every later chapter re-runs them through its own pipeline
// (tests/ch05/earlier_chapters_test.cpp, and on) instead of copying them. A promise checks
// with Catch2's macros, so it runs inside a TEST_CASE of the suite that calls it.
//
//   test::checkPromisesOfChapter(4, {{"chapter 5", [](World& world, ContactSearch search) {
//       return makeChapter05Pipeline(world, chooseStepOrder(world), search); }}});

#include "04_pgs/chapter.h"

#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

namespace stepwise::test {

/// Makes the pipeline under test for a world built by the promise. `search` is chapter 4's
/// contact search (every substep or once per frame); a pipeline without the choice ignores it.
using PipelineMaker = std::function<Pipeline(World& world, ContactSearch search)>;

struct Promise {
    int chapter;          // the chapter whose suite first made it
    const char* claim;    // what holds, in words (the test's INFO line)
    void (*check)(const PipelineMaker& makePipeline);
};

/// The promises chapter `chapter` made about its scenes, in the order of its page.
std::vector<Promise> promisesOfChapter(int chapter);

/// One configuration of the pipeline under test ("broadphase sap", "one point"), named in the
/// INFO line of every failure so the report says which configuration broke a promise.
struct PipelineVariant {
    std::string name;
    PipelineMaker make;
};

/// One variant per value of a switch of the pipeline under test (a setting, an option): named
/// `nameOf(value)`, made by `make(value, world, search)`.
template <class Value, class NameOf, class Make>
std::vector<PipelineVariant> variantsOver(std::initializer_list<Value> values, NameOf nameOf, Make make) {
    std::vector<PipelineVariant> variants;
    for (Value value : values)
        variants.push_back({nameOf(value), [value, make](World& world, ContactSearch search) { return make(value, world, search); }});
    return variants;
}

/// Checks every promise of `chapter` through each variant: what a later chapter's
/// earlier_chapters_test runs, one TEST_CASE per earlier chapter.
void checkPromisesOfChapter(int chapter, const std::vector<PipelineVariant>& variants);

}  // namespace stepwise::test
