// Chapter 9 in the programs: chapter 8's pipeline (the chapter adds tools, not a stage), the
// debugging scenes, the history and ray cast bench, and `stepwise record` / `stepwise replay`.
#include "08_joints/chapter.h"
#include "09_debug/benches.h"
#include "09_debug/commands.h"
#include "09_debug/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter09(Registry& registry) {
    registry.addChapter({9, addChapter09Scenes, [](const World& world) { return makeChapter08Pipeline(world); },
                         {debugBench()}});
    registry.addCommand(CommandEntry{9, installRecordCommand});
    registry.addCommand(CommandEntry{9, installReplayCommand});
}

}  // namespace stepwise
