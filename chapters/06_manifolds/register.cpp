// Chapter 6 in the programs: the stacking scenes with their view, the pipeline with manifolds,
// warm starting and the chosen stabilisation, and the stacking bench.
#include "06_manifolds/benches.h"
#include "06_manifolds/chapter.h"
#include "06_manifolds/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter06(Registry& registry) {
    registry.addChapter({6, addChapter06Scenes, [](const World& world) { return makeChapter06Pipeline(world); },
                         {stackingBench()}});
}

}  // namespace stepwise
