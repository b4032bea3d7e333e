// Chapter 11's scenes.
#include "11_wide_solve/scenes.h"

#include "10_skip_work/scenes.h"

namespace stepwise {

void addChapter11Scenes(Registry& registry) {
    registry.addScene({"wide-pyramid", 11, "11 the wide solve", prose(R"(
        a 30-row pyramid (465 boxes) stands on the wide solve; the performance monitor shows each
        stage's time, the solve's among them, until the settled pyramid falls asleep)"),
                       [] { return buildPyramidRow(1, 30); }, {}});
}

}  // namespace stepwise
