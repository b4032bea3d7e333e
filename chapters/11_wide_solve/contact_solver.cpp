// Chapter 11's solve: the frame's contacts as blocks of lanes, solved colour by colour in substeps
// of one biased and one relax sweep (chapter 6's relax or soft step), warm started. Which worlds
// and contacts it takes: solvable.cpp.
#include "11_wide_solve/contact_solver.h"

#include "01_integrators/methods.h"
#include "03_epa/chapter.h"
#include "06_manifolds/stabilisation.h"
#include "10_skip_work/sleep.h"
#include "11_wide_solve/contact_kernels.h"
#include "11_wide_solve/joint_hand_on.h"
#include "11_wide_solve/joint_pass.h"
#include "11_wide_solve/solve_steps.h"
#include "11_wide_solve/turn_pieces.h"
#include "11_wide_solve/wide_solver.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cmath>

namespace stepwise {

const char* toString(SolverPath path) { return path == SolverPath::Wide ? "wide" : "scalar"; }

SolverPath defaultSolverPath() {
    static const SolverPath path = [] {
        const char* chosen = std::getenv("STEPWISE_SOLVER_PATH");
        return chosen && std::string(chosen) == "scalar" ? SolverPath::Scalar : SolverPath::Wide;
    }();
    return path;
}

namespace {

bool noneAsleep(const World& world) {
    return std::none_of(world.motions.begin(), world.motions.end(), [](const Motion& motion) { return motion.asleep; });
}

}  // namespace

namespace {

template <int N>
void warmStartAll(std::vector<ManifoldBlock<N>>& blocks, SolverBodyState* states) {
    for (ManifoldBlock<N>& block : blocks) warmStartBlock(block, states);
}
template <int N>
bool solveAll(std::vector<ManifoldBlock<N>>& blocks, SolverBodyState* states, const ContactSolveParams& params,
              bool useBias) {
    bool deep = false;
    for (ManifoldBlock<N>& block : blocks) deep = solveAnyBlock(block, states, params, useBias) || deep;
    return deep;
}
template <int N>
void restitutionAll(std::vector<ManifoldBlock<N>>& blocks, SolverBodyState* states, Real threshold) {
    for (ManifoldBlock<N>& block : blocks) restitutionBlock(block, states, threshold);
}

template <int N>
bool collideAll(std::vector<ManifoldBlock<N>>& blocks, SolverBodyState* states, const ContactSolveParams& params) {
    bool struck = false;
    for (ManifoldBlock<N>& block : blocks) struck = collideBlock(block, states, params) || struck;
    return struck;
}
template <int N>
bool anyRestitution(const std::vector<ManifoldBlock<N>>& blocks) {
    for (const ManifoldBlock<N>& block : blocks)
        for (int lane = 0; lane < N; ++lane)
            if (block.restitution[lane] > 0) return true;
    return false;
}

/// Collision sweeps a substep at most: a row of this many touching balls passes an impact on.
constexpr int kCollisionSweeps = 16;

template <int N>
void resetImpulses(std::vector<ManifoldBlock<N>>& blocks) {
    for (ManifoldBlock<N>& block : blocks) {
        for (ManifoldPointPack<N>& p : block.point) p.normalImpulse = Pack<N>::splat(0);
        block.tangentImpulse1 = block.tangentImpulse2 = block.twistImpulse = Pack<N>::splat(0);
        block.rollingImpulse = PackVec3<N>{Pack<N>::splat(0), Pack<N>::splat(0), Pack<N>::splat(0)};
    }
}


/// The solve's phase times: one clock read per phase, and none unless asked for (a read costs
/// tens of nanoseconds, and forty a frame would be a large part of a one-ball step).
class PhaseClock {
public:
    explicit PhaseClock(bool on) : on_(on) {
        if (on_) last_ = std::chrono::steady_clock::now();
    }
    /// Milliseconds since the last lap (0 when off).
    double lap() {
        if (!on_) return 0;
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }

private:
    bool on_;
    std::chrono::steady_clock::time_point last_{};
};



/// The frame's solve is over: its figures, and no velocities kept for restitution.
void finishFrame(World& world, const SolverStats& stats) {
    world.step.solver = stats;
    world.step.velocitiesBeforeForces.clear();
}

/// The contacts that involve a moving body, in contact order (canonical: sorted by pair), with their
/// bodies' slots; counts the records that cannot be solved.
SolverStats gatherContacts(const World& world, ContactSolverScratch& scratch) {
    SolverStats solverStats;
    for (std::size_t i = 0; i < world.contacts.size(); ++i) {
        const Contact& contact = world.contacts[i];
        if (!usableContact(world, contact, scratch.bodies)) {
            if (contact.pointCount > 0 && (contact.bodyA < 0 || contact.bodyB < 0 || contact.pointCount > 4 ||
                                           !contact.normal.allFinite()))
                solverStats.invalidSkipped += std::clamp(contact.pointCount, 1, 4);
            continue;
        }
        scratch.contactOrder.push_back(static_cast<int>(i));
        scratch.slotA.push_back(scratch.bodies.slotOfBody[static_cast<std::size_t>(contact.bodyA)]);
        scratch.slotB.push_back(scratch.bodies.slotOfBody[static_cast<std::size_t>(contact.bodyB)]);
        scratch.stats.points += contact.pointCount;
    }
    scratch.stats.manifolds = static_cast<int>(scratch.contactOrder.size());
    return solverStats;
}

// [ch11-relax-after-push]
/// Whether a substep ends with its relax sweep. The relax sweep takes back the velocity that the
/// biased sweep's push out of points deeper than the slop added. Where no point lay that deep,
/// the two sweeps solve every row alike (a gap's speculative allowance is in both) and the relax is
/// one more Gauss-Seidel sweep, which a substep buys more cheaply (chapter 12's planner, where it
/// asks for such substeps: IterationPlan::relaxOnlyAfterPush). The last substep always relaxes, as
/// do substeps with restitution (the relax keeps the approach speeds it reverses) or joints.
bool relaxSweepNeeded(const World& world, bool lastSubstep, bool pushed, bool collisions, bool joints) {
    return !world.step.iterationPlan.relaxOnlyAfterPush || lastSubstep || pushed || collisions || joints;
}
// [ch11-relax-after-push]

// [ch11-substeps]
/// The frame's substeps: integrate the velocities, collide, warm start, one biased sweep, move the
/// bodies, one relax sweep (relaxSweepNeeded). Scalar and wide blocks take each pass in turn.
int runSubsteps(World& world, ContactSolverScratch& scratch, const ContactSolveParams& params, int substeps,
                SolverPath path, bool collisions, PhaseClock& clock) {
    FastSolveStats& stats = scratch.stats;
    SolverBodyState* states = scratch.bodies.states.data();
    const Real h = params.substep;
    JointPass* joints = scratch.joints && needsJointPass(world) ? scratch.joints.get() : nullptr;
    const bool forces = joints && (!world.springs.empty() || !world.dampings.empty());
    int ran = substeps;
    for (int substep = 0; substep < substeps; ++substep) {
        if (forces) evaluateSubstepForces(world, scratch.bodies, *joints);
        integrateVelocities(world, scratch.bodies, h, substep == 0, path, forces ? &joints->forces : nullptr);
        if (joints) buildJointRows(world, scratch.bodies, h, substep == 0, *joints);
        // [ch11-collisions-first]
        // Collisions first, on the speeds before the warm start adds last substep's pushes.
        for (int sweep = 0; collisions && sweep < kCollisionSweeps; ++sweep) {
            const bool struckWide = collideWide(scratch.wideBlocks, states, params);
            const bool struckScalar = collideAll(scratch.scalarBlocks, states, params);
            if (!struckWide && !struckScalar) break;
        }
        // [ch11-collisions-first]
        stats.ms(SolvePhase::Integrate) += clock.lap();
        // [ch11-joints-first]
        // Joints before contacts in every pass (Box2D v3's order): the contacts, solved last,
        // have the last word on penetration, which a joint's spring may trade for its own error.
        if (joints) warmStartJoints(*joints, states, world.settings.warmStarting);
        // [ch11-joints-first]
        if (!world.settings.warmStarting) {
            resetImpulses(scratch.wideBlocks);
            resetImpulses(scratch.scalarBlocks);
        } else {
            warmStartWide(scratch.wideBlocks, states);
            warmStartAll(scratch.scalarBlocks, states);
        }
        stats.ms(SolvePhase::WarmStart) += clock.lap();
        if (joints) solveJoints(*joints, states, /*relax=*/false);
        const bool deepWide = solveWide(scratch.wideBlocks, states, params, /*useBias=*/true);
        const bool deepScalar = solveAll(scratch.scalarBlocks, states, params, true);
        stats.ms(SolvePhase::Solve) += clock.lap();
        integratePositions(scratch.bodies, h, params.mostSpin, path);
        // What the move did to the errors of rows the next substep may keep (after the piece's
        // last, the next piece: handJointRowsOn).
        if (joints) advanceJointErrors(*joints, states, h);
        stats.ms(SolvePhase::Integrate) += clock.lap();
        if (relaxSweepNeeded(world, substep + 1 == substeps, deepWide || deepScalar, collisions, joints != nullptr)) {
            if (joints) solveJoints(*joints, states, /*relax=*/true);
            solveWide(scratch.wideBlocks, states, params, /*useBias=*/false);  // relax
            solveAll(scratch.scalarBlocks, states, params, false);
            ++stats.relaxSweeps;
        }
        stats.ms(SolvePhase::Relax) += clock.lap();
        if (substep + 1 < substeps && turnedFar(states, scratch.touched, h)) {
            ran = substep + 1;
            break;
        }
    }
    if (joints) keepJointImpulses(*joints);
    return ran;
}
// [ch11-substeps]

/// The blocks of the frame, filled and prepared; with an extension, its groups first (the lanes
/// carry them) and its preparation after.
void buildBlocks(const World& world, ContactSolverScratch& scratch, const ContactSolveParams& params, SolverPath path,
                 bool extended) {
    scratch.laneGroups = 0;
    if (extended) scratch.extension->groupLanes(world, scratch);
    if (path == SolverPath::Wide)
        buildWideBlocks(world, scratch, params);
    else
        buildScalarBlocks(world, scratch, params);
    scratch.stats.wideBlocks = static_cast<int>(scratch.wideBlocks.size());
    scratch.stats.overflow = path == SolverPath::Wide ? static_cast<int>(scratch.scalarBlocks.size()) : 0;
    const SolverBodyState* states = scratch.bodies.states.data();
    prepareWide(scratch.wideBlocks, states);
    for (ManifoldBlock<1>& block : scratch.scalarBlocks) prepareBlock(block, states);
    if (extended) scratch.extension->prepare(scratch);
}

}  // namespace

void addPhaseTimes(FastSolveStats& total, const FastSolveStats& frame) {
    total.bodies = frame.bodies;
    total.manifolds = frame.manifolds;
    total.points = frame.points;
    total.wideBlocks = frame.wideBlocks;
    total.overflow = frame.overflow;
    total.pieces += frame.pieces;
    total.relaxSweeps += frame.relaxSweeps;
    for (std::size_t phase = 0; phase < kSolvePhaseCount; ++phase) total.phaseMs[phase] += frame.phaseMs[phase];
}


namespace {

/// One piece of the frame's solve: up to `substeps` substeps of h, its rows built where the bodies
/// stand as it begins, ended early where a touched body turns far (turnedFar); `frameTime` bounds
/// the spin (mostSpin). Returns the substeps it ran. solveFast runs one a frame, or several.
int solvePiece(World& world, Real h, Real frameTime, int substeps, bool firstPiece, SolverPath path,
               ContactSolverScratch& scratch) {
    FastSolveStats& stats = scratch.stats;
    const std::array<double, kSolvePhaseCount> phaseMs = stats.phaseMs;  // the frame's so far
    const int pieces = stats.pieces + 1, relaxSweeps = stats.relaxSweeps;
    stats = FastSolveStats{};
    stats.phaseMs = phaseMs;
    stats.pieces = pieces;
    stats.relaxSweeps = relaxSweeps;
    PhaseClock clock(scratch.timePhases);
    scratch.contactOrder.clear();
    scratch.slotA.clear();
    scratch.slotB.clear();
    if (everyBodyAsleep(world)) {  // nothing to gather or move
        finishFrame(world, SolverStats{});
        return substeps;
    }
    const IterationPlan& plan = world.step.iterationPlan;  // this frame's (the plan stage's)
    const bool linked = needsJointPass(world);  // joints, springs or drag
    if (world.contacts.empty() && noneAsleep(world) && !linked) {
        // Nothing touches: no solver state to gather, the bodies move on their own (kinematic
        // ones by chapter 1's step).
        stats.bodies = static_cast<int>(world.motions.size());
        moveFreeBodies(world, h, substeps);
        finishFrame(world, SolverStats{});
        return substeps;
    }
    prepareBodies(world, scratch.bodies);
    stats.bodies = static_cast<int>(scratch.bodies.states.size()) - scratch.bodies.firstDynamic;
    if (stats.bodies == 0 && scratch.bodies.firstDynamic == 1) {  // nothing moves
        finishFrame(world, SolverStats{});
        return substeps;
    }
    SolverStats solverStats = gatherContacts(world, scratch);
    // Every body moves in the substeps, touching or not (chapter 6's solve says why); nothing
    // touches and nothing sleeps: the bodies fly free.
    if (stats.manifolds == 0 && !linked && stats.bodies == static_cast<int>(world.motions.size())) {
        moveFreeBodies(world, h, substeps);
        finishFrame(world, solverStats);
        return substeps;
    }
    ContactSolveParams params = solveParams(world.settings, h, frameTime);
    // No body enters the solve spinning faster than it may turn in it: chapter 7's impacts after
    // the last solve may have spun one up, and the first substep's rows would take it whole.
    holdSpin(scratch.bodies, params.mostSpin);
    // Carried impulses were a substep's of the last plan: scaled to this frame's substep.
    const int planned = std::max(1, plan.iterations);
    if (firstPiece && plan.previousIterations > 0 && plan.previousIterations != planned)
        params.carryScale = static_cast<Real>(plan.previousIterations) / static_cast<Real>(planned);
    findTouched(scratch);
    const bool extended = scratch.extension && plan.shockPropagation;
    buildBlocks(world, scratch, params, path, extended);
    if (linked) {
        if (!scratch.joints) scratch.joints = std::make_shared<JointPass>();
        prepareJointPass(world, scratch.bodies, params.carryScale, *scratch.joints);
        takeHandedJointRows(world, h, *scratch.joints);
    }
    stats.ms(SolvePhase::Prepare) += clock.lap();
    // Scenes without restitution (most) have no collisions to sweep.
    const bool collisions = anyRestitution(scratch.wideBlocks) || anyRestitution(scratch.scalarBlocks);
    const int ran = runSubsteps(world, scratch, params, substeps, path, collisions, clock);
    if (extended) scratch.extension->finish(scratch, params);
    stats.ms(SolvePhase::Relax) += clock.lap();
    SolverBodyState* states = scratch.bodies.states.data();
    if (collisions) {  // some lane has restitution
        restitutionWide(scratch.wideBlocks, states, params.restitutionThreshold);
        restitutionAll(scratch.scalarBlocks, states, params.restitutionThreshold);
    }
    holdSpin(scratch.bodies, params.mostSpin);
    writeBodiesBack(world, scratch.bodies);
    storeBlocks(scratch, world);
    if (linked) {
        storeJointImpulses(*scratch.joints, world);
        solverStats.jointRows = scratch.joints->rowCount;
        solverStats.jointsSkipped = scratch.joints->invalidSkipped;
        solverStats.jointsBuilt = scratch.joints->jointsBuilt;
        solverStats.jointsKept = scratch.joints->jointsKept;
        if (!extended) handJointRowsOn(world, scratch.bodies, h, *scratch.joints);
    }
    stats.ms(SolvePhase::Store) += clock.lap();
    solverStats.contactPoints = stats.points;
    solverStats.rows = stats.points + 3 * stats.manifolds;  // normal rows, and three friction rows per manifold
    finishFrame(world, solverStats);
    return ran;
}

}  // namespace

// [ch11-solve-fast]
void solveFast(World& world, Real dt, SolverPath path, ContactSolverScratch& scratch) {
    if (!(dt > 0) || !std::isfinite(dt)) return;
    scratch.stats = FastSolveStats{};
    // Contacts found at an earlier substep of the frame (Settings::substeps > 1, collision once per
    // frame) are where their bodies were then: their points move with the bodies first.
    if (world.step.substep > 0 && world.step.contactsFoundAtSubstep < world.step.substep) followContactAnchors(world);
    IterationPlan& plan = world.step.iterationPlan;
    const int planned = std::max(1, plan.iterations);
    const int substeps = substepsForTurns(world, dt, planned);
    // More substeps than the plan's: the frame's count is theirs (the next frame scales the
    // impulses it carries by it).
    if (substeps > planned) plan.iterations = substeps;
    const Real h = dt / static_cast<Real>(substeps);
    // [ch11-pieces]
    // One piece unless a touched body turns far (turnedFar): then its rows are built again where
    // the bodies stand, and the contacts' points move with the bodies, as between the substeps
    // of Settings::substeps.
    for (int done = 0; done < substeps;) {
        if (done > 0) followContactAnchors(world);
        done += solvePiece(world, h, dt, substeps - done, done == 0, path, scratch);
    }
    // [ch11-pieces]
}
// [ch11-solve-fast]

}  // namespace stepwise
