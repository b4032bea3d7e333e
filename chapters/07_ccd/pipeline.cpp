#include "07_ccd/chapter.h"

#include <memory>

namespace stepwise {

Pipeline makeChapter07Pipeline(const World& world) { return makeChapter07Pipeline(world, makeChapter06Pipeline(world)); }

// [ch07-pipeline]
Pipeline makeChapter07Pipeline(const World& world, Pipeline chapter6) {
    Pipeline pipeline = std::move(chapter6);
    const CcdPlan plan = planContinuousCollision(world);
    pipeline.setPlanNote(stage_group::kCcd, plan.reason);
    if (plan.included) addContinuousCollision(pipeline);
    return pipeline;
}

void addContinuousCollision(Pipeline& pipeline) {
    // Where each body starts the substep: one end of its sweep. Kept in the world, so a copy of
    // the world mid-step carries it.
    Stage sweepStart;
    sweepStart.name = stageName(stage_group::kCcd, "sweep_start");
    sweepStart.run = [](World& world, Real) {
        std::vector<Transform>& start = world.step.ccd.sweepStart;
        start.resize(world.bodies.size());
        for (std::size_t i = 0; i < world.bodies.size(); ++i) start[i] = world.bodies[i].transform;
    };
    // After everything else has moved the bodies: the sorted time-of-impact loop over the
    // sweeps. Settings::ccd is read every step, so the demo's toggle acts at once.
    Stage toi;
    toi.name = stageName(stage_group::kCcd, "toi");
    // Working memory only, rebuilt every step: a copied World steps the same.
    toi.run = [scratch = std::make_shared<ToiLoopScratch>()](World& world, Real dt) {
        if (world.settings.ccd != CcdMode::Off) resolveTimesOfImpact(world, dt, *scratch);
    };
    std::vector<Stage>& stages = pipeline.stages();
    stages.insert(stages.begin(), std::move(sweepStart));
    pipeline.add(std::move(toi));
}
// [ch07-pipeline]

}  // namespace stepwise
