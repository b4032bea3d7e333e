// Chapter 10 in the programs: the fast pipeline.
#include "10_speed/chapter.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter10(Registry& registry) {
    registry.addChapter({10, [](Registry&) {}, [](const World& world) { return makeChapter10Pipeline(world); }, {}});
}

}  // namespace stepwise
