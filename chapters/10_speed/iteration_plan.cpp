// solver_iterations "auto": the substep count from the touching mass ratio (iteration_plan.h).
#include "10_speed/iteration_plan.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

// [ch10-iteration-plan]
int plannedIterations(const World& world, const std::vector<int>& contactOrder, IterationPlan& plan) {
    const Settings& settings = world.settings;
    const int scene = std::max(1, settings.solverIterations);
    Real lightest = kRealMax, heaviest = 0;
    for (const int index : contactOrder) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(index)];
        const Motion* a = world.motionOf(contact.bodyA);
        const Motion* b = world.motionOf(contact.bodyB);
        if (!a || !b || !(a->mass > 0) || !(b->mass > 0)) continue;  // static or kinematic
        lightest = std::min({lightest, a->mass, b->mass});
        heaviest = std::max({heaviest, a->mass, b->mass});
    }
    plan.massRatio = heaviest > 0 ? heaviest / lightest : Real(1);
    int iterations = scene;
    if (settings.planIterations && plan.massRatio > kPlainMassRatio) {
        // Measured on towers of four boxes, masses in geometric steps (docs/ch10_speed.md):
        // 1:300 stands from 15 substeps, 1:1000 from 25. The square root of the ratio over the
        // plain one gives 18 and 32.
        const Real wanted = Real(scene) * std::sqrt(plan.massRatio / kPlainMassRatio);
        iterations = std::min(scene * kMostIterationFactor, static_cast<int>(std::ceil(wanted)));
    }
    plan.iterations = iterations;
    plan.mostIterations = std::max(plan.mostIterations, iterations);
    plan.largestRatio = std::max(plan.largestRatio, plan.massRatio);
    return iterations;
}
// [ch10-iteration-plan]

}  // namespace stepwise
