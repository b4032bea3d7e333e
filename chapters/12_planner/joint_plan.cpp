// Chapter 12's plan for scenes with joints (declared in iteration_plan.h): chapter 8's solve takes
// the scene's count, or fewer where nothing stacks; the fast solve takes the contacts' count, then
// what the joints ask for: the sag law by their depth.
#include "12_planner/iteration_plan.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

int plannedJointSolveIterations(const World& world, Real dt, std::vector<int>& contacts, IterationPlan& plan,
                                StackSearch& search) {
    const Settings& settings = world.settings;
    const int scene = std::max(1, settings.solverIterations);
    const bool substepped =
        settings.stabilisation == Stabilisation::Relax || settings.stabilisation == Stabilisation::SoftStep;
    if (!settings.planIterations || world.joints.empty() || !world.springs.empty() || !substepped) {
        // The scene's own count, written into the plan: the solve stage runs what the plan says.
        plan.shockPropagation = false;
        plan.reason = PlanReason::SceneCount;
        plan.iterations = scene;
        plan.mostIterations = std::max(plan.mostIterations, scene);
        plan.fewestIterations = plan.fewestIterations > 0 ? std::min(plan.fewestIterations, scene) : scene;
        return scene;
    }
    contacts.clear();
    const auto bodyCount = static_cast<int>(world.bodies.size());
    for (std::size_t i = 0; i < world.contacts.size(); ++i) {
        const Contact& contact = world.contacts[i];
        if (contact.pointCount > 0 && contact.bodyA >= 0 && contact.bodyB >= 0 && contact.bodyA < bodyCount &&
            contact.bodyB < bodyCount)
            contacts.push_back(static_cast<int>(i));
    }
    const TouchSummary touches = summarizeTouches(world, contacts);
    plan.shockPropagation = false;  // chapter 8's solve has no shock sweep
    plan.stackDepth = supportDepth(world, contacts, search, /*withJoints=*/true);
    plan.plainIterations = scene;
    plan.massRatio = touches.massRatio;
    plan.largestRatio = std::max(plan.largestRatio, plan.massRatio);
    // Hanging alone with nothing touching is free flight on a leash: substeps of free flight's
    // length; touching the world as well, those of bodies resting on it.
    const Real longest = contacts.empty() ? kFreeFlightSubstep : touches.sliding ? kSlidingSubstep : kRestingSubstep;
    const bool onWorldAlone = plan.stackDepth <= 1 && !touches.bouncy;
    const int iterations = onWorldAlone ? std::min(scene, substepsFor(dt, longest)) : scene;
    plan.reason = !onWorldAlone || iterations == scene ? PlanReason::SceneCount
                  : contacts.empty()                   ? PlanReason::NothingTouches
                  : touches.sliding                    ? PlanReason::SlidesOnWorld
                                                       : PlanReason::RestsOnWorld;
    plan.iterations = iterations;
    plan.mostIterations = std::max(plan.mostIterations, iterations);
    plan.fewestIterations = plan.fewestIterations > 0 ? std::min(plan.fewestIterations, iterations) : iterations;
    plan.deepestStack = std::max(plan.deepestStack, plan.stackDepth);
    return iterations;
}

// [ch12-linked-plan]
int plannedLinkedIterations(const World& world, Real dt, const std::vector<int>& contactOrder, IterationPlan& plan,
                            StackSearch& search) {
    const bool linked = !world.joints.empty();
    const int contacts = plannedIterations(world, dt, contactOrder, plan, search, /*shockAllowed=*/!linked);
    const Settings& settings = world.settings;
    if (!linked || !settings.planIterations) return contacts;
    const int scene = std::max(1, settings.solverIterations);
    const Real perMeasuredFrame = dt / kMeasuredFrame;
    const int most = mostSubsteps(scene, perMeasuredFrame);
    // What hangs from the world by joints sags by its springs' give, which goes as the substep's
    // square (the spring is at most a quarter of the substep rate) and as the chain's depth: the
    // count that holds a chain of that depth to kHeldChainSag.
    int wanted = 1;
    PlanReason reason = PlanReason::HangingChain;
    static const std::vector<int> noContacts;
    const int hanging = supportDepth(world, noContacts, search, /*withJoints=*/true);
    if (hanging > 0) wanted = sagLawCount(scene, hanging, perMeasuredFrame);
    Real ratio = 1;
    bool bodyToBody = false;  // a joint between two dynamic bodies
    for (const JointDesc& joint : world.joints) {
        const Motion* a = joint.bodyA >= 0 ? world.motionOf(joint.bodyA) : nullptr;
        const Motion* b = joint.bodyB >= 0 ? world.motionOf(joint.bodyB) : nullptr;
        if (!a || !b || !(a->mass > 0) || !(b->mass > 0)) continue;
        if (world.bodies[static_cast<std::size_t>(joint.bodyA)].type != BodyType::Dynamic ||
            world.bodies[static_cast<std::size_t>(joint.bodyB)].type != BodyType::Dynamic)
            continue;
        bodyToBody = bodyToBody || !a->asleep || !b->asleep;
        ratio = std::max(ratio, std::max(a->mass, b->mass) / std::min(a->mass, b->mass));
    }
    if (ratio > kPlainMassRatio) {
        const int byRatio = squareRootLawCount(scene, ratio, perMeasuredFrame);
        if (byRatio > wanted) reason = PlanReason::MassRatio;
        wanted = std::max(wanted, byRatio);
    }
    // Bodies joined to bodies pass loads through their joints as a stack does. Resting on the
    // world, through contacts and joints d bodies deep, their joints give as a chain of that depth
    // does: the sag law above, at least kFewestJointedSubsteps (section 9). In the air nothing
    // measures how deep their loads pass (a ragdoll's limbs swing its trunk): the scene's count.
    const int depth = supportDepth(world, contactOrder, search, /*withJoints=*/true);
    if (bodyToBody || depth > 1) {
        const int jointed = depth > 1 ? std::max(kFewestJointedSubsteps, sagLawCount(scene, depth, perMeasuredFrame)) : scene;
        if (jointed > wanted) {
            wanted = jointed;
            reason = PlanReason::JointedBodies;
        }
    }
    const int iterations = std::max(contacts, std::min(most, wanted));
    if (std::min(most, wanted) > contacts) plan.reason = reason;
    plan.massRatio = std::max(plan.massRatio, ratio);
    plan.largestRatio = std::max(plan.largestRatio, plan.massRatio);
    plan.stackDepth = std::max(plan.stackDepth, depth);
    plan.deepestStack = std::max(plan.deepestStack, plan.stackDepth);
    plan.iterations = iterations;
    plan.mostIterations = std::max(plan.mostIterations, iterations);
    plan.fewestIterations = std::min(plan.fewestIterations, iterations);
    return iterations;
}
// [ch12-linked-plan]

}  // namespace stepwise
