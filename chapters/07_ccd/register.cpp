// Chapter 7 in the programs: the pipeline with continuous collision when a scene needs it, the
// gun scenes with their view, and the ccd bench.
#include "07_ccd/benches.h"
#include "07_ccd/chapter.h"
#include "07_ccd/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter07(Registry& registry) {
    registry.addChapter({7, addChapter07Scenes, [](const World& world) { return makeChapter07Pipeline(world); },
                         {ccdBench()}});
}

}  // namespace stepwise
