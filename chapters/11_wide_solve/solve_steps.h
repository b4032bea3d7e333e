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
/// The most a dynamic body turns in one substep, rad (Box2D v3's b2_maxRotation): chapter 1's
/// rotation series and the contacts' separations stay meaningful at it.
constexpr Real kMostTurnPerSubstep = Real(0.25) * kPi;
/// The most a dynamic body turns in one solve, rad. The contacts' points are found, and their rows
/// (arms, the bodies' inverse inertia) built, once a solve; a body that turns further no longer
/// has them: a needle spun about its length to an eighth of a turn a substep turned 11 rad in a frame of
/// 25 substeps, and its frame-start inverse inertia, struck through by a ground contact, threw it
/// off at 295 m/s (found by fuzz_stepper). Box2D v3, which builds its rows once a step of four
/// substeps, lets a body turn four eighths of a turn a step: half a turn, as here. At 60 Hz: 188 rad/s.
constexpr Real kMostTurnPerSolve = kPi;
/// The most a body a contact touches turns before the solve builds its rows again, rad: the solve
/// runs as pieces, each with its rows built where the bodies stand as it begins, a new piece
/// wherever a touched body has turned this far (turnedFar). A needle's arms and its inverse
/// inertia in world axes are wrong once it has turned a good part of a radian, and a contact
/// pushed through them adds energy: 24 needles, plates and sticks spun at 40 to 200 rad/s on a
/// floor gained up to 55 times their energy in a frame with one piece a frame, 0.3 times at
/// pieces of half a radian, nothing at a quarter (tests/ch11/turn_pieces_test.cpp).
constexpr Real kMostTurnPerPiece = Real(0.25);
/// The fastest a dynamic body spins in a solve of `solveTime` seconds in substeps of h, rad/s:
/// within both bounds.
Real mostSpin(Real h, Real solveTime);
// [ch11-most-turn]

/// A dynamic body spinning faster than `most` (rad/s, mostSpin) keeps its axis and that speed:
/// before every position step, and once more as the frame's solve ends, so that no body leaves the
/// solve (restitution's pushes come after the last step) spinning faster than the next frame takes.
void holdSpin(SolverBodies& bodies, Real most);

/// Chapter 1's position step for the moving bodies, a dynamic body's spin first held (holdSpin).
void integratePositions(SolverBodies& bodies, Real h, Real mostSpin, SolverPath path);
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
