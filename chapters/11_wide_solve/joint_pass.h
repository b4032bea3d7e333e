#pragma once
// Joints, springs and drag in the fast solve. The contacts are coloured and solved many at a
// time; a joint needs more than a contact row does (up to ten rows, limits that switch on and
// off, motors), and a scene has far fewer of them, so they are solved in chapter 8's order, with
// its rows (eight at a time where they share no body: packed_joint_rows.h), in the same substeps
// as the contacts and on the same bodies: warm started, the soft
// step's biased pass, the relax pass, every substep (Box2D v3 and Box3D solve joints and contacts
// in one graph the same way). What makes them fast is what makes the contacts fast: one pass
// over everything per substep, no second solve.
//
// A joint's rows are built where its bodies stand in the substep (their moves since the piece
// began, SolverBodyState), or kept from the last substep while its bodies have barely turned
// (kJointRowsKeptTurn), from substep to substep and from frame to frame (joint_hand_on.h),
// with the inverse inertia of the frame they were built in, as the contacts take it; the relax
// pass takes the same rows with the feedback taken out. Building them once a frame and moving
// only their errors to first order does not do: a chain's link swinging 8 cm across its
// neighbour in a frame stretches by 1.3 cm to first order. Moving the Jacobians and keeping the
// effective masses does not either: the arms turn, the frame's inertia does not, and a row's mass
// can fall to half of what it answers with (a ragdoll's shin spun up and blew apart). Chapter 8's
// rules build them, one joint at a time (buildJointRowBatch); the three sweeps take them packed
// (packed_joint_rows.h: chapter 8's sweep, with M^-1 J^T made once a substep), one physics,
// whichever solve runs it.

#include "01_integrators/forces.h"
#include "08_joints/joint_solver.h"
#include "11_wide_solve/packed_joint_rows.h"
#include "11_wide_solve/solver_data.h"
#include "world/world.h"

#include <memory>
#include <vector>

namespace stepwise {

// [ch11-joint-softness]
/// The joints' spring is at most this fraction of the substep rate, whatever Settings::jointHertz
/// asks: chapter 8 measured a quarter as the stiffest a chain resolves with one biased sweep a
/// substep (at a half, a 10-link chain diverges).
constexpr Real kJointHertzPerSubstepRate = Real(0.25);
// [ch11-joint-softness]

/// The joints' feedback in substeps of h: Settings::jointHertz and jointDampingRatio, the hertz
/// capped at kJointHertzPerSubstepRate / h.
JointFeedback fastJointFeedback(const Settings& settings, Real h);

/// What the fast solve keeps for the frame's joints and forces: rebuilt from the World every
/// piece; what one piece hands the next (the impulses, and the rows a joint may keep) goes back
/// into the World (World::jointImpulses, StepState::jointRows), so the pass carries nothing.
struct JointPass {
    std::vector<int> joints;           // into World::joints: those with a moving body, in sweep order
    std::vector<int> entryA, entryB;   // per listed joint: its bodies' entries in `bodies`
    std::vector<int> worldBody;        // per entry: the World body
    std::vector<int> slot;             // per entry: its solver slot (0: static or asleep)
    std::vector<int> entryOfBody;      // per World body: its entry, or -1
    std::vector<SolverBody> bodies;    // chapter 4's view of the joints' bodies, this substep
    std::vector<JointImpulses> carried;  // per listed joint: its impulses from substep to substep
    struct BodyPose {
        Transform transform;
        Vec3 center = Vec3::Zero();
    };
    std::vector<BodyPose> poses;       // per entry: where it stands this substep, once a joint built asks
    std::vector<int> placedAt;         // per entry: the substep its pose was made for (-1: none yet)
    int substepStamp = 0;              // counts the substeps buildJointRows has run
    std::vector<Vec3> startArmA, startArmB;  // per listed distance joint: centre to anchor as the piece began, world axes (others zero)
    JointRowBatch batch;               // one joint's rows, as chapter 8 builds them
    bool laneBuild = true;             // point joints built a lane group at a time (buildJointLanes); false: one by one
    std::vector<unsigned> lanesToBuild;  // per lane group: the lanes buildJointLanes takes this substep
    std::vector<LaneJoint> laneJoints;   // kWideLanes per lane group: what it reads of each
    std::vector<JointRoom> rooms;      // what each listed joint asks of the lanes' layout
    PackedJointRows packed;            // this substep's rows, as the sweeps take them (listed joint i is entry i)
    std::vector<int> packedEntry;      // per listed joint: its entry in `packed`, or -1 (left out this substep)
    std::vector<unsigned> keptLanes;   // per lane group: the lanes whose point joint keeps its rows this substep
    std::vector<int> notKept;          // the listed joints that do not keep their rows this substep, in list order
    bool laidOut = false;              // the lanes are laid out as the last piece left them (takeHandedJointRows)
    std::vector<unsigned> handedLanes; // per lane group: the lanes whose joint may keep the last piece's rows
    std::shared_ptr<HandedJointRows> handOn;  // what the last piece handed on, taken for this one
    std::vector<char> bodyUnchanged;   // per entry: as the last piece left it (takeHandedJointRows)
    std::vector<char> descHanded;      // per listed joint: its description is the handed one (when laidOut)
    int rowCount = 0;                  // this substep's rows, used slots or not (the run report's)
    int jointsBuilt = 0, jointsKept = 0;  // this frame's substeps: joints whose rows were built, kept
    int invalidSkipped = 0;            // joints left out this substep: their rows came out non-finite
    JointSweep sweep;
    // Springs and drag: chapter 1's forces at each substep's state, per motion.
    std::vector<MotionState> forceStates;
    std::vector<Wrench> forces;
};

/// Whether the world has anything the pass solves: joints, springs or drag.
bool needsJointPass(const World& world);

/// The frame's joints with at least one moving body, their bodies, and their impulses from
/// World::jointImpulses times `carryScale` (the substep count changed).
void prepareJointPass(const World& world, const SolverBodies& bodies, Real carryScale, JointPass& pass);

// [ch11-kept-turn]
/// A joint keeps last substep's rows while neither body has turned more than this since they were
/// built (rad): its Jacobians then stand where the arms and axes were, and its errors move to first
/// order (advanceJointErrors). A frozen arm of length r misplaces its anchor by about
/// turn^2 r / 2, 50 micrometres for a 1 m arm at this turn (a ragdoll's arms are a fifth of
/// that), where the joints' own error at rest is a millimetre. The same bound holds across the
/// frame's boundary (joint_hand_on.h). Against 5 mrad it saves 4.8% of the instructions of the
/// 100-ragdoll field's first 120 frames; 20 mrad would save 2.9% more for four times the
/// misplacement.
constexpr Real kJointRowsKeptTurn = Real(0.01);
// [ch11-kept-turn]

/// The rows for a substep of h, where the bodies stand now, from the carried impulses; a point
/// joint (ball socket, hinge, cone twist, fixed) whose bodies have turned at most
/// kJointRowsKeptTurn since its rows were built keeps them, its biases made again from its moved
/// errors, and so does a distance joint whose line between the anchors has turned no more either,
/// its error measured. On the piece's first substep only the joints the last piece handed on
/// (takeHandedJointRows) may keep theirs.
void buildJointRows(const World& world, const SolverBodies& bodies, Real h, bool firstSubstep, JointPass& pass);

/// Where entry `entry` of the pass stands this substep: its start moved by the substeps so far
/// (slot 0 does not move). Made once a substep, when a joint built in it first asks.
const JointPass::BodyPose& placeJointBody(const World& world, const SolverBodies& bodies, JointPass& pass, std::size_t entry);

/// Every row's position error moved by the velocities the bodies moved with in this substep
/// (after the biased pass, before the relax pass), the piece's last substep too: the next piece
/// may keep the rows (joint_hand_on.h).
void advanceJointErrors(JointPass& pass, const SolverBodyState* states, Real h);

/// The carried impulses applied to the bodies (the warm start); without warm starting, every
/// substep's impulses start from zero.
void warmStartJoints(JointPass& pass, SolverBodyState* states, bool warmStarting);

/// One Gauss-Seidel sweep over the joints: biased, or (`relax`) the same rows without feedback.
void solveJoints(JointPass& pass, SolverBodyState* states, bool relax);


/// The impulses the sweeps ended with, into the joints' carried ones: once, when the piece's
/// substeps end (a joint built again mid-piece takes its own first, buildJointRows).
void keepJointImpulses(JointPass& pass);

/// The carried impulses back into World::jointImpulses.
void storeJointImpulses(const JointPass& pass, World& world);

/// Chapter 1's forces (gravity, springs, drag) at the substep's state of every body, into
/// pass.forces (per motion).
void evaluateSubstepForces(const World& world, const SolverBodies& bodies, JointPass& pass);

}  // namespace stepwise
