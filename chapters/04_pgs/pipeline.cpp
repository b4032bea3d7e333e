#include "04_pgs/chapter.h"

#include "01_integrators/integrate.h"
#include "03_epa/chapter.h"
#include "04_pgs/contact_constraints.h"

#include <memory>

namespace stepwise {

const char* toString(StepOrder order) {
    return order == StepOrder::IntegrateFirst ? "integrate_first" : "split_integration";
}

StepOrder chooseStepOrder(const World& world) {
    return integratorLabel(world) == std::string(toString(IntegratorKind::SemiImplicitEuler))
               ? StepOrder::SplitIntegration
               : StepOrder::IntegrateFirst;
}

const char* solveStageName(SolverKind kind) {
    return kind == SolverKind::Jacobi ? "solve:jacobi" : "solve:pgs";
}

Pipeline makeChapter04Pipeline(const World& world) { return makeChapter04Pipeline(world, chooseStepOrder(world)); }

// [ch04-pipeline]
namespace {

// The solve stage as a named callable, so lastSolveStats() can find what it measured.
struct SolveStage {
    // The velocities from before this step's forces, for restitution's approach speed. The
    // velocity stage fills them, the solve stage uses them once and clears them (so a disabled
    // velocity stage cannot leave stale ones behind).
    std::shared_ptr<std::vector<SolverBody>> approach;
    std::shared_ptr<SolveStats> stats;

    void operator()(World& world, Real dt) const {
        *stats = solveContacts(world, dt, approach->empty() ? nullptr : approach.get());
        approach->clear();
    }
};

}  // namespace

Pipeline makeChapter04Pipeline(const World& world, StepOrder order) {
    Pipeline pipeline = makeChapter03Pipeline(world);

    auto approach = std::make_shared<std::vector<SolverBody>>();

    Stage solve;
    solve.name = solveStageName(world.settings.solver);
    // The stage reads Settings::solver every step, so the demo's toggle takes effect at once; the
    // name says which solver the world asked for when the pipeline was planned.
    solve.run = SolveStage{approach, std::make_shared<SolveStats>()};

    if (order == StepOrder::IntegrateFirst) {
        pipeline.add(std::move(solve));
        return pipeline;
    }

    // Split semi-implicit Euler around the solve. The velocity half takes the integrate stage's
    // place (before collision detection, which does not move anything) and first keeps a copy of
    // the velocities for restitution; the position half runs last, with the velocities the solver
    // produced. A resting body then sits at exactly the slop (the page measures both orders).
    Stage velocities;
    velocities.name = "integrate:velocities";
    velocities.run = [approach](World& stepWorld, Real dt) {
        *approach = gatherSolverBodies(stepWorld);
        applyForces(stepWorld);
        integrateVelocities(stepWorld, dt);
    };
    Stage positions;
    positions.name = "integrate:positions";
    positions.run = [](World& stepWorld, Real dt) { integratePositions(stepWorld, dt); };

    if (Stage* integrateStage = pipeline.find("integrate"))
        *integrateStage = std::move(velocities);
    else
        pipeline.insertBefore("narrowphase", std::move(velocities));
    pipeline.add(std::move(solve));
    pipeline.add(std::move(positions));
    return pipeline;
}
// [ch04-pipeline]

const SolveStats* lastSolveStats(const Pipeline& pipeline) {
    const Stage* stage = pipeline.find("solve");
    const SolveStage* solve = stage ? stage->run.target<SolveStage>() : nullptr;
    return solve ? solve->stats.get() : nullptr;
}

}  // namespace stepwise
