#pragma once
// Islands and sleeping. Most bodies of a big scene lie still most of the time: a pile that has come
// to rest costs the same solve as one that is falling, for nothing. So a body that stays slow for
// a while gets ready to sleep, and when every body of its island (the bodies it touches or is tied
// to, through each other) is ready, the island sleeps: the solve treats its bodies as static and
// nothing integrates them. Anything that touches the island fast, or a user who pushes one of its
// bodies, wakes the whole island at once, so its contacts all start again together.
//
// The rules follow Box2D v3 and Box3D (Erin Catto): a body is slow while its speed and its
// angular speed times its extent stay under the sleep speed (Box2D v3 compares their sum with
// b2BodyDef::sleepThreshold, 0.05 m/s by default; here each must stay under it alone);
// an island sleeps once its least-rested body has been slow for b2_timeToSleep (0.5 s); static
// bodies never join islands (a ground under every pile would make one island of all of them), and
// a moving kinematic body keeps what it touches awake. Jolt does the same with
// PhysicsSettings::mTimeBeforeSleep (0.5 s) and mPointVelocitySleepThreshold (0.03 m/s, tested at
// points on the body's bounding sphere, as |w| r is here).
//
// All state lives in Motion::asleep and Motion::sleepTime: a copied World sleeps and wakes the same.

#include "world/pipeline.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

/// Buffers the island passes work in, reused every frame so a steady scene allocates nothing.
/// Scratch only: every call rebuilds them from the World, nothing in them outlives the call.
struct SleepScratch {
    std::vector<int> parent;       // union-find over body indices (a root is its own parent)
    std::vector<char> flagged;     // per root: the island must stay awake / must wake
};

/// Whether a moving body is slow: |v| < sleep_speed and |w| r < sleep_speed, r the bounding
/// radius of its shape (the fastest a point of the body can turn around its origin).
bool isSlow(const World& world, int bodyIndex);

/// Whether bodyIndex names a dynamic body of the world (false for any other index).
inline bool isDynamicBody(const World& world, int bodyIndex) {  // inline: the planner asks it per contact
    return bodyIndex >= 0 && std::size_t(bodyIndex) < world.bodies.size() &&
           world.bodies[std::size_t(bodyIndex)].type == BodyType::Dynamic;
}

/// Whether bodyIndex names a dynamic body that is awake.
bool isAwakeDynamic(const World& world, int bodyIndex);

/// Whether a body is a kinematic body that moves (not slow): it keeps what it touches awake.
bool isMovingKinematic(const World& world, int bodyIndex);

/// Advances the sleep timers by dt: an awake dynamic body that is slow, and does not touch a
/// moving kinematic body, adds dt; any other awake dynamic body starts again at 0. Sleeping
/// bodies keep theirs. Returns the number of slow awake dynamic bodies.
int updateSleepTimers(World& world, Real dt);

/// Joins the awake dynamic bodies into islands (touching contacts and joints, springs between two
/// bodies) and puts to sleep every island whose bodies all have sleepTime >= time_to_sleep and
/// that touches no moving kinematic body: asleep, velocities, force and torque zeroed. Returns
/// the number of bodies put to sleep.
int putIslandsToSleep(World& world, SleepScratch& scratch);

/// Wakes (asleep = false, sleepTime = 0) every sleeping island that something disturbs: a touching
/// contact with an awake dynamic body that moved this frame (sleepTime == 0) or with a moving
/// kinematic body, a joint or spring to an awake body, or a velocity, force or torque a user gave
/// one of its bodies. Runs after the narrowphase, so this frame's solve already sees the island
/// awake. Returns the number of bodies woken.
int wakeTouchedIslands(World& world, SleepScratch& scratch);

/// Dynamic bodies asleep (reports and benches).
int countSleeping(const World& world);

/// True when the world has moving bodies and every one of them sleeps: nothing can change this frame.
bool everyBodyAsleep(const World& world);

/// Adds "sleep:wake" (frame start, right after the narrowphase) and "sleep:islands" (frame end,
/// last) when Settings::sleeping; the plan note of group "sleep" says which and why.
void addSleepStages(Pipeline& pipeline, const World& world);

/// Adds "sleep:hold" right after "sleep:wake" and "sleep:release" right before "sleep:islands":
/// from the wake pass to the island pass a sleeper is a static body (BodyType::Static), so a solve
/// and an integration written for awake bodies (chapter 8's) leave it exactly where it sleeps.
/// No-op without the sleep stages.
void holdSleepersStill(Pipeline& pipeline);

}  // namespace stepwise
