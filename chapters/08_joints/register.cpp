// Chapter 8 in the programs: the pipeline with joints and kinematic paths, the sandbox and joint
// gallery scenes, and the joints bench.
#include "08_joints/benches.h"
#include "08_joints/chapter.h"
#include "08_joints/scenes.h"
#include "app/registry.h"

namespace stepwise {

void registerChapter08(Registry& registry) {
    registry.addChapter({8, addChapter08Scenes, [](const World& world) { return makeChapter08Pipeline(world); },
                         {jointsBench()}});
    registry.addPenetrationProbe(PenetrationProbe{8, measureDeepestCollidingPenetration});
}

}  // namespace stepwise
