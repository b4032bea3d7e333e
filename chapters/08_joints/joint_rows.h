#pragma once
// Each joint type as constraint rows (chapter 4's ConstraintRow): a position constraint C(x) = 0
// (or C >= 0 for a limit) becomes the velocity row J v = bias, J = dC/dx, with the bias feeding
// the position error back. The point of a ball socket (three rows: the anchors coincide) is
// solved as one 3x3 block; every other row is scalar. Rows are rebuilt from the poses at every
// solve, and start from the impulses the joint carried (World::jointImpulses), like contacts.
//
// Slots (JointImpulses::slot), per type:
//   distance    0 along the anchors' line (rigid, or a spring)
//   ball_socket 0-2 point
//   hinge       0-2 point, 3-4 the two turns off the axis, 5 lower limit, 6 upper limit, 7 motor
//   cone_twist  0-2 point, 3 swing cone, 4 twist lower, 5 twist upper, 6-8 joint friction
//   slider      0-1 the two moves off the axis, 2-4 the three turns, 5 lower, 6 upper, 7 motor
//   fixed       0-2 point, 3-5 the three turns

#include "04_pgs/constraint_row.h"
#include "06_manifolds/stabilisation.h"
#include "08_joints/joint_frame.h"
#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stepwise {

// [ch08-feedback]
/// How a solve feeds position errors back into the equality rows and the violated limits:
/// Baumgarte's fraction of the error per step (rigid rows), Box2D v3's soft constraint (a stiff
/// spring-damper), or nothing (the relax pass: velocities only). A limit that is not reached is
/// speculative in every case: the row lets the bodies close the gap in this step, no more.
struct JointFeedback {
    enum class Kind { Baumgarte, Soft, None };
    Kind kind = Kind::Baumgarte;
    Real baumgarte = Real(0.2);
    Softness soft;
};
// [ch08-feedback]

/// The fastest a joint's position feedback moves its bodies back together: Box2D v3's contact
/// push-out speed, and a turn rate that moves a 1 m limb's end as fast.
constexpr Real kMaxJointPushOutSpeed = 3;   // m/s
constexpr Real kMaxJointPushOutTurn = 3;    // rad/s

/// A joint's rows in JointRows::rows: [firstRow, firstRow + rowCount), slot i at firstRow + i.
struct JointRowSet {
    int joint = -1;
    int firstRow = 0;
    int rowCount = 0;
    bool pointBlock = false;      // slots 0-2 are solved together with pointMass (their rows' own mass is 0)
    Mat3 pointMass = Mat3::Zero();  // K^-1 of the point block
    Vec3 pointArmA = Vec3::Zero();  // the block's arms from the centres of mass to the anchors
    Vec3 pointArmB = Vec3::Zero();
};

/// What a row's bias is made from (applyRowFeedback).
enum class JointRowKind : char {
    Equality,   // C = 0: the error fed back by the feedback's rule
    Limit,      // C >= 0: speculative while open, fed back like an equality once passed
    Spring,     // a distance spring: its own softness
    Free,       // a motor, joint friction or an unused slot: the bias is a speed, not an error
};

struct JointRows {
    std::vector<ConstraintRow> rows;
    std::vector<Softness> softness;   // one per row
    std::vector<char> fedBack;        // one per row: its bias and softness are the feedback's (an equality)
    std::vector<JointRowKind> kind;   // one per row
    std::vector<Real> error;          // one per row: the position error C its bias comes from (0 for Free)
    std::vector<JointRowSet> joints;
    int invalidSkipped = 0;           // joints with bad bodies or non-finite data: left out

    /// Empty, keeping the vectors' room (a solve builds its rows again every substep).
    void clear() {
        rows.clear();
        softness.clear();
        fedBack.clear();
        kind.clear();
        error.clear();
        joints.clear();
        invalidSkipped = 0;
    }
};

/// One joint's rows as built, before a solve takes them: what appendJointRows adds to a
/// JointRows, held in place so that a solve with its own row layout (chapter 11's packed rows)
/// takes them without a list in between. Slot i is rows[i], as in JointImpulses.
struct JointRowBatch {
    static constexpr int kMaxRows = JointImpulses::kSlots;
    int count = 0;
    ConstraintRow rows[kMaxRows];
    Softness softness[kMaxRows];
    bool fedBack[kMaxRows] = {};
    JointRowKind kind[kMaxRows] = {};
    Real error[kMaxRows] = {};
    bool used[kMaxRows] = {};       // false: a slot the joint does not use now (no Jacobian)
    JointRowSet set;                // the point block; firstRow 0, rowCount = count
};

/// What a solve reads of a batch besides the biases, bounds, softness and impulses. Chapter 8's
/// solve reads every row's Jacobian and effective mass (its warm start pushes the point rows by
/// their Jacobians). A solve that packs the rows itself (chapter 11) makes M^-1 J^T anyway, and
/// the effective mass with it, and pushes a point block by its arms: making them here too is
/// work thrown away, a third of a ragdoll joint's.
struct JointBatchNeeds {
    bool pointJacobians = true;   // false: a point block's rows carry only their linear part
    bool effectiveMasses = true;  // false: every row's effectiveMass is left 0
};

/// The slots the rules below fill for a joint of `type`, used or not (JointImpulses::slot): a
/// hinge's three point rows, two across its axis, two limits and a motor; a cone twist's three
/// point rows, the swing, two twist limits and three friction rows. They depend on the type alone.
constexpr int jointSlotCount(JointType type) {
    switch (type) {
        case JointType::Distance: return 1;
        case JointType::BallSocket: return 3;
        case JointType::Fixed: return 6;
        case JointType::Hinge:
        case JointType::Slider: return 8;
        case JointType::ConeTwist: return 9;
    }
    return JointRowBatch::kMaxRows;
}

/// Whether a joint of `type` solves slots 0-2 (its anchors together) as one 3x3 block.
constexpr bool hasPointBlock(JointType type) { return type != JointType::Distance && type != JointType::Slider; }

/// A point block's K counts as singular (both bodies fixed, or nearly) below this determinant,
/// relative to the cube of its norm: the block's rows then stay scalar.
constexpr Real kSingularPointBlock = Real(1e-9);

/// Whether a point block with K of this norm and determinant is inverted (setPointBlock; chapter
/// 11's lane build decides each lane by the same rule).
inline bool pointBlockInvertible(Real norm, Real determinant) {
    return norm > 0 && std::abs(determinant) > kSingularPointBlock * norm * norm * norm;
}

/// Builds the rows of `joint` at `frame` into `batch` (appendJointRows' rules, the same numbers):
/// false, with nothing to solve, if any row came out non-finite.
bool buildJointRowBatch(JointRowBatch& batch, const JointDesc& joint, int jointIndex, const JointFrame& frame,
                        int rowBodyA, int rowBodyB, const std::vector<SolverBody>& bodies, Real h,
                        const JointFeedback& feedback, const JointImpulses* carried,
                        const JointBatchNeeds& needs = JointBatchNeeds{});

/// A distance joint's line where `frame` has its anchors: the unit direction from A's anchor to
/// B's (zero where they coincide) and the row's error, the length less the rest length.
struct DistanceLine {
    Vec3 direction = Vec3::Zero();
    Real error = 0;
};
DistanceLine distanceLine(const JointDesc& joint, const JointFrame& frame);

/// Appends the rows of World::joints[jointIndex] for a step of h, effective masses filled in,
/// accumulated impulses loaded from World::jointImpulses when `carryImpulses` (and clamped to
/// this step's bounds), zero otherwise.
void appendJointRows(JointRows& out, const World& world, int jointIndex, const std::vector<SolverBody>& bodies, Real h,
                     const JointFeedback& feedback, bool carryImpulses);

/// The same for a solve that keeps its own body list and impulses: the rows of `joint`
/// (World::joints[jointIndex]) at `frame`, between the bodies `bodies` holds at rowBodyA and
/// rowBodyB, starting from `carried` (nullptr: zero). The joint's bodies must be valid.
void appendJointRows(JointRows& out, const JointDesc& joint, int jointIndex, const JointFrame& frame, int rowBodyA,
                     int rowBodyB, const std::vector<SolverBody>& bodies, Real h, const JointFeedback& feedback,
                     const JointImpulses* carried);

/// A row's bias, softness and fedBack from its kind and position error by the feedback's rule, for
/// a step of h: what every build does for every row, and what a solve that moves a row's error
/// without building the row again (chapter 11's kept rows) does. `movesPoints`: the row has a
/// linear part (its push-out is capped as a speed, else as a turn rate). A spring's `softness`
/// is its own and is read, not set.
// [ch08-bias]
// C = 0 wanted: the error goes back in by the feedback's rule. The push back is capped
// (kMaxJointPushOutSpeed, kMaxJointPushOutTurn): a joint that starts 25 cm apart would otherwise
// ask for 40 m/s, and what a static body pushes back with stays in the bodies as momentum that no
// relax pass takes out (uncapped, scenes/two-box-stack.json's distance joint throws its 65 kg ball
// 12 m up). A limit not reached is speculative: the row only stops the bodies from closing the
// gap by more than it is in this step. Passed, it is fed back like an equality. Inline: chapter 11
// runs it for every kept row every substep.
inline void jointRowFeedback(Real& bias, Softness& softness, bool& fedBack, JointRowKind kind, Real error, bool movesPoints,
                             const JointFeedback& feedback, Real h) {
    switch (kind) {
        case JointRowKind::Free: return;
        case JointRowKind::Spring: bias = -softness.biasRate * error; return;
        case JointRowKind::Limit:
            if (error > 0) {
                bias = -error / h;
                softness = Softness{};
                fedBack = false;
                return;
            }
            break;  // passed: an equality
        case JointRowKind::Equality: break;
    }
    Softness soft;
    bias = 0;
    if (feedback.kind == JointFeedback::Kind::Baumgarte) bias = -feedback.baumgarte * error / h;
    if (feedback.kind == JointFeedback::Kind::Soft) {
        soft = feedback.soft;
        bias = -soft.biasRate * error;
    }
    const Real cap = movesPoints ? kMaxJointPushOutSpeed : kMaxJointPushOutTurn;
    bias = std::clamp(bias, -cap, cap);
    softness = soft;
    fedBack = true;
}
// [ch08-bias]

/// One Gauss-Seidel pass over one joint's rows: the point block first, then the scalar rows.
void solveJointRows(JointRows& rows, const JointRowSet& set, std::vector<SolverBody>& bodies);

}  // namespace stepwise
