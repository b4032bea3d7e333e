// Chapter 3 registers its demo scenes, its pipeline (chapter 2's with a contact-making
// narrowphase), the penetration probe of run reports, the EPA bench and `stepwise collide`.
#include "03_epa/bench_epa.h"
#include "03_epa/chapter.h"
#include "03_epa/collide_command.h"
#include "03_epa/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter03(Registry& registry) {
    registry.addChapter({3, addChapter03Scenes, [](const World& world) { return makeChapter03Pipeline(world); }, {epaBench()}});
    registry.addPenetrationProbe(PenetrationProbe{3, measureDeepestPenetration});
    registry.addCommand(CommandEntry{3, installCollideCommand});
}

}  // namespace stepwise
