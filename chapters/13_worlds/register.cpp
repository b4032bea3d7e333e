// Chapter 13 in the programs: its pipeline, its scenes, `stepwise bench worlds` and the demo's
// mesh-tree view.
#include "13_worlds/bench_worlds.h"
#include "13_worlds/chapter.h"
#include "13_worlds/scenes.h"
#include "13_worlds/tree_view.h"
#include "app/registry.h"

#include <memory>

namespace stepwise {

void registerChapter13(Registry& registry) {
    registry.addChapter({13, addChapter13Scenes, [](const World& world) { return makeChapter13Pipeline(world); },
                         {worldsBench()}});
    registry.addDebugOverlay({13, "mesh-tree", "dark red: near the root; yellow: deep",
                              kTreeViewLevels, [] {
                                  auto trees = std::make_shared<WorldShapesCache>();
                                  return [trees](DebugDraw& draw, const World& world, int level) {
                                      drawMeshTreeLevel(draw, world, level, *trees);
                                  };
                              }});
}

}  // namespace stepwise
