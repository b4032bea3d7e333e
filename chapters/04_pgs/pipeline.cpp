#include "04_pgs/chapter.h"

#include "01_integrators/integrate.h"
#include "03_epa/chapter.h"
#include "04_pgs/contact_constraints.h"

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
Pipeline makeChapter04Pipeline(const World& world, StepOrder order) {
    Pipeline pipeline = makeChapter03Pipeline(world);

    Stage solve;
    solve.name = solveStageName(world.settings.solver);
    // The stage reads Settings::solver every step, so the demo's toggle takes effect at once; the
    // name says which solver the world asked for when the pipeline was planned.
    solve.run = [](World& stepWorld, Real dt) { solveContacts(stepWorld, dt); };

    if (order == StepOrder::IntegrateFirst) {
        pipeline.add(std::move(solve));
        return pipeline;
    }

    // Split semi-implicit Euler around the solve. The velocity half takes the integrate stage's
    // place (before collision detection, which does not move anything); the position half runs
    // last, with the velocities the solver produced. A resting body then sits at exactly the slop
    // (see the page for the measurement against IntegrateFirst).
    Stage velocities;
    velocities.name = "integrate:velocities";
    velocities.run = [](World& stepWorld, Real dt) {
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

}  // namespace stepwise
