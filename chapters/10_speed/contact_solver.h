#pragma once
// The fast step's solve: chapter 6's relax and soft step (substeps of one biased and one relax
// sweep, warm started), on the data of solver_data.h, built once per frame. Two paths give the same
// physics: the scalar one solves the contacts one after another in contact order; the wide one
// solves kWideLanes contacts of a colour at once (colouring.h) and the overflow after them.

#include "10_speed/iteration_plan.h"
#include "10_speed/shock_propagation.h"
#include "10_speed/solver_data.h"
#include "world/world.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace stepwise {

enum class SolverPath { Scalar, Wide };
const char* toString(SolverPath path);

/// What one fast solve did (World::step.solver carries the engine-wide figures).
/// The phases of a solve, in the order a frame runs them (Box3D's solver stages).
enum class SolvePhase {
    Prepare,    // bodies, colours, blocks and their effective masses, once per frame
    Integrate,  // velocities and positions, every substep
    WarmStart,
    Solve,      // the biased sweeps
    Relax,      // the relax sweeps
    Store,      // restitution, poses, velocities and impulses back into the World
};
constexpr std::size_t kSolvePhaseCount = 6;

struct FastSolveStats {
    int bodies = 0;          // moving bodies solved (awake dynamic)
    int manifolds = 0;       // contacts with at least one moving body
    int points = 0;
    int wideBlocks = 0;      // blocks of kWideLanes lanes (their fill: manifolds in them / lanes)
    int overflow = 0;        // manifolds past the last colour, solved one at a time
    // Where the solve's time went, ms per phase (the bench's profile of the solve stage).
    std::array<double, kSolvePhaseCount> phaseMs{};
    double& ms(SolvePhase phase) { return phaseMs[static_cast<std::size_t>(phase)]; }
    double ms(SolvePhase phase) const { return phaseMs[static_cast<std::size_t>(phase)]; }
};

/// total's phase times += frame's; the counts become frame's.
void addPhaseTimes(FastSolveStats& total, const FastSolveStats& frame);

/// One block of the shock sweep's order: wideBlocks[block] (or scalarBlocks[block]), its lanes of
/// one group (solveHeldBlock).
struct ShockVisit {
    bool wide = false;
    std::size_t block = 0;
    int group = 0;
};

/// The buffers a solve works in. Rebuilt from the World every frame and carrying nothing from one
/// frame to the next (all state stays in the World); kept only so that a steady scene allocates
/// nothing per step.
struct ContactSolverScratch {
    SolverBodies bodies;
    std::vector<ManifoldBlock<1>> scalarBlocks;          // scalar path, and the wide path's overflow
    std::vector<ManifoldBlock<kWideLanes>> wideBlocks;   // grouped by colour
    LaneInputs<kWideLanes> laneInputs;                   // the block being filled (buildWideBlocks)
    std::vector<int> contactOrder, slotA, slotB, colours;
    std::vector<int> laneOrder, laneScratch, laneBuckets;  // the wide blocks' fill order (orderLanes)
    std::vector<std::uint64_t> colourBits;
    StackSearch stackSearch;  // the planner's (iteration_plan.h)
    // Shock propagation (shock_propagation.h): the sweep's order, each contact's group in it (per
    // contact-order index; 0: not swept) and held body, and the blocks it visits in turn.
    std::vector<int> slotDepth;
    std::vector<std::uint8_t> slowSlot;
    ShockOrder shockOrder;
    int shockGroups = 0;  // 0: no shock sweep this frame
    std::vector<int> shockGroupOf;
    std::vector<std::uint8_t> shockHeldIsA;
    std::vector<ShockVisit> shockVisits, shockScratch;
    FastSolveStats stats;
    bool shockAllowed = true;  // false: no shock sweep whatever the planner says (the bench's A/B)
    bool timePhases = false;  // fill stats.phaseMs (the bench's profile); off, the solve reads no clock
};

/// Whether the fast solve can take this world, solving what chapter 6/8's solve would: relax or soft
/// step with Gauss-Seidel, semi-implicit Euler everywhere, no springs, dampings, joints or kinematic
/// bodies, gyroscopic off or implicit. Otherwise `why` says what stands in the way.
bool fastSolveApplies(const World& world, std::string* why = nullptr);

/// The frame's solve and integration (the substeps of Settings::solverIterations): gathers the awake
/// dynamic bodies (Motion::asleep skipped: they are static for the solve), builds the contacts'
/// blocks, steps, writes poses, velocities and carried impulses back.
void solveFast(World& world, Real dt, SolverPath path, ContactSolverScratch& scratch);

}  // namespace stepwise
