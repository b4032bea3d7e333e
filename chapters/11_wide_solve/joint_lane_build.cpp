// A lane group's joints built at once (packed_joint_rows.h, buildJointLanes). Chapter 8's rules
// write each joint's rows straight into its lane; what every row then needs (its feedback, its
// M^-1 J^T and effective mass) is made for the whole group in lanes. Joint by joint, chapter 8's
// batch and writePackedJoint spent most of a ragdoll joint's build on that per-row work.
#include "11_wide_solve/packed_joint_rows.h"

#include "08_joints/joint_row_rules.h"
#include "11_wide_solve/joint_lane_storage.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

constexpr int N = kWideLanes;

// Chapter 8's seatRow: the impulse carried in, clamped to this step's bounds (zero if not finite).
Real seated(Real carried, Real lower, Real upper) {
    return std::isfinite(carried) ? std::clamp(carried, lower, upper) : Real(0);
}

// The rules' Builder (joint_row_rules.h) for one lane: each used slot past the point block goes
// into the next row of the lane as chapter 8's RowBuilder and writePackedJoint would put it, less
// the feedback and the masses, which the group makes afterwards; the point rows' errors and
// impulses go to the block.
class LaneRecorder {
public:
    LaneRecorder(JointLaneGroup& group, int lane, bool keepable, LaneJoint& joint, Real h)
        : group_(group), lane_(lane), keepable_(keepable), joint_(joint), h_(h) {}

    bool blockWithoutJacobians = true;  // a block's rows: their linear part alone (never read here)

    void equality(const ConstraintRow& row, Real error) { add(row, JointRowKind::Equality, error, Softness{}); }
    void limit(ConstraintRow row, Real gap) {
        row.lower = 0;
        add(row, JointRowKind::Limit, gap, Softness{});
    }
    void motor(ConstraintRow row, Real speed, Real maxForce) {
        row.bias = speed;
        row.lower = -maxForce * h_;
        row.upper = maxForce * h_;
        add(row, JointRowKind::Free, 0, Softness{});
    }
    void unused(int, int) { seat(-kRealMax, kRealMax); }
    void spring(const ConstraintRow& row, Real error, const Softness& soft) { add(row, JointRowKind::Spring, error, soft); }

    int rows() const { return rows_; }
    int slots() const { return slot_; }
    const Vec3& blockError() const { return blockError_; }
    const Vec3& blockImpulse() const { return blockImpulse_; }

private:
    Real seat(Real lower, Real upper) {
        const Real impulse = seated(joint_.carried->slot[slot_], lower, upper);
        joint_.seated.slot[slot_++] = impulse;
        return impulse;
    }

    void add(const ConstraintRow& row, JointRowKind kind, Real error, const Softness& soft) {
        const int slot = slot_;
        const Real impulse = seat(row.lower, row.upper);
        if (slot < 3) {  // the point block's (every joint built here has one)
            blockError_[slot] = error;
            blockImpulse_[slot] = impulse;
            return;
        }
        // storeRow's fields but the masses (makeLaneMoves) and the feedback's (the group's, after).
        JointRowLanes& to = rowToWrite(group_, rows_++);
        const int lane = lane_;
        const auto put = [lane](PackVec3<N>& field, const Vec3& v) {
            field.x[lane] = v.x();
            field.y[lane] = v.y();
            field.z[lane] = v.z();
        };
        put(to.linearA, row.linearA);
        put(to.angularA, row.angularA);
        put(to.linearB, row.linearB);
        put(to.angularB, row.angularB);
        const bool turnOnly = row.linearA.isZero(0) && row.linearB.isZero(0);
        to.bias[lane] = row.bias;
        to.lower[lane] = row.lower;
        to.upper[lane] = row.upper;
        to.impulse[lane] = impulse;
        to.error[lane] = error;
        to.biasRate[lane] = soft.biasRate;
        to.massScale[lane] = soft.massScale;
        to.impulseScale[lane] = soft.impulseScale;
        to.fedBack[lane] = 0;
        to.slot[lane] = slot;
        storeRowKind(to, lane, kind, turnOnly, keepable_);
    }

    JointLaneGroup& group_;
    int lane_;
    bool keepable_;
    LaneJoint& joint_;
    Real h_;
    int slot_ = 0, rows_ = 0;
    Vec3 blockError_ = Vec3::Zero(), blockImpulse_ = Vec3::Zero();
};

// Chapter 8's finiteRow over a lane's built row: its Jacobian and bias.
bool finiteLane(const JointRowLanes& row, int lane) {
    const Real values[] = {row.linearA.x[lane],  row.linearA.y[lane],  row.linearA.z[lane],  row.angularA.x[lane],
                           row.angularA.y[lane], row.angularA.z[lane], row.linearB.x[lane],  row.linearB.y[lane],
                           row.linearB.z[lane],  row.angularB.x[lane], row.angularB.y[lane], row.angularB.z[lane],
                           row.bias[lane]};
    return std::all_of(std::begin(values), std::end(values), [](Real x) { return std::isfinite(x); });
}

void putMasses(LaneMasses& masses, int lane, const SolverBody& a, const SolverBody& b) {
    masses.inverseMassA[lane] = a.inverseMass;
    masses.inverseMassB[lane] = b.inverseMass;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            masses.inverseInertiaA[3 * i + j][lane] = a.inverseInertia(i, j);
            masses.inverseInertiaB[3 * i + j][lane] = b.inverseInertia(i, j);
        }
}

// Lane `lane`'s rows from row 0 to `rows`, and its block, zero again: a lane left to the joint-by-joint build.
void clearLane(JointLaneGroup& group, int lane, int rows) {
    for (int k = 0; k < rows; ++k) zeroRow(group.rows[static_cast<std::size_t>(k)], lane);
    zeroBlock(group.block, lane);
}

}  // namespace

unsigned buildJointLanes(PackedJointRows& packed, int g, LaneJoint* joints, unsigned lanes, const JointFeedback& feedback,
                         Real h) {
    JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
    int rows[N] = {};
    unsigned left = 0, built = 0;
    LaneMasses masses;
    PackVec3<N> armA, armB;
    for (int lane = 0; lane < N; ++lane) {
        const bool taken = lanes >> lane & 1u;
        const LaneJoint& input = joints[lane];
        const Vec3 a = taken ? input.frame.armA : Vec3::Zero(), b = taken ? input.frame.armB : Vec3::Zero();
        armA.x[lane] = a.x(), armA.y[lane] = a.y(), armA.z[lane] = a.z();
        armB.x[lane] = b.x(), armB.y[lane] = b.y(), armB.z[lane] = b.z();
        if (taken) putMasses(masses, lane, *input.bodyA, *input.bodyB);
    }
    // The point blocks' K^-1 side by side; each lane decides as chapter 8's setPointBlock does.
    Pack<N> inverse[9], scale, determinant;
    makeLanePointMasses(armA, armB, masses, inverse, scale, determinant);
    // Each lane's rows by chapter 8's rules, written into the lane.
    for (int lane = 0; lane < N; ++lane) {
        if (!(lanes >> lane & 1u)) continue;
        LaneJoint& input = joints[lane];
        const PackedJoint& joint = packed.joints[static_cast<std::size_t>(group.entry[lane])];
        Mat3 mass;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) mass(i, j) = inverse[3 * i + j][lane];
        const bool invertible = pointBlockInvertible(scale[lane], determinant[lane]);
        if (!invertible || !mass.allFinite() || !joint.blockRoom) {  // singular: chapter 8 keeps the point rows scalar
            left |= 1u << lane;
            continue;
        }
        LaneRecorder recorder(group, lane, joint.keepable, input, h);
        joint_rules::addRowsOf(recorder, *input.joint, input.frame, h);
        rows[lane] = recorder.rows();
        input.slots = recorder.slots();
        PackedPointBlock block;
        block.armA = input.frame.armA;
        block.armB = input.frame.armB;
        block.mass = mass;
        block.inverseMassA = input.bodyA->inverseMass;
        block.inverseMassB = input.bodyB->inverseMass;
        block.inverseInertiaA = input.bodyA->inverseInertia;
        block.inverseInertiaB = input.bodyB->inverseInertia;
        block.impulse = recorder.blockImpulse();
        block.error = recorder.blockError();
        storeBlock(group.block, lane, block);  // its bias, softness and fedBack: the feedback below
        built |= 1u << lane;
    }
    if (built == 0) return left;
    // What every row needs, for the group at once: the feedback of its error, M^-1 J^T, its mass.
    refreshPackedFeedbackLanes(packed, g, built, feedback, h);
    makeLaneMoves(group, built, rows, masses);
    for (int lane = 0; lane < N; ++lane) {
        if (!(built >> lane & 1u)) continue;
        PackedJoint& joint = packed.joints[static_cast<std::size_t>(group.entry[lane])];
        bool kept = true;
        for (int k = 0; k < rows[lane] && kept; ++k) {
            const JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
            kept = finiteLane(row, lane) && row.effectiveMass[lane] != 0;  // writePackedJoint leaves a massless row out
        }
        const Real blockBias[] = {group.block.bias.x[lane], group.block.bias.y[lane], group.block.bias.z[lane]};
        kept = kept && std::all_of(std::begin(blockBias), std::end(blockBias), [](Real x) { return std::isfinite(x); });
        if (!kept) {
            clearLane(group, lane, rows[lane]);
            left |= 1u << lane;
            continue;
        }
        for (int k = rows[lane]; k < joint.rowCount; ++k) zeroRow(group.rows[static_cast<std::size_t>(k)], lane);
        joint.slotCount = joints[lane].slots;
        joint.hasBlock = true;
        joint.rowCount = rows[lane];
    }
    return left;
}

}  // namespace stepwise
