// Chapter 13 in the programs: its pipeline, its scenes and `stepwise bench worlds`.
#include "13_worlds/bench_worlds.h"
#include "13_worlds/chapter.h"
#include "13_worlds/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter13(Registry& registry) {
    registry.addChapter({13, addChapter13Scenes, [](const World& world) { return makeChapter13Pipeline(world); },
                         {worldsBench()}});
}

}  // namespace stepwise
