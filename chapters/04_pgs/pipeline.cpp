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

std::string solveStageName(SolverKind kind) {
    return stageName(stage_group::kSolve, kind == SolverKind::Jacobi ? "jacobi" : "pgs");
}

Pipeline makeChapter04Pipeline(const World& world) { return makeChapter04Pipeline(world, chooseStepOrder(world)); }

// [ch04-pipeline]
namespace {

std::vector<BodyVelocity> currentVelocities(const World& world) {
    std::vector<BodyVelocity> velocities(world.bodies.size());
    for (const Motion& motion : world.motions)
        velocities[motion.bodyIndex] = BodyVelocity{motion.linearVelocity, motion.angularVelocity};
    return velocities;
}

// The solve, once per substep. When the contacts were found at the start of the frame, their
// points move with their bodies first from the second substep on. The velocities from before the
// forces are used once and cleared, so a disabled velocity stage cannot leave stale ones behind.
void solveStage(World& world, Real dt) {
    if (world.step.substep > 0 && world.step.contactsFoundAtSubstep < world.step.substep) followContactAnchors(world);
    solveContacts(world, dt);
    world.step.velocitiesBeforeForces.clear();
}

}  // namespace

Pipeline makeChapter04Pipeline(const World& world, StepOrder order, ContactSearch search) {
    Pipeline pipeline = makeChapter03Pipeline(world, search);

    Stage solve;
    solve.name = solveStageName(world.settings.solver);
    // The stage reads Settings::solver every step, so the demo's toggle takes effect at once; the
    // name says which solver the world asked for when the pipeline was planned.
    solve.run = solveStage;

    // After the frame's last solve, the cache keeps only the points that carried load.
    Stage upkeep;
    upkeep.name = stageName(stage_group::kContacts, "drop_unloaded");
    upkeep.frequency = StageFrequency::FrameEnd;
    upkeep.run = [](World& stepWorld, Real) { stepWorld.step.contactPointsDropped = dropUnloadedContactPoints(stepWorld); };

    if (order == StepOrder::IntegrateFirst) {
        pipeline.add(std::move(solve));
        pipeline.add(std::move(upkeep));
        return pipeline;
    }

    // Split semi-implicit Euler around the solve. The velocity half takes the integrate stage's
    // place (before collision detection, which does not move anything) and first keeps a copy of
    // the velocities for restitution; the position half runs after the solve, with the velocities
    // the solver produced. A resting body then sits at exactly the slop (the page measures both
    // orders).
    Stage velocities;
    velocities.name = stageName(stage_group::kIntegrate, "velocities");
    velocities.run = [](World& stepWorld, Real dt) {
        stepWorld.step.velocitiesBeforeForces = currentVelocities(stepWorld);
        applyForces(stepWorld);
        integrateVelocities(stepWorld, dt);
    };
    Stage positions;
    positions.name = stageName(stage_group::kIntegrate, "positions");
    positions.run = [](World& stepWorld, Real dt) { integratePositions(stepWorld, dt); };

    if (Stage* integrateStage = pipeline.find(stage_group::kIntegrate))
        *integrateStage = std::move(velocities);
    else
        pipeline.insertBefore(stage_group::kNarrowphase, std::move(velocities));
    pipeline.add(std::move(solve));
    pipeline.add(std::move(positions));
    pipeline.add(std::move(upkeep));
    return pipeline;
}
// [ch04-pipeline]

}  // namespace stepwise
