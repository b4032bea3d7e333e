#pragma once
// The steps of chapter 11's solve, shared by its files (contact_solver.cpp runs them in order):
// gathering the moving bodies, filling the blocks, integrating, storing.

#include "01_integrators/forces.h"
#include "11_wide_solve/contact_solver.h"

#include <vector>

namespace stepwise {

/// Slot 0 for everything that does not move, then one slot per kinematic body and one per awake
/// dynamic body, each in motion order.
void prepareBodies(const World& world, SolverBodies& bodies);
/// The rows' feedback and softness for substeps of h of a frame of `frame` seconds (chapter 6's
/// relax or soft step).
ContactSolveParams solveParams(const Settings& settings, Real h, Real frame);
/// Chapter 1's velocity step for the dynamic bodies (gravity; the user's force in the first
/// substep). With `forces` (per motion: chapter 1's evaluateForces at this substep's state, which
/// a scene with springs or drag needs), their force and torque instead of gravity alone.
void integrateVelocities(World& world, SolverBodies& bodies, Real h, bool firstSubstep, SolverPath path,
                         const std::vector<Wrench>* forces = nullptr);
// [ch11-most-turn]
/// The most a dynamic body turns in one substep, rad (Box2D v3's b2_maxRotation). The contacts'
/// points are found at the frame's start and their rows keep the start's arms; a body turning a
/// radian a substep leaves them meaningless (without the bound a
/// 1.3 g plate spun to 800 rad/s by a landing leaves at 5e5 m/s in the next frame's solve,
/// tests/ch11/fast_solve_test.cpp). No resting or rolling body comes near: 0.785 rad a substep
/// is 471 rad/s at ten substeps of a 60 Hz frame.
constexpr Real kMostTurnPerSubstep = Real(0.25) * kPi;
// [ch11-most-turn]

/// A dynamic body spinning faster than kMostTurnPerSubstep / h keeps its axis and that speed:
/// before every position step, and once more as the frame's solve ends, so that no body leaves the
/// solve (restitution's pushes come after the last step) spinning faster than the next frame takes.
void holdSpin(SolverBodies& bodies, Real h);

/// Chapter 1's position step for the moving bodies, a dynamic body's spin first held (holdSpin).
void integratePositions(SolverBodies& bodies, Real h, SolverPath path);
/// Where a slot's body stands now: its centre of mass and rotation at the frame's start moved by
/// the substeps so far (what writeBodiesBack stores, and what joints and springs are built at).
struct SlotPose {
    Vec3 center;
    Quat rotation;
};
SlotPose slotPose(const SolverBodies& bodies, int slot);
/// Poses and velocities back into the World.
void writeBodiesBack(World& world, const SolverBodies& bodies);
/// Bodies that touch nothing, each through all the substeps at once.
void moveFreeBodies(World& world, Real h, int substeps);

/// Both bodies named and distinct, one to four finite points, a unit normal.
bool validContactRecord(const World& world, const Contact& contact);
/// Whether a contact is one the solve takes, from the slots prepareBodies gave (solvableContact).
bool usableContact(const World& world, const Contact& contact, const SolverBodies& bodies);
/// The wide path's blocks: each colour kWideLanes contacts at a time, the overflow one at a time.
void buildWideBlocks(const World& world, ContactSolverScratch& scratch, const ContactSolveParams& params);
/// The scalar path's blocks, one contact each, in the wide path's order.
void buildScalarBlocks(const World& world, ContactSolverScratch& scratch, const ContactSolveParams& params);
/// Every block's impulses back into its contact points.
void storeBlocks(const ContactSolverScratch& scratch, World& world);

}  // namespace stepwise
