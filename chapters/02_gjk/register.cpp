// Chapter 2 registers its demo scenes, its pipeline (chapter 1's + narrowphase:gjk) and the
// GJK bench.
#include "02_gjk/bench_gjk.h"
#include "02_gjk/chapter.h"
#include "02_gjk/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter02(Registry& registry) {
    registry.addChapter({2, addChapter02Scenes, makeChapter02Pipeline, {gjkBench()}});
}

}  // namespace stepwise
