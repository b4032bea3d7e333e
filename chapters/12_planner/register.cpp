// Chapter 12 in the programs: the planned pipeline, its scenes and `stepwise bench speed`.
#include "12_planner/benches.h"
#include "12_planner/chapter.h"
#include "12_planner/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter12(Registry& registry) {
    registry.addChapter({12, addChapter12Scenes, [](const World& world) { return makeChapter12Pipeline(world); },
                         {speedBench()}});
}

}  // namespace stepwise
