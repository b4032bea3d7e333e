// solver_iterations "auto" (iteration_plan.h): the substep count from what touches: free flight,
// bodies resting on the world alone, bounces, touching mass ratios, stack depth.
#include "12_planner/iteration_plan.h"

#include "04_pgs/contact_constraints.h"
#include "11_wide_solve/lanes.h"
#include "11_wide_solve/joint_pass.h"
#include "12_planner/shock_propagation.h"
#include "10_skip_work/sleep.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

// [ch12-support-depth]
int supportDepth(const World& world, const std::vector<int>& contactOrder, StackSearch& search, bool withJoints) {
    if (contactOrder.empty() && (!withJoints || world.joints.empty())) return 0;
    const std::size_t bodyCount = world.bodies.size();
    const auto isDynamic = [&](int body) { return isDynamicBody(world, body); };
    if (contactOrder.empty()) {
        // Joints alone carry from a support only where one holds a body that does not move (a
        // chain's anchor); ragdolls in the air hang from nothing, and the search finds no layer.
        const auto anchored = [&](const JointDesc& joint) { return !isDynamic(joint.bodyA) || !isDynamic(joint.bodyB); };
        if (std::none_of(world.joints.begin(), world.joints.end(), anchored)) {
            search.depth.assign(bodyCount, 0);
            return 0;
        }
    }
    // The contact graph as adjacency lists in two flat arrays (compressed rows).
    std::vector<int>& start = search.start;
    start.assign(bodyCount + 1, 0);
    const auto validJoint = [&](const JointDesc& joint) {
        return withJoints && joint.bodyA >= 0 && joint.bodyB >= 0 && static_cast<std::size_t>(joint.bodyA) < bodyCount &&
               static_cast<std::size_t>(joint.bodyB) < bodyCount;
    };
    // A contact is read once: its two bodies go to a short list the links below read again.
    std::vector<int>& ends = search.ends;
    ends.clear();
    for (const int index : contactOrder) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(index)];
        ends.push_back(contact.bodyA);
        ends.push_back(contact.bodyB);
    }
    for (const int body : ends) ++start[static_cast<std::size_t>(body) + 1];
    for (const JointDesc& joint : world.joints) {
        if (!validJoint(joint)) continue;
        ++start[static_cast<std::size_t>(joint.bodyA) + 1];
        ++start[static_cast<std::size_t>(joint.bodyB) + 1];
    }
    for (std::size_t body = 0; body < bodyCount; ++body) start[body + 1] += start[body];
    search.neighbours.resize(static_cast<std::size_t>(start[bodyCount]));
    search.fill.assign(start.begin(), start.end() - 1);
    const auto link = [&](int a, int b) {
        search.neighbours[static_cast<std::size_t>(search.fill[static_cast<std::size_t>(a)]++)] = b;
        search.neighbours[static_cast<std::size_t>(search.fill[static_cast<std::size_t>(b)]++)] = a;
    };
    for (std::size_t k = 0; k < ends.size(); k += 2) link(ends[k], ends[k + 1]);
    for (const JointDesc& joint : world.joints)
        if (validJoint(joint)) link(joint.bodyA, joint.bodyB);
    // Breadth first from the supports: a body's depth is its layer. Whether a body is dynamic is
    // read once into a dense list, not once an edge from the large Body.
    std::vector<unsigned char>& dynamic = search.dynamic;
    dynamic.resize(bodyCount);
    for (std::size_t body = 0; body < bodyCount; ++body) dynamic[body] = world.bodies[body].type == BodyType::Dynamic;
    std::vector<int>& depth = search.depth;
    std::vector<int>& queue = search.queue;
    depth.assign(bodyCount, 0);
    queue.clear();
    for (std::size_t body = 0; body < bodyCount; ++body)
        if (!dynamic[body] && start[body + 1] > start[body]) queue.push_back(static_cast<int>(body));
    int deepest = 0;
    for (std::size_t next = 0; next < queue.size(); ++next) {
        const int body = queue[next];
        for (int k = start[static_cast<std::size_t>(body)]; k < start[static_cast<std::size_t>(body) + 1]; ++k) {
            const int other = search.neighbours[static_cast<std::size_t>(k)];
            if (!dynamic[static_cast<std::size_t>(other)] || depth[static_cast<std::size_t>(other)] > 0) continue;
            depth[static_cast<std::size_t>(other)] = depth[static_cast<std::size_t>(body)] + 1;
            deepest = std::max(deepest, depth[static_cast<std::size_t>(other)]);
            queue.push_back(other);
        }
    }
    return deepest;
}
// [ch12-support-depth]

namespace {

/// Whether a touching pair has a moving body that friction pushes along (last frame's impulses):
/// sliding, or rolling down a slope. Such a body accelerates, and Euler's step puts it h a t / 2
/// off its path; a body at rest, or rolling steadily on the level (no friction), does not.
bool slidesUnderFriction(const World& world, const Contact& contact) {
    Real normal = 0, tangent = 0;
    for (int i = 0; i < contact.pointCount; ++i) {
        normal += contact.points[i].normalImpulse;
        tangent += std::abs(contact.points[i].tangentImpulse[0]) + std::abs(contact.points[i].tangentImpulse[1]);
    }
    if (!(tangent > kFrictionAtRest * normal)) return false;
    for (const int body : {contact.bodyA, contact.bodyB}) {
        const Motion* motion = world.motionOf(body);
        if (motion && motion->linearVelocity.squaredNorm() > kRestingSpeed * kRestingSpeed) return true;
    }
    return false;
}

/// The velocity of `body`'s material point at `point` (world frame); zero for a static body.
Vec3 velocityAt(const World& world, int body, const Vec3& point) {
    const Motion* motion = world.motionOf(body);
    if (!motion) return Vec3::Zero();
    const Vec3 center = world.bodies[static_cast<std::size_t>(body)].transform.apply(motion->localCenter);
    return motion->linearVelocity + motion->angularVelocity.cross(point - center);
}

/// Whether a pair with restitution arrives this frame: one of its points closes faster than the
/// restitution threshold, so the solve reverses that speed. Balls that rest against one another
/// (a cradle between strikes) or that part after a bounce do not bounce again. Asked only of pairs
/// with restitution.
bool arrivesBouncing(const World& world, const Contact& contact) {
    for (int i = 0; i < contact.pointCount; ++i) {
        const Vec3 point = (contact.points[i].pointA + contact.points[i].pointB) * Real(0.5);
        const Real closing =
            (velocityAt(world, contact.bodyA, point) - velocityAt(world, contact.bodyB, point)).dot(contact.normal);
        if (closing > world.settings.restitutionThreshold) return true;
    }
    return false;
}

}  // namespace

TouchSummary summarizeTouches(const World& world, const std::vector<int>& contacts) {
    TouchSummary summary;
    Real lightest = kRealMax, heaviest = 0;
    for (const int index : contacts) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(index)];
        const bool restitution = combinedRestitution(world.bodies[static_cast<std::size_t>(contact.bodyA)].material,
                                                     world.bodies[static_cast<std::size_t>(contact.bodyB)].material) > 0;
        summary.restitution = summary.restitution || restitution;
        summary.bouncy = summary.bouncy || (restitution && arrivesBouncing(world, contact));
        summary.sliding = summary.sliding || slidesUnderFriction(world, contact);
        const Motion* a = world.motionOf(contact.bodyA);
        const Motion* b = world.motionOf(contact.bodyB);
        if (!a || !b || !(a->mass > 0) || !(b->mass > 0)) continue;  // static or kinematic
        lightest = std::min({lightest, a->mass, b->mass});
        heaviest = std::max({heaviest, a->mass, b->mass});
    }
    if (heaviest > 0) summary.massRatio = heaviest / lightest;
    return summary;
}


Real shockSweepSubsteps(const World& world, const std::vector<int>& contactOrder, StackSearch& search) {
    const std::vector<int>& depth = search.depth;
    const auto isDynamic = [&](int body) { return isDynamicBody(world, body); };
    // A contact the sweep takes: two dynamic bodies a layer apart (orderShockSweep); its layer is
    // the lower one's depth, and its upper body's contacts downwards split the layer into groups.
    const auto swept = [&](const Contact& contact) {
        return isDynamic(contact.bodyA) && isDynamic(contact.bodyB) &&
               depth[static_cast<std::size_t>(contact.bodyA)] != depth[static_cast<std::size_t>(contact.bodyB)];
    };
    const auto upperOf = [&](const Contact& contact) {
        const auto a = static_cast<std::size_t>(contact.bodyA), b = static_cast<std::size_t>(contact.bodyB);
        return depth[a] > depth[b] ? a : b;
    };
    search.downward.assign(world.bodies.size(), 0);
    int deepest = 0;
    for (const int index : contactOrder) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(index)];
        if (!swept(contact)) continue;
        ++search.downward[upperOf(contact)];
        deepest = std::max(deepest, depth[upperOf(contact)]);
    }
    search.layerLanes.assign(static_cast<std::size_t>(deepest) + 1, 0);
    search.layerGroups.assign(static_cast<std::size_t>(deepest) + 1, 0);
    for (const int index : contactOrder) {
        const Contact& contact = world.contacts[static_cast<std::size_t>(index)];
        if (!swept(contact)) continue;
        const std::size_t upper = upperOf(contact);
        const auto layer = static_cast<std::size_t>(depth[upper] - 1);
        ++search.layerLanes[layer];
        search.layerGroups[layer] = std::max(search.layerGroups[layer], search.downward[upper]);
    }
    // Priced as the first sweep built them: a group's lanes in wide blocks, a few left over one-lane blocks.
    const auto groupBlocks = [](int lanes) {
        const int leftOver = lanes % kPricedLanes;
        const Real last = leftOver >= kShockWideLanesAtLeast ? Real(1) : kShockLaneBlocks * static_cast<Real>(leftOver);
        return static_cast<Real>(lanes / kPricedLanes) + last;
    };
    Real shockBlocks = 0;
    for (std::size_t layer = 0; layer < search.layerLanes.size(); ++layer) {
        const int groups = search.layerGroups[layer];
        if (groups == 0) continue;
        const int lanesPerGroup = (search.layerLanes[layer] + groups - 1) / groups;
        shockBlocks += static_cast<Real>(groups) * groupBlocks(lanesPerGroup);
    }
    const Real frameLanes = static_cast<Real>(contactOrder.size());
    const Real frameBlocks = std::max(Real(1), std::ceil(frameLanes / static_cast<Real>(kPricedLanes)));
    return kShockBlockSubsteps * shockBlocks / frameBlocks;
}

int countOf(Real substeps) {
    // A hair under the value: 1/60 over 1/600 is 10.000001 in float, and means ten.
    return static_cast<int>(std::ceil(substeps - Real(1e-3)));
}

int substepsFor(Real dt, Real longest) { return std::max(1, countOf(dt / longest)); }

int mostSubsteps(int scene, Real perMeasuredFrame) {
    return countOf(Real(scene * kMostIterationFactor) * std::max(Real(1), perMeasuredFrame));
}

int squareRootLawCount(int scene, Real ratio, Real perMeasuredFrame) {
    return countOf(Real(scene) * std::sqrt(ratio / kPlainMassRatio) * perMeasuredFrame);
}

int sagLawCount(int scene, int depth, Real perMeasuredFrame) {
    const Real depths = static_cast<Real>(depth) / static_cast<Real>(kPlainChainDepth);
    return countOf(Real(scene) * std::sqrt(depths * kPlainChainSag / kHeldChainSag) * perMeasuredFrame);
}

// [ch12-iteration-plan]
int plannedIterations(const World& world, Real dt, const std::vector<int>& contactOrder, IterationPlan& plan,
                      StackSearch& search, bool shockAllowed) {
    const Settings& settings = world.settings;
    // Bodies that carry one another take the scene's count (auto: ten) in every solve: a load
    // crosses a contact layer a sweep, and a substep is a sweep however long it is.
    const int scene = std::max(1, settings.solverIterations);
    const TouchSummary touches = summarizeTouches(world, contactOrder);
    // The square-root law counts masses where one rests on another (load_paths.h), not wherever
    // two touch; whether a stack is of like masses (kLikeMassRatio) is still read off every touch.
    plan.massRatio = loadPathMassRatio(world, contactOrder, touches.massRatio, search.loads);
    plan.stackDepth = supportDepth(world, contactOrder, search);
    plan.plainIterations = scene;
    int iterations = scene;
    PlanReason reason = touches.bouncy ? PlanReason::Bounce : PlanReason::SceneCount;
    // The laws below hold a substep's length (kMeasuredFrame), and so does their ceiling.
    const Real perMeasuredFrame = dt / kMeasuredFrame;
    const int most = mostSubsteps(scene, perMeasuredFrame);
    if (settings.planIterations && contactOrder.empty()) {
        iterations = std::min(scene, substepsFor(dt, kFreeFlightSubstep));
        reason = PlanReason::NothingTouches;
    } else if (settings.planIterations && plan.stackDepth <= 1 && !touches.bouncy) {
        iterations = std::min(scene, substepsFor(dt, touches.sliding ? kSlidingSubstep : kRestingSubstep));
        reason = touches.sliding ? PlanReason::SlidesOnWorld : PlanReason::RestsOnWorld;
    }
    if (settings.planIterations && plan.massRatio > kPlainMassRatio) {
        // The square-root law (plan_constants.h, kPlainMassRatio).
        const int byRatio = std::min(most, squareRootLawCount(scene, plan.massRatio, perMeasuredFrame));
        if (byRatio > iterations) reason = PlanReason::MassRatio;
        iterations = std::max(iterations, byRatio);
    }
    plan.shockPropagation = false;
    plan.relaxOnlyAfterPush = false;
    if (settings.planIterations && plan.stackDepth > 1) {
        // The depth laws (plan_constants.h). The count holds while a stack rests too: changing it
        // changes how deep a resting contact sits, and a stack switched between counts is pumped.
        const Real rows = static_cast<Real>(plan.stackDepth) / static_cast<Real>(kPlainStackDepth);
        // A stack of like masses into which nothing arrives bouncing: the shock sweep ends the
        // frame where the walk law with it, plus the sweep's own cost, asks for fewer substeps
        // than the law without it (a pyramid from about 20 rows; never a column of single boxes).
        const auto count = [](Real substeps) {
            return std::max(kFewestStackSubsteps, countOf(substeps));
        };
        const Real plainLaw = Real(scene) * rows * rows * perMeasuredFrame;  // walks kPlainStackDrift
        const int plain = count(plainLaw * std::sqrt(kPlainStackDrift / kHeldStackDrift));
        const Real shockLaw = kShockStackSubsteps * math::pow(rows, kShockDepthExponent) * perMeasuredFrame;
        const int shocked = count(shockLaw);
        // [ch12-shock-price]
        // The sweep pays where, for the walk its law allows, it and its substeps cost less than
        // the substeps without it.
        const Real heldWalk = kHeldWalkPerBody * static_cast<Real>(plan.stackDepth);
        const Real plainForHeldWalk = plainLaw * std::sqrt(kPlainStackDrift / heldWalk);
        const bool likeAndQuiet = touches.massRatio <= kLikeMassRatio && !touches.bouncy;
        // The sweep costs at most every contact a one-lane block: where even that pays, the
        // blocks are not counted (a 40-row pyramid, six substeps against 22).
        const Real mostSweep = kShockBlockSubsteps * kShockLaneBlocks * static_cast<Real>(kPricedLanes);
        const auto sweepCost = [&] {
            return Real(shocked) + mostSweep < plainForHeldWalk ? mostSweep
                                                                : shockSweepSubsteps(world, contactOrder, search);
        };
        const bool sweepSaves =
            likeAndQuiet && Real(shocked) < plainForHeldWalk && Real(shocked) + sweepCost() < plainForHeldWalk;
        // [ch12-shock-price]
        plan.shockPropagation = sweepSaves && shockAllowed;
        // [ch12-one-sweep-substeps]
        // The swept stack's substeps relax only after a push (kOneSweepSubstepFactor), where the
        // solve lets them: restitution or a joint pass relaxes every substep (relaxSweepNeeded).
        plan.relaxOnlyAfterPush = sweepSaves && !touches.restitution && !needsJointPass(world);
        const int oneSweep = count(kOneSweepSubstepFactor * shockLaw);
        const int wanted = !sweepSaves ? plain : plan.relaxOnlyAfterPush ? oneSweep : shocked;
        // [ch12-one-sweep-substeps]
        // No fewer than kFewestStackSubsteps, nor than bodies resting on the world alone take.
        const int lengths = substepsFor(dt, touches.sliding ? kSlidingSubstep : kRestingSubstep);
        const int stack = std::min(most, std::max({kFewestStackSubsteps, lengths, wanted}));
        // Unlike masses, and a frame in which something arrives bouncing, keep at least the
        // scene's count (and the mass-ratio rule above); a deep stack more, whatever bounces on it.
        // A shallow heap of unlike masses takes the square-root law on the ratio its loads pass
        // through (load_paths.h), below kPlainMassRatio too, and at least kFewestUnlikeSubsteps:
        // the towers of sections 1 and 5 stand at it, and heaps no deeper than kShallowUnlikeDepth
        // sleep at it (section 9).
        const bool unlike = touches.massRatio > kLikeMassRatio;
        const bool shallowUnlike = unlike && !touches.bouncy && plan.stackDepth <= kShallowUnlikeDepth;
        const bool keepScene = (touches.bouncy || unlike) && !shallowUnlike;
        const PlanReason byDepth = sweepSaves ? PlanReason::ShockSweep : PlanReason::LikeStack;
        if (shallowUnlike) {
            const int ratioCount = std::min(
                most, std::max(kFewestUnlikeSubsteps, squareRootLawCount(scene, std::max(Real(1), plan.massRatio), perMeasuredFrame)));
            if (reason != PlanReason::MassRatio) reason = ratioCount > stack ? PlanReason::UnlikeStack : byDepth;
            iterations = std::max(stack, ratioCount);
        } else {
            if (!keepScene || stack > iterations) reason = byDepth;
            else if (reason != PlanReason::MassRatio) reason = touches.bouncy ? PlanReason::Bounce : PlanReason::UnlikeStack;
            iterations = keepScene ? std::max(iterations, stack) : stack;
        }
    }
    if (!settings.planIterations) reason = PlanReason::SceneCount;
    plan.reason = reason;
    plan.shockFrames += plan.shockPropagation ? 1 : 0;
    plan.iterations = iterations;
    plan.mostIterations = std::max(plan.mostIterations, iterations);
    plan.fewestIterations = plan.fewestIterations > 0 ? std::min(plan.fewestIterations, iterations) : iterations;
    plan.largestRatio = std::max(plan.largestRatio, plan.massRatio);
    plan.deepestStack = std::max(plan.deepestStack, plan.stackDepth);
    return iterations;
}
// [ch12-iteration-plan]

void tallyPlanReason(IterationPlan& plan) {
    plan.thresholds = {kPlainMassRatio, kPlainStackDepth, kFewestUnlikeSubsteps};
    PlanReasonTally& tally = plan.reasons[static_cast<std::size_t>(plan.reason)];
    tally.fewest = tally.frames > 0 ? std::min(tally.fewest, plan.iterations) : plan.iterations;
    tally.most = std::max(tally.most, plan.iterations);
    ++tally.frames;
}


}  // namespace stepwise
