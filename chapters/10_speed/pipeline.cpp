#include "10_speed/chapter.h"

#include <memory>
#include <cstdlib>

namespace stepwise {

Pipeline makeChapter10Pipeline(const World& world) { return makeChapter10Pipeline(world, SpeedOptions{}); }

// [ch10-pipeline]
Pipeline makeChapter10Pipeline(const World& world, const SpeedOptions& options) {
    Pipeline pipeline = makeChapter08Pipeline(world);
    std::string why;
    if (!options.fastSolve) {
        pipeline.setPlanNote(stage_group::kSolve, "chapter 8's solve: the fast solve is switched off");
    } else if (!fastSolveApplies(world, &why)) {
        pipeline.setPlanNote(stage_group::kSolve, "chapter 8's solve: " + why);
    } else if (Stage* solve = pipeline.find(stage_group::kSolve)) {
        solve->name = stageName(stage_group::kSolve, std::string(toString(options.solverPath)) + "_" +
                                                         toString(world.settings.stabilisation));
        // Scratch buffers only: rebuilt from the World every frame, they carry nothing between
        // frames (a copied World steps the same), and spare the allocation per step.
        auto scratch = std::make_shared<ContactSolverScratch>();
        SolverPath debugPath = getenv("SCALAR") ? SolverPath::Scalar : options.solverPath;
        solve->run = [scratch, path = debugPath](World& stepWorld, Real dt) {
            solveFast(stepWorld, dt, path, *scratch);
        };
        pipeline.setPlanNote(stage_group::kSolve, std::string(toString(options.solverPath)) +
                                                      ": no joints, springs, dampings or kinematic bodies");
    }
    return pipeline;
}
// [ch10-pipeline]

}  // namespace stepwise
