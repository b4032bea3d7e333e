// solver_iterations "auto": the substep count from the touching mass ratio (iteration_plan.h).
#include "10_speed/iteration_plan.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

int supportDepth(const World& world, const std::vector<int>& contactOrder, StackSearch& search) {
    // A stack deeper than kPlainStackDepth has at least that many contacts: small scenes skip
    // the search.
    if (static_cast<int>(contactOrder.size()) < kPlainStackDepth) return 0;
    const std::size_t bodyCount = world.bodies.size();
    const auto isDynamic = [&](int body) { return world.bodies[static_cast<std::size_t>(body)].type == BodyType::Dynamic; };
    // The contact graph as adjacency lists in two flat arrays (compressed rows).
    std::vector<int>& start = search.start;
    start.assign(bodyCount + 1, 0);
    for (const int index : contactOrder) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(index)];
        ++start[static_cast<std::size_t>(contact.bodyA) + 1];
        ++start[static_cast<std::size_t>(contact.bodyB) + 1];
    }
    for (std::size_t body = 0; body < bodyCount; ++body) start[body + 1] += start[body];
    search.neighbours.resize(static_cast<std::size_t>(start[bodyCount]));
    search.fill.assign(start.begin(), start.end() - 1);
    for (const int index : contactOrder) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(index)];
        search.neighbours[static_cast<std::size_t>(search.fill[static_cast<std::size_t>(contact.bodyA)]++)] = contact.bodyB;
        search.neighbours[static_cast<std::size_t>(search.fill[static_cast<std::size_t>(contact.bodyB)]++)] = contact.bodyA;
    }
    // Breadth first from the supports: a body's depth is its layer.
    std::vector<int>& depth = search.depth;
    std::vector<int>& queue = search.queue;
    depth.assign(bodyCount, 0);
    queue.clear();
    for (std::size_t body = 0; body < bodyCount; ++body)
        if (!isDynamic(static_cast<int>(body)) && start[body + 1] > start[body]) queue.push_back(static_cast<int>(body));
    int deepest = 0;
    for (std::size_t next = 0; next < queue.size(); ++next) {
        const int body = queue[next];
        for (int k = start[static_cast<std::size_t>(body)]; k < start[static_cast<std::size_t>(body) + 1]; ++k) {
            const int other = search.neighbours[static_cast<std::size_t>(k)];
            if (!isDynamic(other) || depth[static_cast<std::size_t>(other)] > 0) continue;
            depth[static_cast<std::size_t>(other)] = depth[static_cast<std::size_t>(body)] + 1;
            deepest = std::max(deepest, depth[static_cast<std::size_t>(other)]);
            queue.push_back(other);
        }
    }
    return deepest;
}

// [ch10-iteration-plan]
int plannedIterations(const World& world, const std::vector<int>& contactOrder, IterationPlan& plan,
                      StackSearch& search) {
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
    plan.stackDepth = supportDepth(world, contactOrder, search);
    if (settings.planIterations && plan.stackDepth > kPlainStackDepth) {
        // Measured on pyramids of 1 m boxes (docs/ch10_speed.md): 40 rows move their top boxes
        // 2.6 cm at ten substeps, 1.2 cm at 15, 0.6 cm at 20: ten per 20 rows. Only while they
        // settle was tried and is worse: changing the count changes how deep a resting contact
        // sits, and a stack switched between counts is pumped into swaying.
        const int wanted = (scene * plan.stackDepth + kPlainStackDepth - 1) / kPlainStackDepth;
        iterations = std::max(iterations, std::min(scene * kMostIterationFactor, wanted));
    }
    plan.iterations = iterations;
    plan.mostIterations = std::max(plan.mostIterations, iterations);
    plan.largestRatio = std::max(plan.largestRatio, plan.massRatio);
    plan.deepestStack = std::max(plan.deepestStack, plan.stackDepth);
    return iterations;
}
// [ch10-iteration-plan]

}  // namespace stepwise
