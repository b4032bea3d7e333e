// Chapter 11's scenes.
#include "11_wide_solve/scenes.h"

#include "10_skip_work/scenes.h"

namespace stepwise {

void addChapter11Scenes(Registry& registry) {
    registry.addScene({"wide-pyramid", 11, "11 the wide solve", prose(R"(
        a 30-row pyramid (465 boxes) stands; the panel shows the colours, the wide blocks and the
        overflow, and the solve's time with the wide path on and off)"),
                       [] { return buildPyramidRow(1, 30); }, {}});
}

}  // namespace stepwise
