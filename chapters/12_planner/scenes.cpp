// Chapter 12's scenes.
#include "12_planner/scenes.h"

#include "10_skip_work/scenes.h"

namespace stepwise {

void addChapter12Scenes(Registry& registry) {
    const char* category = "12 the planner";
    registry.addScene({"speed-pyramids", 12, category, prose(R"(
        ten 20-row pyramids (2,100 boxes) stand; the panel shows ms per stage and the plan:
        substeps, stack depth and whether the frame ends with a shock sweep)"),
                       [] { return buildPyramidRow(10, 20); }, {}});
    registry.addScene({"speed-pile", 12, category, prose(R"(
        2,000 mixed bodies fall into a pit and settle; the plan follows the mass ratios of what touches)"),
                       [] { return buildMixedPile(2000); }, {}});
}

}  // namespace stepwise
