#pragma once
// What one step hands from stage to stage, and what the last step measured. It lives in the
// World (never in a stage's closure) so that copying the World is a complete snapshot: a copy
// stepped on gives exactly the states the original does (the rewind of chapter 9, to come, relies on it).

#include "math/math.h"

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace stepwise {

/// The joints' rows as the fast solve's last piece left them, for the next to keep (chapter 11's
/// joint_hand_on.h defines it; opaque here).
struct HandedJointRows;

struct BodyVelocity {
    Vec3 linear = Vec3::Zero();
    Vec3 angular = Vec3::Zero();
};

/// What the last call of the contact solver did, for tests, benches and the demo panel.
struct SolverStats {
    int contactPoints = 0;       // points in World::contacts when the solve started
    int rows = 0;                // constraint rows built from them
    int invalidSkipped = 0;      // points with non-finite data, skipped (a defined result, not a crash)
    Real residualRms = 0;        // velocity residual after the last iteration, m/s
    Real residualMax = 0;        // m/s
    int jointRows = 0;           // rows of the joints solved with the contacts (chapter 8)
    int jointsSkipped = 0;       // joints with bad bodies or non-finite data, left out
    int jointsBuilt = 0;         // the frame's substeps: joints whose rows were built (chapter 11)
    int jointsKept = 0;          // ... and joints that kept last substep's rows, their errors moved
};

/// What continuous collision (chapter 7) keeps within a step and measured in the last ones. Plain
/// data in the World, so a copy of the world carries it (no state in the stage's closure).
struct CcdState {
    /// Pose of every body when the frame's substep began: the start of each body's sweep. The
    /// stage's recorder fills it at the first stage of a substep; empty when no CCD stage ran.
    std::vector<Transform> sweepStart;
    // What the last substep's TOI loop did (the demo draws the ghosts and the swept bounds).
    int fastBodies = 0;          // bodies whose sweep was checked
    int toiEvents = 0;           // impacts resolved (TOI > 0)
    int rootIterations = 0;      // distance queries of conservative advancement
    bool boundHit = false;       // an event bound stopped the loop early
    Real timeLost = 0;           // over the impacts: the fraction of the step the bodies waited (1 - TOI)
    std::vector<int> ghostBodies;          // one per resolved event: the moving body
    std::vector<Transform> ghostPoses;     // and its pose at the time of impact
    std::vector<Aabb> sweptBounds;         // one per fast body: start and end pose bounded
    // Since the world was made (the run report):
    long stepsRun = 0;           // substeps in which the TOI loop ran
    long totalToiEvents = 0;
    long stepsBoundHit = 0;      // substeps in which an event bound was hit
};

/// The rule that decided a frame's substep count (chapter 12's iteration_plan.h).
enum class PlanReason {
    SceneCount,      // the scene's solver_iterations: planning off, or bodies carry one another
    NothingTouches,  // free flight: substeps of kFreeFlightSubstep
    RestsOnWorld,    // bodies rest on static or kinematic bodies alone
    SlidesOnWorld,   // ... and one slides under friction
    Bounce,          // something arrives bouncing: the scene's count
    MassRatio,       // a body rests on a much lighter one: the square-root law
    LikeStack,       // a stack of like masses: the depth law without the sweep
    ShockSweep,      // a stack of like masses: the depth law with the shock sweep
    UnlikeStack,     // a stack of unlike masses: the square-root law where shallow, the scene's count where deep
    HangingChain,    // bodies hang from the world by joints: the sag law
    JointedBodies,   // dynamic bodies joined to one another: the sag law by depth (in the air, the scene's count)
};
constexpr int kPlanReasonCount = static_cast<int>(PlanReason::JointedBodies) + 1;

/// Frames a rule decided, and the counts it chose.
struct PlanReasonTally {
    long frames = 0;
    int fewest = 0;
    int most = 0;
};

/// What chapter 12's planner for solver_iterations "auto" saw and chose (iteration_plan.h).
/// The planner's thresholds (chapter 12's plan_constants.h), as the report quotes them: the
/// planner writes them every frame it plans (common code includes no chapter). Zero: no planner.
struct PlanThresholds {
    Real plainMassRatio = 0;       // load-path mass ratios up to it solve at the scene's count
    int plainStackDepth = 0;       // a stack deeper than it walks more than the held drift
    int fewestUnlikeSubsteps = 0;  // a shallow heap of unlike masses takes at least these
};

struct IterationPlan {
    int iterations = 0;       // substeps of this frame's solve (the plan stage writes them before the solve)
    int previousIterations = 0;  // of the frame planned before (0 before the first)
    Real massRatio = 1;       // along load paths: heaviest body resting on a lighter one over it, last frame
    int stackDepth = 0;       // dynamic bodies between the top of the deepest stack and its support, last frame
    int plainIterations = 0;  // where bodies carry one another, at the solve's dt (auto), last frame
    int mostIterations = 0;   // over every frame so far
    int fewestIterations = 0; // over every frame so far
    Real largestRatio = 1;
    int deepestStack = 0;     // over every frame so far
    bool shockPropagation = false;  // the last frame ended with a shock sweep (chapter 12)
    /// The last frame's substeps relaxed only after a biased sweep that pushed a point deeper than
    /// the slop, and in the last substep (chapter 11's relaxSweepNeeded; chapter 12 asks for it).
    bool relaxOnlyAfterPush = false;
    int shockFrames = 0;            // frames that did, so far
    PlanReason reason = PlanReason::SceneCount;  // what decided the last frame's count
    std::array<PlanReasonTally, kPlanReasonCount> reasons{};  // per rule, over every frame so far
    PlanThresholds thresholds;  // the rules' constants, for the report
};

struct StepState {
    int substep = 0;             // of the frame being stepped, 0 .. substepCount - 1
    int substepCount = 1;
    /// One per body, taken before this substep's forces: restitution reverses the approach speed
    /// they give (Box2D's "relax" velocity). Empty when no stage took them this substep.
    std::vector<BodyVelocity> velocitiesBeforeForces;
    int contactsFoundAtSubstep = 0;  // when World::contacts were last searched; later substeps
                                     // move their points with the bodies before solving
    SolverStats solver;          // of the last solve (the last substep of the last frame)
    int contactPointsDropped = 0;  // by the last cache upkeep: points that carried no load
    int manifoldsReused = 0;     // by the last search: records carried without a shape query (chapter 10)
    int manifoldsRebuilt = 0;    // by the last search: pairs the shapes were queried for (chapter 10)
    CcdState ccd;                // continuous collision (chapter 7)
    IterationPlan iterationPlan; // the fast solve's substep count (chapters 11 and 12)
    /// The joints' rows the fast solve's last piece left (chapter 11), shared by copies of the
    /// World until one steps on: the step that takes them copies them first when they are shared.
    std::shared_ptr<HandedJointRows> jointRows;
    std::size_t jointRowsBytes = 0;  // what they hold (chapter 9's snapshots count it)
};

}  // namespace stepwise
