// Chapter 10 in the programs: the fast pipeline, its scenes and `stepwise bench speed`.
#include "10_speed/benches.h"
#include "10_speed/chapter.h"
#include "10_speed/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter10(Registry& registry) {
    registry.addChapter({10, addChapter10Scenes, [](const World& world) { return makeChapter10Pipeline(world); },
                         {speedBench()}});
}

}  // namespace stepwise
