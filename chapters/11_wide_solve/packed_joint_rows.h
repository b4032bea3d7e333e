#pragma once
// A substep's joint rows, as the fast solve sweeps them three times (warm start, biased pass,
// relax pass). Chapter 8's rules build each joint's rows (buildJointRowBatch), and they go
// straight into this layout, with no list of rows in between. Chapter 8's rows name their bodies
// and carry the Jacobian J; every sweep then
// multiplies J by the bodies' inverse mass and inertia again (M^-1 J^T, two 3x3 products a row).
// The inertia is the frame's for the whole substep, so the product is made once, when the rows
// are packed, and the sweeps read and write the solve's body states by slot. Rows without a
// Jacobian's effect (an unused slot, a joint whose bodies cannot both move it) are left out: the
// sweeps skip them anyway. The rules (bias, softness, clamping, the point block) are chapter 8's.
// The rows lie in lanes, as the contacts' blocks do: row k of a group of joints that share no
// moving body side by side (JointLaneGroup), swept a group at a time (packed_joint_sweep.cpp).
// PackedJointRow and PackedPointBlock are one lane's row and block, as the build writes them and
// tests read them back.

#include "08_joints/joint_frame.h"
#include "08_joints/joint_rows.h"
#include "11_wide_solve/solver_data.h"

#include <cstdint>
#include <vector>

namespace stepwise {

/// One scalar row of a joint, ready to sweep.
struct PackedJointRow {
    int slotA = 0, slotB = 0;   // the bodies' solver slots (0: does not move)
    int slot = 0;               // its joint's slot (JointImpulses::slot): where its impulse goes back
    bool fedBack = false;       // the relax pass takes its bias and softness out
    bool turnOnly = false;      // no linear part (a hinge's, a cone's, a limit's turn): the sweeps skip it
    JointRowKind kind = JointRowKind::Free;  // what its bias is made from (chapter 8's jointRowFeedback)
    Real error = 0;             // its position error C, moved to first order while the row is kept
    Vec3 linearA = Vec3::Zero(), angularA = Vec3::Zero(), linearB = Vec3::Zero(), angularB = Vec3::Zero();  // J
    Vec3 moveLinearA = Vec3::Zero(), moveAngularA = Vec3::Zero();  // M^-1 J^T: the velocity one unit of impulse adds
    Vec3 moveLinearB = Vec3::Zero(), moveAngularB = Vec3::Zero();
    Real effectiveMass = 0, bias = 0, lower = 0, upper = 0, impulse = 0;
    Softness soft;
};

/// A ball socket's three point rows, solved as chapter 8's 3x3 block.
struct PackedPointBlock {
    int slotA = 0, slotB = 0;
    bool fedBack[3] = {false, false, false};
    Vec3 armA = Vec3::Zero(), armB = Vec3::Zero();
    Mat3 mass = Mat3::Zero();          // K^-1
    Real inverseMassA = 0, inverseMassB = 0;
    Mat3 inverseInertiaA = Mat3::Zero(), inverseInertiaB = Mat3::Zero();
    Vec3 bias = Vec3::Zero(), impulse = Vec3::Zero();
    Vec3 error = Vec3::Zero();         // the anchors' gap, moved to first order while the block is kept
    Softness soft;
};

/// Row k of up to kWideLanes joints, one joint per lane: what the sweeps read and write, laid out
/// as the contacts' blocks are, so that one stream of SIMD instructions sweeps a row of every
/// joint of a group at once. A lane without such a row holds zeros: no Jacobian, no mass, no
/// impulse, so its sweep changes nothing.
struct JointRowLanes {
    PackVec3<kWideLanes> linearA, angularA, linearB, angularB;                  // J
    PackVec3<kWideLanes> moveLinearA, moveAngularA, moveLinearB, moveAngularB;  // M^-1 J^T
    Pack<kWideLanes> effectiveMass, bias, lower, upper, impulse, error;
    Pack<kWideLanes> biasRate, massScale, impulseScale;  // the row's Softness
    Pack<kWideLanes> fedBack;   // 1 where the relax pass takes the bias and softness out
    Pack<kWideLanes> advances;  // 1 where the substeps move the error (advancePackedErrors)
    Pack<kWideLanes> isSpring, isLimit, isEquality;  // 1 where the row is of that kind (its feedback's case)
    Pack<kWideLanes> pushCap;   // its feedback's cap: kMaxJointPushOutSpeed, or Turn for a turn-only row
    // What only the scalar work per joint reads (feedback, impulses back):
    int slot[kWideLanes] = {};
    JointRowKind kind[kWideLanes] = {};
    bool turnOnly[kWideLanes] = {};
};

/// The point blocks of a group's joints, one per lane (zeros where a joint has none).
struct JointBlockLanes {
    PackVec3<kWideLanes> armA, armB;
    Pack<kWideLanes> mass[9];  // K^-1, row by row
    Pack<kWideLanes> inverseMassA, inverseMassB;
    Pack<kWideLanes> inverseInertiaA[9], inverseInertiaB[9];  // row by row (as the frame made them)
    PackVec3<kWideLanes> bias, impulse, error;
    Pack<kWideLanes> biasRate, massScale, impulseScale;
    Pack<kWideLanes> fedBack[3];
    Pack<kWideLanes> present;  // 1 where the lane's joint has a block (the substeps move its error)
};

// [ch11-joint-lanes]
/// Up to kWideLanes joints that share no moving body, swept side by side: part of a colour of the
/// graph whose nodes are the bodies and whose edges are the joints (layOutPackedJoints). The joints
/// of a group touch different bodies, so sweeping them side by side gives the same numbers as
/// sweeping them one after another: the sweep over the groups is Gauss-Seidel joint after joint,
/// in the groups' order.
struct JointLaneGroup {
    int slotA[kWideLanes] = {}, slotB[kWideLanes] = {};  // the bodies' solver slots (0: an empty lane)
    int entry[kWideLanes] = {};  // each lane's joint (PackedJointRows::joints)
    int lanes = 0;       // lanes holding a joint
    bool blocks = false;  // some lane has a point block
    int rowCount = 0;    // rows with room: the most any lane's joint reserved
    int rowsInUse = 0;   // rows the sweeps take: the most any lane's joint has written this frame
    JointBlockLanes block;
    std::vector<JointRowLanes> rows;
    // Whether a lane's joint may keep its rows to the next substep (joint_pass.h, kJointRowsKeptTurn):
    PackQuat<kWideLanes> builtA, builtB;  // its bodies' turns since the piece began, when its rows were built
    unsigned keepableLanes = 0;  // bit per lane: its rows follow its bodies' turns alone (the substeps move their errors)
    unsigned builtLanes = 0;     // bit per lane: its rows are in use (built, not left out)
};
// [ch11-joint-lanes]

/// One joint: its group and lane, whether it has a block, its rows there, in chapter 8's order.
/// Each joint keeps its lane and room for the whole frame, so a joint built again mid-frame
/// writes over its own rows and a kept one stays where it is.
struct PackedJoint {
    int joint = 0;                // the caller's index of the joint (its carried impulses)
    int slotCount = 0;            // the joint's slots, used or not
    bool hasBlock = false;        // its point block is in use this substep
    bool blockRoom = false;       // a point block is reserved for it
    int rowCount = 0;             // rows in use, from row 0 of its group
    int rowRoom = 0;              // rows reserved
    int group = 0, lane = 0;      // into PackedJointRows::groups
    bool keepable = true;         // its rows may be kept to the next substep (else built every substep)
};

struct PackedJointRows {
    /// No joints; the groups keep their room (a frame lays them out again over the last frame's).
    void clear() {
        joints.clear();
        groupCount = 0;
    }
    std::vector<PackedJoint> joints;
    std::vector<JointLaneGroup> groups;  // the first groupCount are this frame's
    int groupCount = 0;
    // The layout's buffers (layOutPackedJoints), kept for their room:
    std::vector<std::uint64_t> coloursOfSlot;  // per solver slot: a bit per colour holding one of its joints
    std::vector<int> colourOfJoint, colourStart, colourOrder, colourFill;
};

/// What one joint asks of the layout: room for `rows` rows and, with `block`, a point block;
/// `keepable`: its rows may be kept to the next substep (else built every substep, and
/// advancePackedErrors leaves them be); its bodies' solver slots (0: does not move); `joint`, the
/// caller's index of it.
struct JointRoom {
    int joint = 0;
    int rows = 0;
    bool block = false;
    bool keepable = false;
    int slotA = 0, slotB = 0;
};

/// Colours one bit each of a body's mask stands for; past them a joint of that body takes a
/// colour of its own. A body with more joints than this is a hub (a rope's anchor, a wheel's
/// spokes), whose joints each cost a part-empty group's sweep and nothing else.
constexpr int kMaskedColours = 64;

/// Lays out a frame's joints, entry i for rooms[i], empty until written (writePackedJoint,
/// writeDistanceJoint): each joint's colour is the first that holds neither of its moving bodies
/// (greedy colouring, as Box2D v3 colours its constraint graph), and the groups are the colours in
/// order, each cut into groups of kWideLanes joints. Within a colour no two joints share a moving
/// body, so the sweep's numbers are the same at every width.
void layOutPackedJoints(PackedJointRows& packed, const std::vector<JointRoom>& rooms);

/// One more joint (entry: the next) in a group of its own: a layout of single joints, for tests of
/// one joint's rows.
void reservePackedJoint(PackedJointRows& packed, int joint, int rows, bool block, bool keepable, int slotA = 0,
                        int slotB = 0);

/// Joint `entry`'s rows were built where its bodies had turned by `turnA` and `turnB` since the
/// piece began (`built`), or left out (not `built`).
void markPackedBuilt(PackedJointRows& packed, int entry, bool built, const Quat& turnA = Quat::Identity(),
                     const Quat& turnB = Quat::Identity());

/// The lanes of `group` (bit i: lane i) whose two bodies have each turned at most `most` (rad)
/// since the lane's rows were built, by the body states' turns since the piece began, in the
/// small-angle form 1 - w^2 <= most^2 / 4 (w: the dot product of the two turns, as Eigen sums four
/// products: (x + z) + (y + w)).
unsigned lanesTurnedAtMost(const JointLaneGroup& group, const SolverBodyState* states, Real most);

/// Each lane's turns at build (JointLaneGroup::builtA, builtB) made relative to where its bodies
/// stand now, `states` holding their turns since the piece began: what a piece hands on
/// (joint_hand_on.h). Slot 0 and empty lanes keep theirs.
void rebaseBuiltTurns(PackedJointRows& packed, const SolverBodyState* states);

/// Row k of joint `entry` as one row (what the sweeps read of it).
PackedJointRow packedRowOf(const PackedJointRows& packed, int entry, int k);
/// Writes row k of joint `entry`.
void storePackedRow(PackedJointRows& packed, int entry, int k, const PackedJointRow& row);
/// Joint `entry`'s point block (zeros if it has none).
PackedPointBlock packedBlockOf(const PackedJointRows& packed, int entry);

/// Writes one joint's rows (`batch`, built over the solver bodies `bodies`, entries `slotOfEntry`
/// in the solve's slots) into the room of `entry`, each row's M^-1 J^T and effective mass made
/// here (the batch needs neither). False, and the entry left empty, if they do not fit its room.
bool writePackedJoint(const JointRowBatch& batch, const std::vector<SolverBody>& bodies,
                      const std::vector<int>& slotOfEntry, PackedJointRows& packed, int entry);

/// Joint `entry`'s one row for the distance joint `joint` where `frame` (chapter 8's jointRowFrame)
/// has its anchors, between the entries `entryA` and `entryB` of `bodies`, its impulse `carried`
/// clamped to its bounds (and written back so): the numbers buildJointRowBatch and writePackedJoint make, written straight
/// into the room (a swinging chain builds every joint every substep, and the rows in between were
/// most of that work). False, the entry left empty, if the row came out non-finite or has no room.
bool writeDistanceJoint(const JointDesc& joint, const JointFrame& frame, int entryA, int entryB, Real h,
                        const JointFeedback& feedback, Real& carried, const std::vector<SolverBody>& bodies,
                        const std::vector<int>& slotOfEntry, PackedJointRows& packed, int entry);

/// One joint for buildJointLanes: what chapter 8's rules read of it, and where its impulses go.
struct LaneJoint {
    const JointDesc* joint = nullptr;
    JointFrame frame;                  // chapter 8's jointRowFrame where its bodies stand
    const SolverBody* bodyA = nullptr;  // its bodies' masses (JointPass::bodies)
    const SolverBody* bodyB = nullptr;
    const JointImpulses* carried = nullptr;  // the impulses it carries in
    JointImpulses seated;              // out: each slot's impulse clamped to its bounds (buildJointRowBatch's)
    int slots = 0;                     // out: its slots, used or not
};

/// Whether buildJointLanes takes joints of `type`: those solved with a point block.
constexpr bool buildsInLanes(JointType type) { return hasPointBlock(type); }

/// The joints of group `g` in `lanes` (bit i: lane i, joint `joints[i]`), built at once: chapter
/// 8's rules (joint_row_rules.h) write each joint's rows straight into its lane, then the feedback,
/// M^-1 J^T and the effective masses are made for all of them side by side. The same numbers as
/// buildJointRowBatch and writePackedJoint give joint by joint. Returns the lanes it leaves to them,
/// untouched: a joint whose K is singular, or with a row that is not finite or has no mass.
unsigned buildJointLanes(PackedJointRows& packed, int g, LaneJoint* joints, unsigned lanes, const JointFeedback& feedback,
                         Real h);

/// Each body's inverse mass and inertia (row by row) for the lanes of a group, sides A and B.
struct LaneMasses {
    Pack<kWideLanes> inverseMassA, inverseMassB;
    Pack<kWideLanes> inverseInertiaA[9], inverseInertiaB[9];
};

/// M^-1 J^T and the effective mass of rows 0 to rows[lane] - 1 of the lanes in `lanes`, as
/// writePackedJoint makes them (the rest keep what they hold).
void makeLaneMoves(JointLaneGroup& group, unsigned lanes, const int* rows, const LaneMasses& masses);

/// Chapter 8's point block K for each lane's arms and masses: K^-1 row by row, and the norm and
/// determinant of K by which chapter 8 decides whether K is invertible (setPointBlock).
void makeLanePointMasses(const PackVec3<kWideLanes>& armA, const PackVec3<kWideLanes>& armB, const LaneMasses& masses,
                         Pack<kWideLanes> (&inverse)[9], Pack<kWideLanes>& scale, Pack<kWideLanes>& determinant);

/// Leaves joint `entry` out of the sweeps (no block, no rows) until it is written again.
void emptyPackedJoint(PackedJointRows& packed, int entry);

/// Every keepable joint's rows' and block's position error moved by what the velocities in
/// `states` do to it over h: C += h J v, the first-order change (the rows' Jacobians are dC/dx).
void advancePackedErrors(PackedJointRows& packed, const SolverBodyState* states, Real h);

/// Joint `entry`'s biases, softness and fedBack made again from its rows' errors by chapter 8's
/// rule (jointRowFeedback), for a substep of h.
void refreshPackedFeedback(PackedJointRows& packed, int entry, const JointFeedback& feedback, Real h);

/// The same for the lanes of group `group` set in `lanes` (bit i: lane i), all at once: what a
/// substep does for the joints it keeps. Any feedback kind; the soft step's runs in lanes.
void refreshPackedFeedbackLanes(PackedJointRows& packed, int group, unsigned lanes, const JointFeedback& feedback, Real h);

/// The carried impulses applied to the bodies.
void warmStartPacked(const PackedJointRows& packed, SolverBodyState* states);

/// One Gauss-Seidel sweep, joint after joint (group after group, the same numbers): biased, or
/// (`relax`) without the feedback.
void solvePacked(PackedJointRows& packed, SolverBodyState* states, bool relax);

/// The sweeps' impulses back into the joints' carried impulses (`carried`, by PackedJoint::joint);
/// the slots the sweeps leave out keep what they hold.
void keepPackedImpulses(const PackedJointRows& packed, std::vector<JointImpulses>& carried);

/// The same for joint `entry` alone.
void keepPackedImpulsesOf(const PackedJointRows& packed, int entry, std::vector<JointImpulses>& carried);

/// Every impulse zero, in the sweeps and in `carried` (a solve without warm starting).
void resetPackedImpulses(PackedJointRows& packed, std::vector<JointImpulses>& carried);

}  // namespace stepwise
