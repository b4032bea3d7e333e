#include "08_joints/joint_rows.h"

#include "04_pgs/contact_constraints.h"
#include "04_pgs/solver.h"
#include "08_joints/joint_frame.h"
#include "08_joints/joint_row_rules.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace stepwise {

namespace {

// x - x is 0 for every finite x and NaN for an infinity or a NaN, so one sum of them says whether
// all thirteen numbers are finite (one branch a row instead of thirteen).
bool finiteRow(const ConstraintRow& row) {
    const Real sum = (row.linearA - row.linearA).sum() + (row.angularA - row.angularA).sum() +
                     (row.linearB - row.linearB).sum() + (row.angularB - row.angularB).sum() + (row.bias - row.bias);
    return sum == 0;
}

void applyFeedback(ConstraintRow& row, Softness& softness, bool& fedBack, JointRowKind kind, Real error,
                   const JointFeedback& feedback, Real h);

// Collects one joint's rows, slot by slot, into a batch. A joint has at most
// JointRowBatch::kMaxRows slots (a cone twist: three point rows, the swing, two twist limits and
// three friction rows), so the rules below never write past it.
class RowBuilder {
public:
    RowBuilder(JointRowBatch& out, const JointFeedback& feedback, Real h) : out_(out), feedback_(feedback), h_(h) {}

    // The point rows of a block its solve pushes by the arms: their linear part alone, which is
    // all their feedback reads (the cap of a row that moves points).
    bool blockWithoutJacobians = false;

    void equality(ConstraintRow row, Real error) { add(row, Softness{}, JointRowKind::Equality, error); }

    // C >= 0 wanted (a limit), row J = dC/dt, impulse >= 0.
    void limit(ConstraintRow row, Real gap) {
        row.lower = 0;
        add(row, Softness{}, JointRowKind::Limit, gap);
    }

    // A row that drives J v towards `speed` with an impulse of at most maxForce h either way (a
    // motor; joint friction is a motor of speed zero).
    void motor(ConstraintRow row, Real speed, Real maxForce) {
        row.bias = speed;
        row.lower = -maxForce * h_;
        row.upper = maxForce * h_;
        add(row, Softness{});
    }

    // A slot the joint does not use now (no limit, no motor): a row without Jacobian, which the
    // solver skips, so every slot keeps its place.
    void unused(int bodyA, int bodyB) {
        ConstraintRow row;
        row.bodyA = bodyA;
        row.bodyB = bodyB;
        add(row, Softness{});
        out_.used[out_.count - 1] = false;
    }

    void spring(ConstraintRow row, Real error, const Softness& soft) { add(row, soft, JointRowKind::Spring, error); }

    void add(const ConstraintRow& row, const Softness& soft, JointRowKind kind = JointRowKind::Free, Real error = 0) {
        const int i = out_.count++;
        out_.rows[i] = row;
        out_.softness[i] = soft;
        out_.fedBack[i] = false;
        out_.kind[i] = kind;
        out_.error[i] = error;
        out_.used[i] = true;
        applyFeedback(out_.rows[i], out_.softness[i], out_.fedBack[i], kind, error, feedback_, h_);
    }

private:
    JointRowBatch& out_;
    const JointFeedback& feedback_;
    Real h_;
};

}  // namespace

// [ch08-distance-row]
DistanceLine distanceLine(const JointDesc& joint, const JointFrame& frame) {
    const Vec3 gap = frame.anchorB - frame.anchorA;
    const Real length = gap.norm();
    // Coincident anchors leave no direction to hold the length along: the row is empty (and skipped).
    const Vec3 direction = length > Real(1e-9) ? Vec3(gap / length) : Vec3::Zero();
    return {direction, length - joint.length.value_or(length)};
}

joint_rules::DistanceRow joint_rules::distanceRow(const JointDesc& joint, const JointFrame& frame, Real h) {
    const DistanceLine line = distanceLine(joint, frame);
    DistanceRow out;
    out.row = joint_rules::linearRow(joint.bodyA, joint.bodyB, frame.armA, frame.armB, line.direction);
    out.error = line.error;
    out.spring = joint.springHertz > 0;
    if (out.spring) out.springSoftness = makeSoftness(joint.springHertz, joint.springDampingRatio, h);
    return out;
}
// [ch08-distance-row]

namespace {

// A built row's last steps: the bodies as the caller's list holds them, and the impulse carried
// in, clamped to this step's bounds (zero if it is not finite).
void seatRow(ConstraintRow& row, int rowBodyA, int rowBodyB, Real carried) {
    row.bodyA = rowBodyA;
    row.bodyB = rowBodyB;
    row.impulse = std::isfinite(carried) ? std::clamp(carried, row.lower, row.upper) : Real(0);
}

// The point joints' slots 0-2 as one block, at the frame's arms.
void setPointBlock(JointRowSet& set, const JointFrame& frame, const SolverBody& a, const SolverBody& b) {
    // [ch08-point-mass]
    // K = (1/mA + 1/mB) 1 - [rA]x IA^-1 [rA]x - [rB]x IB^-1 [rB]x: how the anchors' relative
    // velocity answers an impulse at them. A singular K (both bodies fixed) keeps the rows scalar.
    const Mat3 armA = skew(frame.armA), armB = skew(frame.armB);
    const Mat3 k = (a.inverseMass + b.inverseMass) * Mat3::Identity() - armA * a.inverseInertia * armA -
                   armB * b.inverseInertia * armB;
    // [ch08-point-mass]
    const Real scale = k.norm();
    const bool invertible = pointBlockInvertible(scale, k.determinant());
    const Mat3 inverse = invertible ? Mat3(k.inverse()) : Mat3::Zero();
    set.pointBlock = invertible && inverse.allFinite();
    set.pointMass = set.pointBlock ? inverse : Mat3::Zero();
    set.pointArmA = frame.armA;
    set.pointArmB = frame.armB;
}

void applyFeedback(ConstraintRow& row, Softness& softness, bool& fedBack, JointRowKind kind, Real error,
                   const JointFeedback& feedback, Real h) {
    const bool movesPoints = !row.linearA.isZero(0) || !row.linearB.isZero(0);
    jointRowFeedback(row.bias, softness, fedBack, kind, error, movesPoints, feedback, h);
}

}  // namespace

void appendJointRows(JointRows& out, const World& world, int jointIndex, const std::vector<SolverBody>& bodies, Real h,
                     const JointFeedback& feedback, bool carryImpulses) {
    const JointDesc& joint = world.joints[static_cast<std::size_t>(jointIndex)];
    if (!jointBodiesValid(world, joint) || !(h > 0)) {
        ++out.invalidSkipped;
        return;
    }
    const bool carried = carryImpulses && static_cast<std::size_t>(jointIndex) < world.jointImpulses.size();
    appendJointRows(out, joint, jointIndex, jointFrame(world, joint), joint.bodyA, joint.bodyB, bodies, h, feedback,
                    carried ? &world.jointImpulses[static_cast<std::size_t>(jointIndex)] : nullptr);
}

bool buildJointRowBatch(JointRowBatch& batch, const JointDesc& joint, int jointIndex, const JointFrame& frame,
                        int rowBodyA, int rowBodyB, const std::vector<SolverBody>& bodies, Real h,
                        const JointFeedback& feedback, const JointImpulses* carried, const JointBatchNeeds& needs) {
    batch.count = 0;
    JointRowSet& set = batch.set;
    set = JointRowSet{};
    set.joint = jointIndex;
    if (hasPointBlock(joint.type))
        setPointBlock(set, frame, bodies[static_cast<std::size_t>(rowBodyA)], bodies[static_cast<std::size_t>(rowBodyB)]);
    RowBuilder builder(batch, feedback, h);
    // A block made from non-finite arms is not invertible, so its rows are built whole and the
    // check below still sees them.
    builder.blockWithoutJacobians = set.pointBlock && !needs.pointJacobians;
    joint_rules::addRowsOf(builder, joint, frame, h);
    for (int slot = 0; slot < batch.count; ++slot) {
        if (!batch.used[slot] || finiteRow(batch.rows[slot])) continue;  // an unused slot is all zeros
        batch.count = 0;
        return false;
    }
    set.rowCount = batch.count;
    for (int slot = 0; slot < batch.count; ++slot) {
        ConstraintRow& row = batch.rows[slot];
        seatRow(row, rowBodyA, rowBodyB, carried && slot < JointImpulses::kSlots ? carried->slot[slot] : Real(0));
        // The block solves slots 0-2 by its own mass; an unused slot has no Jacobian (mass 0).
        const bool inBlock = set.pointBlock && slot < 3;
        row.effectiveMass = inBlock || !batch.used[slot] || !needs.effectiveMasses ? Real(0) : effectiveMass(row, bodies);
    }
    return true;
}

void appendJointRows(JointRows& out, const JointDesc& joint, int jointIndex, const JointFrame& frame, int rowBodyA,
                     int rowBodyB, const std::vector<SolverBody>& bodies, Real h, const JointFeedback& feedback,
                     const JointImpulses* carried) {
    JointRowBatch batch;
    if (!buildJointRowBatch(batch, joint, jointIndex, frame, rowBodyA, rowBodyB, bodies, h, feedback, carried)) {
        ++out.invalidSkipped;
        return;
    }
    JointRowSet set = batch.set;
    set.firstRow = static_cast<int>(out.rows.size());
    for (int slot = 0; slot < batch.count; ++slot) {
        out.rows.push_back(batch.rows[slot]);
        out.softness.push_back(batch.softness[slot]);
        out.fedBack.push_back(batch.fedBack[slot]);
        out.kind.push_back(batch.kind[slot]);
        out.error.push_back(batch.error[slot]);
    }
    out.joints.push_back(set);
}

// [ch08-solve-rows]
void solveJointRows(JointRows& jointRows, const JointRowSet& set, std::vector<SolverBody>& bodies) {
    int begin = set.firstRow;
    const int end = set.firstRow + set.rowCount;
    if (set.pointBlock) {
        // The three point rows at once: lambda = K^-1 (bias - relative velocity), softened.
        ConstraintRow* point = &jointRows.rows[static_cast<std::size_t>(begin)];
        const Softness& soft = jointRows.softness[static_cast<std::size_t>(begin)];
        SolverBody& a = bodies[static_cast<std::size_t>(point->bodyA)];
        SolverBody& b = bodies[static_cast<std::size_t>(point->bodyB)];
        const Vec3 relative = b.linearVelocity + b.angularVelocity.cross(set.pointArmB) - a.linearVelocity -
                              a.angularVelocity.cross(set.pointArmA);
        const Vec3 bias(point[0].bias, point[1].bias, point[2].bias);
        const Vec3 accumulated(point[0].impulse, point[1].impulse, point[2].impulse);
        const Vec3 impulse = soft.massScale * (set.pointMass * (bias - relative)) - soft.impulseScale * accumulated;
        for (int axis = 0; axis < 3; ++axis) point[axis].impulse += impulse[axis];
        a.linearVelocity -= a.inverseMass * impulse;
        a.angularVelocity -= a.inverseInertia * set.pointArmA.cross(impulse);
        b.linearVelocity += b.inverseMass * impulse;
        b.angularVelocity += b.inverseInertia * set.pointArmB.cross(impulse);
        begin += 3;
    }
    for (int i = begin; i < end; ++i) {
        ConstraintRow& row = jointRows.rows[static_cast<std::size_t>(i)];
        if (row.effectiveMass == 0) continue;
        const Softness& soft = jointRows.softness[static_cast<std::size_t>(i)];
        const Real previous = row.impulse;
        const Real increment = soft.massScale * row.effectiveMass * (row.bias - rowVelocity(row, bodies)) -
                               soft.impulseScale * previous;
        row.impulse = std::clamp(previous + increment, row.lower, row.upper);
        applyRowImpulse(row, row.impulse - previous, bodies);
    }
}
// [ch08-solve-rows]

}  // namespace stepwise
