// Chapter 2 registers its demo scenes, its pipeline (chapter 1's + narrowphase:gjk) and the
// GJK bench.
#include "02_gjk/bench_gjk.h"
#include "02_gjk/chapter.h"
#include "02_gjk/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter02(Registry& registry) {
    addChapter02Scenes(registry);
    registry.addPipeline(PipelineEntry{2, makeChapter02Pipeline});
    registry.addBench(gjkBench());
}

}  // namespace stepwise
