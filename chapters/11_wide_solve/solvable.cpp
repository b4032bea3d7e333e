// Which worlds and which contact records chapter 11's solve takes, and the plan of a solve without
// a planner (the scene's count). Chapter 12's planner reads the same list of contacts the solve
// builds (collectSolvableContacts).
#include "11_wide_solve/contact_solver.h"

#include "01_integrators/methods.h"
#include "06_manifolds/stabilisation.h"
#include "10_skip_work/sleep.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

bool fastSolveApplies(const World& world, std::string* why) {
    auto refuse = [&](const char* reason) {
        if (why) *why = reason;
        return false;
    };
    const Settings& settings = world.settings;
    if (!isSubstepped(settings.stabilisation)) return refuse("the stabilisation is not relax or soft_step");
    if (settings.solver != SolverKind::GaussSeidel) return refuse("the solver is Jacobi");
    if (settings.gyroscopic == GyroscopicMode::Explicit) return refuse("the gyroscopic term is explicit");
    if (settings.integrator != IntegratorKind::SemiImplicitEuler) return refuse("the integrator is not semi-implicit Euler");
    for (const Motion& motion : world.motions)
        if (motion.integrator && *motion.integrator != IntegratorKind::SemiImplicitEuler)
            return refuse("a body uses another integrator");
    return true;
}

bool validContactRecord(const World& world, const Contact& contact) {
    const int count = static_cast<int>(world.bodies.size());
    if (contact.bodyA < 0 || contact.bodyB < 0 || contact.bodyA >= count || contact.bodyB >= count) return false;
    if (contact.pointCount <= 0 || contact.pointCount > 4 || contact.bodyA == contact.bodyB) return false;
    // x - x is 0 for every finite x and NaN otherwise: one sum says whether all of them are finite
    // (the planner and the solve both ask, for every contact, every frame).
    Real probe = (contact.normal - contact.normal).sum();
    for (int i = 0; i < contact.pointCount; ++i) {
        const ContactPoint& point = contact.points[i];
        probe += (point.pointA - point.pointA).sum() + (point.pointB - point.pointB).sum() + (point.depth - point.depth);
    }
    if (probe != 0) return false;
    return std::abs(contact.normal.norm() - 1) <= Real(1e-3);
}

bool solvableContact(const World& world, const Contact& contact) {
    return validContactRecord(world, contact) &&
           (isAwakeDynamic(world, contact.bodyA) || isAwakeDynamic(world, contact.bodyB));
}

void collectSolvableContacts(const World& world, std::vector<int>& order) {
    order.clear();
    for (std::size_t i = 0; i < world.contacts.size(); ++i)
        if (solvableContact(world, world.contacts[i])) order.push_back(static_cast<int>(i));
}

bool fastSolvePlans(const World& world, Real dt) {
    // Something awake moves: a dynamic body, or a kinematic one that the substeps carry.
    return dt > 0 && std::isfinite(dt) && !everyBodyAsleep(world);
}

// [ch11-plan-scene-count]
void planSceneCount(World& world) {
    IterationPlan& plan = world.step.iterationPlan;
    plan.previousIterations = plan.iterations;
    plan.iterations = std::max(1, world.settings.solverIterations);
    plan.plainIterations = plan.iterations;
    plan.shockPropagation = false;
    plan.relaxOnlyAfterPush = false;
}
// [ch11-plan-scene-count]

}  // namespace stepwise
