#pragma once
// One frame of a run as the next step reads it back, and nothing more. A World holds two kinds of
// data: its structure (names, shapes, mass properties, materials, joint and spring definitions,
// paths), which no step changes, and the state each step hands to the next (poses, velocities,
// the contact cache with its warm-start impulses, sleep timers, the joints' impulses, the sweep's
// order). A snapshot keeps only the second kind, every Real in its own bits; restored into a world
// of the same structure, it steps on exactly as the original did (Jolt's StateRecorder keeps the
// bodies' and constraints' mutable state apart from the scene the same way).

#include "world/world.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace stepwise {

// [ch09-snapshot]
/// A body's pose: every body, static ones included (the inspector can move a static body).
struct PoseBits {
    Real position[3];
    Real rotation[4];   // x, y, z, w
};

/// A moving body's velocities and its sleep timer (one per World::motions entry).
struct MotionBits {
    Real linear[3];
    Real angular[3];
    Real sleepTime;
};

/// A force or torque set between frames and not yet applied (a user's push); rare, so kept apart.
struct PushBits {
    std::int32_t motion;
    Real force[3];
    Real torque[3];
};

/// A contact record of the cache. The point count, the reference side, the searches missed and
/// the flags take a byte each: a record holds at most 4 points, and chapter 6 drops it a few
/// searches after it was last found.
struct ContactBits {
    std::int32_t bodyA, bodyB;
    Real normal[3];
    std::uint8_t pointCount;
    std::uint8_t referenceSide;
    std::uint8_t missedSteps;
    std::uint8_t flags;           // bit 0: built pose known; bits 1-4: point i persisted;
                                  // bit 5: the pair is in World::pairs
};

/// Where B stood in A's frame when the manifold was built (chapter 10's cache rule), for the
/// records whose pose is known only.
struct BuiltPoseBits {
    Real relativePosition[3];
    Real relativeRotation[4];
    Real localNormal[3];
};

/// A contact point: the anchors the next search matches and refreshes from, the feature id it
/// matches by, the depth a sleeping pair is kept with, and the impulses of the warm start.
struct PointBits {
    Real anchorA[3];
    Real anchorB[3];
    Real depth;
    std::uint32_t featureId;
    Real normalImpulse;
    Real tangentImpulse[2];
    Real normalMass;              // the drop rule reads it for records the solve skipped (sleepers)
};

/// The step's scalars: the planner's last plan, the counters a run report sums, the last solve's
/// and broadphase's measurements.
struct StepScalars {
    int substep = 0, substepCount = 1, contactsFoundAtSubstep = 0;
    SolverStats solver;
    int contactPointsDropped = 0, manifoldsReused = 0, manifoldsRebuilt = 0;
    int ccdFastBodies = 0, ccdToiEvents = 0, ccdRootIterations = 0;
    bool ccdBoundHit = false;
    Real ccdTimeLost = 0;
    long ccdStepsRun = 0, ccdTotalToiEvents = 0, ccdStepsBoundHit = 0;
    IterationPlan iterationPlan;
    int sweepAxis = -1;           // the broadphase keeps its axis unless another spreads much more
    BroadphaseMode broadphaseUsed = BroadphaseMode::Auto;
    Vec3 centreVariance = Vec3::Zero();
    bool fullSort = false, sweepSkipped = false;
    long sortMoves = 0, axisOverlaps = 0;
};

struct WorldSnapshot {
    long frame = 0;
    double time = 0;
    Settings settings;            // the demo's panel and chapter 12's plan change them between frames
    StepScalars step;
    std::vector<PoseBits> poses;             // one per body
    std::vector<MotionBits> motions;         // one per motion
    std::vector<std::uint8_t> asleep;        // one per motion
    std::vector<PushBits> pushes;
    std::vector<std::int32_t> sweepOrder;    // the broadphase's endpoints, body by body, in order
    std::vector<ContactBits> contacts;       // sorted by pair, as World::contacts
    std::vector<BuiltPoseBits> builtPoses;   // one per contact whose built pose is known
    std::vector<PointBits> points;           // pointCount per contact, in contact order
    std::vector<BodyPair> pairs;             // World::pairs without a contact record (flag bit 5 marks
                                             // the others), or all of them when pairsWhole
    bool pairsWhole = false;                 // World::pairs not in the canonical order: kept as it is
    std::vector<JointImpulses> jointImpulses;
    // The joints' rows the fast solve hands from frame to frame (chapter 11): opaque here, shared
    // with the world until it steps on (the step copies them then), restored as they are.
    std::shared_ptr<HandedJointRows> jointRows;
    std::size_t jointRowsBytes = 0;
};
// [ch09-snapshot]

/// Writes the world's mutable state into `snapshot`, reusing its vectors' storage.
void saveSnapshot(const World& world, WorldSnapshot& snapshot);

/// Writes the snapshot's state into `world`, which must have the structure of the world it was
/// taken from (the same bodies, moving bodies and joints; sameStructure). What a step rebuilds
/// from scratch (candidate pairs, the broadphase's grown boxes and buffers, the gaps of pairs
/// known apart, this frame's CCD sweeps) is cleared: the next step finds it again and gets the
/// same answers. Throws std::invalid_argument when the counts do not fit the world.
void restoreSnapshot(const WorldSnapshot& snapshot, World& world);

/// Whether two worlds have the same structure as far as a snapshot is concerned: the same counts
/// of bodies, moving bodies, joints, springs, dampings and paths, and every moving body with the
/// same mass properties to the bit (what an edit can change between frames).
bool sameStructure(const World& a, const World& b);

/// Memory the snapshot holds (its vectors' capacities and the fixed part), bytes.
std::size_t snapshotBytes(const WorldSnapshot& snapshot);

/// The snapshot's bytes split the way the budget is stated: per body (poses, motions, sleep
/// flags, pushes, sweep order) and per contact point (records, built poses, points, pairs); the
/// fixed part and the joints' impulses and handed rows apart. Sizes, not capacities (the handed
/// rows: what they hold).
struct SnapshotSize {
    std::size_t bodyBytes = 0, contactBytes = 0, fixedBytes = 0, jointBytes = 0;
    std::size_t bodies = 0, contactPoints = 0;
    double perBody() const { return bodies ? double(bodyBytes) / double(bodies) : 0.0; }
    double perContactPoint() const { return contactPoints ? double(contactBytes) / double(contactPoints) : 0.0; }
};
SnapshotSize snapshotSize(const WorldSnapshot& snapshot);

}  // namespace stepwise
