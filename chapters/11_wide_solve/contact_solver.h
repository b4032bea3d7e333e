#pragma once
// The fast step's solve: chapter 6's relax and soft step (substeps of one biased and one relax
// sweep, warm started), on the data of solver_data.h, built once per frame. Two paths give the same
// bits: the wide one solves kWideLanes contacts of a colour at once (colouring.h) and the overflow
// after them; the scalar one solves the same contacts one after another in the same order.

#include "11_wide_solve/solver_data.h"
#include "world/step_state.h"
#include "world/world.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace stepwise {

enum class SolverPath { Scalar, Wide };
const char* toString(SolverPath path);

/// The path a pipeline takes unless its options say otherwise: Wide, or Scalar when the
/// environment variable STEPWISE_SOLVER_PATH is "scalar" (read once). The golden hashes are
/// checked both ways (tests/reliability/CMakeLists.txt): the two paths must give the same bits.
SolverPath defaultSolverPath();

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
    int pieces = 0;          // solves the frame took (more than one where a touched body turned far)
    int relaxSweeps = 0;     // relax sweeps the frame ran (one a substep, or fewer: relaxSweepNeeded)
    // Where the solve's time went, ms per phase (the bench's profile of the solve stage).
    std::array<double, kSolvePhaseCount> phaseMs{};
    double& ms(SolvePhase phase) { return phaseMs[static_cast<std::size_t>(phase)]; }
    double ms(SolvePhase phase) const { return phaseMs[static_cast<std::size_t>(phase)]; }
};

/// total's phase times, pieces and relax sweeps += frame's; the other counts become frame's.
void addPhaseTimes(FastSolveStats& total, const FastSolveStats& frame);

struct ContactSolverScratch;
struct JointPass;

/// What a later stage adds to a frame's solve (chapter 12's shock sweep): a pass over some of the
/// frame's lanes after the substeps. The solve calls it only in a frame whose plan asks for it
/// (IterationPlan::shockPropagation).
class SolveExtension {
public:
    virtual ~SolveExtension() = default;
    /// Before the blocks are filled: each contact's lane group (ContactSolverScratch::laneGroups).
    virtual void groupLanes(const World& world, ContactSolverScratch& scratch) = 0;
    /// After every block is prepared: whatever the pass needs of the blocks.
    virtual void prepare(ContactSolverScratch& scratch) = 0;
    /// After the last substep, before restitution and the store.
    virtual void finish(ContactSolverScratch& scratch, const ContactSolveParams& params) = 0;
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
    std::vector<int> laneClass;                            // per contact-order index: 0 single point, 1 more
    std::vector<int> laneLoad;                             // per contact-order index: its points' last loads (loadClass)
    std::vector<std::uint64_t> colourBits;
    // Lane groups (an extension's, SolveExtension::groupLanes): the groups' count (0: none this
    // frame), each contact's group (per contact-order index; 0: none) and which of its bodies the
    // extension holds still. A colour's lanes are filled group by group (orderLanes).
    int laneGroups = 0;
    std::vector<int> laneGroupOf;
    std::vector<std::uint8_t> laneHeldIsA;
    std::shared_ptr<SolveExtension> extension;  // none: the plain solve
    std::shared_ptr<JointPass> joints;          // joints, springs and drag (joint_pass.h); made when a scene has them
    std::vector<int> touched;                   // the dynamic slots the contacts touch (turnedFar)
    std::vector<std::uint8_t> touchedFlag;
    FastSolveStats stats;
    bool timePhases = false;  // fill stats.phaseMs (the bench's profile); off, the solve reads no clock
};

/// Whether the fast solve can take this world, solving what chapter 6/8's solve would: relax or soft
/// step with Gauss-Seidel, semi-implicit Euler everywhere, gyroscopic off or implicit. Joints,
/// springs, drag and kinematic bodies it takes. Otherwise `why` says what stands in the way.
bool fastSolveApplies(const World& world, std::string* why = nullptr);

/// Whether a contact record is one the solve can use: both bodies named, one to four finite points,
/// a unit normal, and at least one of its bodies awake and dynamic.
bool solvableContact(const World& world, const Contact& contact);

/// The contacts the frame's solve takes (solvableContact), as indices into World::contacts in
/// contact order: what the planner reads (chapter 12), the same list the solve builds.
void collectSolvableContacts(const World& world, std::vector<int>& order);

/// Whether a fast solve of `dt` has anything to plan this frame: not everything asleep.
bool fastSolvePlans(const World& world, Real dt);

/// The plan stage of a solve without a planner: the scene's count, every frame.
void planSceneCount(World& world);

/// The frame's solve and integration, in the substeps World::step.iterationPlan.iterations holds
/// (the plan stage before the solve writes them): gathers the awake dynamic bodies (Motion::asleep
/// skipped: they are static for the solve), builds the contacts' blocks, steps, writes poses,
/// velocities and carried impulses back.
void solveFast(World& world, Real dt, SolverPath path, ContactSolverScratch& scratch);

}  // namespace stepwise
