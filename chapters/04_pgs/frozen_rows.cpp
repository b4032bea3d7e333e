#include "04_pgs/frozen_rows.h"

#include "04_pgs/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "04_pgs/scenes.h"

#include <algorithm>

namespace stepwise {

FrozenRows freezeSpherePitRows(int sphereCount, int frames) {
    World world = buildSpherePitScene(sphereCount);
    Pipeline pipeline = makeChapter04Pipeline(world);
    for (int frame = 0; frame < frames; ++frame) pipeline.step(world);
    const Real dt = world.settings.dt / static_cast<Real>(std::max(1, world.settings.substeps));
    world.step.substep = 0;
    for (Stage& stage : pipeline.stages()) {
        if (stageGroup(stage.name) == stage_group::kSolve) break;
        if (stage.enabled) stage.run(world, dt);
    }
    FrozenRows frozen;
    frozen.bodies = gatherSolverBodies(world);
    frozen.rows = buildContactRows(world, frozen.bodies, dt).rows;
    return frozen;
}

}  // namespace stepwise
