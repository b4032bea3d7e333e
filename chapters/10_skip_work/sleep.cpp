// Islands and sleeping (sleep.h): timers, islands by union-find, waking by union-find too.
#include "10_skip_work/sleep.h"

#include <memory>
#include <algorithm>
#include <numeric>
#include <sstream>

namespace stepwise {

bool isAwakeDynamic(const World& world, int bodyIndex) {
    return isDynamicBody(world, bodyIndex) && !world.motionOf(bodyIndex)->asleep;
}

namespace {

bool isSleeper(const World& world, int bodyIndex) {
    return isDynamicBody(world, bodyIndex) && world.motionOf(bodyIndex)->asleep;
}

// [ch10-union-find]
/// Union-find with path halving (Tarjan and van Leeuwen, JACM 1984): each find makes every other body
/// on its path point to its grandparent, so paths stay short; no recursion. The root of
/// a set is its smallest body index (joins keep the smaller root), so islands come out the same
/// whatever order the links arrive in.
int islandRoot(std::vector<int>& parent, int body) {
    while (parent[std::size_t(body)] != body) {
        parent[std::size_t(body)] = parent[std::size_t(parent[std::size_t(body)])];
        body = parent[std::size_t(body)];
    }
    return body;
}

void joinIslands(std::vector<int>& parent, int a, int b) {
    const int rootA = islandRoot(parent, a), rootB = islandRoot(parent, b);
    if (rootA < rootB) parent[std::size_t(rootB)] = rootA;
    else if (rootB < rootA) parent[std::size_t(rootA)] = rootB;
}
// [ch10-union-find]

void resetSleepScratch(const World& world, SleepScratch& scratch) {
    scratch.parent.resize(world.bodies.size());
    std::iota(scratch.parent.begin(), scratch.parent.end(), 0);
    scratch.flagged.assign(world.bodies.size(), 0);
}

/// Calls link(a, b) for every pair of bodies the step ties together: touching contacts
/// (pointCount > 0, speculative points included: a gap that closes this frame is a touch), joints,
/// and springs between two bodies. An island is what these links join.
template <class Link>
void forEachIslandLink(const World& world, Link link) {
    for (const Contact& contact : world.contacts)
        if (contact.pointCount > 0) link(contact.bodyA, contact.bodyB, true);
    for (const JointDesc& joint : world.joints) link(joint.bodyA, joint.bodyB, false);
    for (const Spring& spring : world.springs)
        if (spring.bodyB >= 0) link(spring.bodyA, spring.bodyB, false);
}

bool hasUserMotion(const Motion& motion) {
    return !motion.linearVelocity.isZero(0) || !motion.angularVelocity.isZero(0) || !motion.force.isZero(0) ||
           !motion.torque.isZero(0);
}

void holdSleeperAtRest(Motion& motion) {
    motion.linearVelocity = motion.angularVelocity = Vec3::Zero();
    motion.force = motion.torque = Vec3::Zero();
}

}  // namespace

bool isSlow(const World& world, int bodyIndex) {
    const Motion* motion = world.motionOf(bodyIndex);
    if (!motion) return true;  // static bodies never move
    const Real speed = world.settings.sleepSpeed;
    const Real radius = boundingRadius(world.bodies[std::size_t(bodyIndex)].shape);
    // Squared, as Box2D v3 compares them: no square root per body.
    return motion->linearVelocity.squaredNorm() < speed * speed &&
           motion->angularVelocity.squaredNorm() * radius * radius < speed * speed;
}

bool isMovingKinematic(const World& world, int bodyIndex) {
    return bodyIndex >= 0 && std::size_t(bodyIndex) < world.bodies.size() &&
           world.bodies[std::size_t(bodyIndex)].type == BodyType::Kinematic && !isSlow(world, bodyIndex);
}

// [ch10-sleep-timers]
int updateSleepTimers(World& world, Real dt) {
    int slow = 0;
    for (Motion& motion : world.motions) {
        if (motion.asleep || !isDynamicBody(world, motion.bodyIndex)) continue;
        if (isSlow(world, motion.bodyIndex)) {
            motion.sleepTime += dt;
            ++slow;
        } else {
            motion.sleepTime = 0;
        }
    }
    // A platform that moves carries what stands on it along at its own speed, which may be slow:
    // touching it restarts the timer, so the body stays awake and counts as moving for waking
    // others (Box2D v3 keeps the island of a moving kinematic body awake the same way).
    for (const Contact& contact : world.contacts) {
        if (contact.pointCount == 0) continue;
        if (isMovingKinematic(world, contact.bodyA) && isAwakeDynamic(world, contact.bodyB))
            world.motionOf(contact.bodyB)->sleepTime = 0;
        if (isMovingKinematic(world, contact.bodyB) && isAwakeDynamic(world, contact.bodyA))
            world.motionOf(contact.bodyA)->sleepTime = 0;
    }
    return slow;
}
// [ch10-sleep-timers]

// [ch10-islands-sleep]
int putIslandsToSleep(World& world, SleepScratch& scratch) {
    // An island sleeps only when every body in it has been slow long enough: none has, none sleeps.
    const bool anyReady = std::any_of(world.motions.begin(), world.motions.end(), [&](const Motion& motion) {
        return isAwakeDynamic(world, motion.bodyIndex) && motion.sleepTime >= world.settings.timeToSleep;
    });
    if (!anyReady) return 0;
    resetSleepScratch(world, scratch);
    // Islands of awake dynamic bodies only: a static or kinematic body links nothing (the ground
    // under two piles must not make one island of them), it only keeps an island awake when it moves.
    std::vector<char>& awake = scratch.flagged;  // per root: the island must stay awake
    forEachIslandLink(world, [&](int a, int b, bool) {
        if (isAwakeDynamic(world, a) && isAwakeDynamic(world, b)) joinIslands(scratch.parent, a, b);
    });
    forEachIslandLink(world, [&](int a, int b, bool) {
        if (isMovingKinematic(world, a) && isAwakeDynamic(world, b)) awake[std::size_t(islandRoot(scratch.parent, b))] = 1;
        if (isMovingKinematic(world, b) && isAwakeDynamic(world, a)) awake[std::size_t(islandRoot(scratch.parent, a))] = 1;
    });
    // Box2D v3: "any single body in an island can keep it awake".
    const Real timeToSleep = world.settings.timeToSleep;
    for (const Motion& motion : world.motions)
        if (isAwakeDynamic(world, motion.bodyIndex) && motion.sleepTime < timeToSleep)
            awake[std::size_t(islandRoot(scratch.parent, motion.bodyIndex))] = 1;
    int slept = 0;
    for (Motion& motion : world.motions) {
        if (!isAwakeDynamic(world, motion.bodyIndex) || awake[std::size_t(islandRoot(scratch.parent, motion.bodyIndex))])
            continue;
        // What was left of the motion is below the sleep speed: dropping it is what lets the
        // island stay put (a sleeper keeps exactly zero velocity until something wakes it).
        motion.asleep = true;
        holdSleeperAtRest(motion);
        ++slept;
    }
    return slept;
}
// [ch10-islands-sleep]

// [ch10-wake]
namespace {

/// Whether `other`, linked to the sleeper `sleeper`, disturbs it: it touches it and moved this frame,
/// or a joint or spring ties it to an awake body, or it is a kinematic body that moves.
bool disturbs(const World& world, int sleeper, int other, bool isContact) {
    if (!isSleeper(world, sleeper)) return false;
    const bool movedThisFrame = isAwakeDynamic(world, other) && world.motionOf(other)->sleepTime == 0;
    const bool tiedToAwake = !isContact && isAwakeDynamic(world, other);
    return movedThisFrame || tiedToAwake || isMovingKinematic(world, other);
}

}  // namespace

int wakeTouchedIslands(World& world, SleepScratch& scratch) {
    // A user's push: a sleeper has no velocity, force or torque of its own (putIslandsToSleep and
    // the frame-end stage keep them zero), so any it has now was given to it.
    bool anySleeper = false, anyMover = false, disturbed = false;
    for (const Motion& motion : world.motions) {
        // motion.asleep first: a world asleep reads no Body (the flag is set on dynamic bodies only).
        if (!motion.asleep || !isDynamicBody(world, motion.bodyIndex)) {
            anyMover = true;  // an awake dynamic body, or a kinematic one
            continue;
        }
        anySleeper = true;
        disturbed = disturbed || hasUserMotion(motion);
    }
    if (!anySleeper || (!anyMover && !disturbed)) return 0;  // all asleep and untouched: nothing to wake them
    // Something that moved touches a sleeper, or an awake body is tied to one: a joint or spring
    // between an awake and a sleeping body would pull on a body the solve holds still. Most frames
    // nothing does, and the islands need not be found at all.
    if (!disturbed)
        forEachIslandLink(world, [&](int a, int b, bool isContact) {
            disturbed = disturbed || disturbs(world, a, b, isContact) || disturbs(world, b, a, isContact);
        });
    if (!disturbed) return 0;
    resetSleepScratch(world, scratch);
    // The sleeping islands: sleepers joined through each other only.
    forEachIslandLink(world, [&](int a, int b, bool) {
        if (isSleeper(world, a) && isSleeper(world, b)) joinIslands(scratch.parent, a, b);
    });
    std::vector<char>& wake = scratch.flagged;  // per root: the island wakes
    const auto disturb = [&](int sleeper) { wake[std::size_t(islandRoot(scratch.parent, sleeper))] = 1; };
    for (const Motion& motion : world.motions)
        if (isSleeper(world, motion.bodyIndex) && hasUserMotion(motion)) disturb(motion.bodyIndex);
    forEachIslandLink(world, [&](int a, int b, bool isContact) {
        if (disturbs(world, a, b, isContact)) disturb(a);
        if (disturbs(world, b, a, isContact)) disturb(b);
    });
    int woken = 0;
    for (Motion& motion : world.motions) {
        if (!isSleeper(world, motion.bodyIndex) || !wake[std::size_t(islandRoot(scratch.parent, motion.bodyIndex))])
            continue;
        motion.asleep = false;
        motion.sleepTime = 0;
        ++woken;
    }
    return woken;
}
// [ch10-wake]

bool everyBodyAsleep(const World& world) {
    for (const Motion& motion : world.motions)
        if (!motion.asleep) return false;
    return !world.motions.empty();
}

int countSleeping(const World& world) {
    int sleeping = 0;
    for (const Motion& motion : world.motions)
        if (isSleeper(world, motion.bodyIndex)) ++sleeping;
    return sleeping;
}

void addSleepStages(Pipeline& pipeline, const World& world) {
    if (!world.settings.sleeping) {
        pipeline.setPlanNote(stage_group::kSleep, "off: the scene turns sleeping off");
        return;
    }
    std::ostringstream note;
    note << "on: islands below " << world.settings.sleepSpeed << " m/s for " << world.settings.timeToSleep
         << " s sleep";
    pipeline.setPlanNote(stage_group::kSleep, note.str());

    // Scratch only: rebuilt from the World on every call, it carries nothing between frames (a
    // copied World sleeps and wakes the same); shared so the stages can be copied with the pipeline.
    auto scratch = std::make_shared<SleepScratch>();

    Stage wake;
    wake.name = stageName(stage_group::kSleep, "wake");
    wake.frequency = StageFrequency::FrameStart;
    wake.run = [scratch](World& stepWorld, Real) { wakeTouchedIslands(stepWorld, *scratch); };
    // Right after the narrowphase: the contacts of this frame are known, and the solve after it
    // already sees a woken island as moving bodies.
    std::vector<Stage>& stages = pipeline.stages();
    auto at = stages.end();
    for (auto it = stages.begin(); it != stages.end(); ++it)
        if (stageGroup(it->name) == stage_group::kNarrowphase) at = it + 1;
    if (at == stages.end() && !pipeline.find(stage_group::kNarrowphase)) at = stages.begin();
    stages.insert(at, std::move(wake));

    Stage islands;
    islands.name = stageName(stage_group::kSleep, "islands");
    islands.frequency = StageFrequency::FrameEnd;
    // Once per frame, so the timers advance by the frame, not by the substep the stage is handed.
    islands.run = [scratch](World& stepWorld, Real) {
        // Sleeping means no motion: whatever a force or stage gave a sleeper is dropped here.
        for (Motion& motion : stepWorld.motions)
            if (motion.asleep) holdSleeperAtRest(motion);
        // Asleep throughout: no timer runs (sleepers keep theirs) and no island is left to sleep.
        if (everyBodyAsleep(stepWorld)) return;
        updateSleepTimers(stepWorld, stepWorld.settings.dt);
        putIslandsToSleep(stepWorld, *scratch);
    };
    pipeline.add(std::move(islands));
}

// [ch10-sleep-hold]
void holdSleepersStill(Pipeline& pipeline) {
    std::vector<Stage>& stages = pipeline.stages();
    const std::string wakeName = stageName(stage_group::kSleep, "wake");
    const std::string islandsName = stageName(stage_group::kSleep, "islands");
    const auto named = [&](const std::string& name) {
        return std::find_if(stages.begin(), stages.end(), [&](const Stage& stage) { return stage.name == name; });
    };
    if (named(wakeName) == stages.end() || named(islandsName) == stages.end()) return;
    Stage hold;
    hold.name = stageName(stage_group::kSleep, "hold");
    hold.frequency = StageFrequency::FrameStart;
    hold.run = [](World& stepWorld, Real) {
        for (const Motion& motion : stepWorld.motions) {
            Body& body = stepWorld.bodies[static_cast<std::size_t>(motion.bodyIndex)];
            if (motion.asleep && body.type == BodyType::Dynamic) body.type = BodyType::Static;
        }
    };
    stages.insert(named(wakeName) + 1, std::move(hold));
    Stage release;
    release.name = stageName(stage_group::kSleep, "release");
    release.frequency = StageFrequency::FrameEnd;
    // Only dynamic bodies sleep, so a sleeper is dynamic again.
    release.run = [](World& stepWorld, Real) {
        for (const Motion& motion : stepWorld.motions)
            if (motion.asleep) stepWorld.bodies[static_cast<std::size_t>(motion.bodyIndex)].type = BodyType::Dynamic;
    };
    stages.insert(named(islandsName), std::move(release));
}
// [ch10-sleep-hold]

}  // namespace stepwise
