// Chapter 10 in the programs: the pipeline that skips work, and its scenes.
#include "10_skip_work/chapter.h"
#include "10_skip_work/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter10(Registry& registry) {
    registry.addChapter({10, addChapter10Scenes, [](const World& world) { return makeChapter10Pipeline(world); }, {}});
}

}  // namespace stepwise
