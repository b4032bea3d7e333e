// Chapter 11 in the programs: the wide solve's pipeline and its scenes.
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter11(Registry& registry) {
    registry.addChapter({11, addChapter11Scenes, [](const World& world) { return makeChapter11Pipeline(world); }, {}});
}

}  // namespace stepwise
