#include "08_joints/joint_rows.h"

#include "04_pgs/contact_constraints.h"
#include "04_pgs/solver.h"
#include "08_joints/joint_frame.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace stepwise {

namespace {

// [ch08-row-shapes]
// A row that measures how fast two points close along n: point B (arm armB from B's centre of
// mass) minus point A (arm armA from A's). d/dt (pB - pA) . n with n fixed: J = [-n, -rA x n, n, rB x n],
// chapter 4's contact row.
ConstraintRow linearRow(int bodyA, int bodyB, const Vec3& armA, const Vec3& armB, const Vec3& direction) {
    return pointVelocityRow(bodyA, bodyB, direction, armA, armB);
}

// A row that measures how fast B turns relative to A about a world axis: (wB - wA) . axis.
ConstraintRow angularRow(int bodyA, int bodyB, const Vec3& axis) {
    ConstraintRow row;
    row.bodyA = bodyA;
    row.bodyB = bodyB;
    row.angularA = -axis;
    row.angularB = axis;
    return row;
}
// [ch08-row-shapes]

ConstraintRow negated(ConstraintRow row) {
    row.linearA = -row.linearA;
    row.angularA = -row.angularA;
    row.linearB = -row.linearB;
    row.angularB = -row.angularB;
    return row;
}

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

// Two unit vectors perpendicular to `axis` and to each other.
void perpendiculars(const Vec3& axis, Vec3& first, Vec3& second) { tangentBasis(axis, first, second); }

// [ch08-point-rows]
// Slots 0-2 of the point joints: the anchors coincide, one row per world axis (solved as a block).
void addPointRows(RowBuilder& builder, const JointDesc& joint, const JointFrame& frame) {
    const Vec3 gap = frame.anchorB - frame.anchorA;
    for (int axis = 0; axis < 3; ++axis) {
        if (!builder.blockWithoutJacobians) {
            builder.equality(linearRow(joint.bodyA, joint.bodyB, frame.armA, frame.armB, Vec3::Unit(axis)), gap[axis]);
            continue;
        }
        ConstraintRow row;
        row.linearA = -Vec3::Unit(axis);
        row.linearB = Vec3::Unit(axis);
        builder.equality(row, gap[axis]);
    }
}
// [ch08-point-rows]

// B turns with A: one row per world axis, the error the deviation's small-angle vector.
void addWeldRows(RowBuilder& builder, const JointDesc& joint, const JointFrame& frame) {
    const Vec3 error = rotationError(frame);
    for (int axis = 0; axis < 3; ++axis)
        builder.equality(angularRow(joint.bodyA, joint.bodyB, Vec3::Unit(axis)), error[axis]);
}

// [ch08-limit-rows]
// The two limit slots of a coordinate x (an angle or a travel) that `along` measures the rate of:
// lower wants x - lo >= 0, upper wants hi - x >= 0.
void addLimitRows(RowBuilder& builder, const JointDesc& joint, const ConstraintRow& along, Real coordinate,
                  const std::optional<std::pair<Real, Real>>& limits) {
    if (!limits) {
        builder.unused(joint.bodyA, joint.bodyB);
        builder.unused(joint.bodyA, joint.bodyB);
        return;
    }
    builder.limit(along, coordinate - limits->first);
    builder.limit(negated(along), limits->second - coordinate);
}

void addLimitAndMotorRows(RowBuilder& builder, const JointDesc& joint, const ConstraintRow& along, Real coordinate,
                          const std::optional<std::pair<Real, Real>>& limits) {
    addLimitRows(builder, joint, along, coordinate, limits);
    if (joint.motor)
        builder.motor(along, joint.motor->speed, joint.motor->maxForce);
    else if (joint.frictionTorque > 0)  // a hinge's joint friction: the motor slot at speed zero
        builder.motor(along, 0, joint.frictionTorque);
    else
        builder.unused(joint.bodyA, joint.bodyB);
}
// [ch08-limit-rows]

// [ch08-hinge-rows]
void addHingeRows(RowBuilder& builder, const JointDesc& joint, const JointFrame& frame) {
    addPointRows(builder, joint, frame);
    // B's axis stays on A's: its components along two directions b, c across A's axis are zero.
    // d/dt (axisB . b) = (wB x axisB) . b + axisB . (wA x b) = (axisB x b) . (wB - wA).
    Vec3 across[2];
    perpendiculars(frame.axisA, across[0], across[1]);
    for (const Vec3& direction : across)
        builder.equality(angularRow(joint.bodyA, joint.bodyB, frame.axisB.cross(direction)), frame.axisB.dot(direction));
    // The angle turns at (wB - wA) . axis; the lower limit wants angle - lo >= 0, the upper hi - angle >= 0.
    const Real angle = twistAngle(frame.deviation, joint.axis);
    const ConstraintRow turn = angularRow(joint.bodyA, joint.bodyB, frame.axisA);
    addLimitAndMotorRows(builder, joint, turn, angle, joint.limits);
}
// [ch08-hinge-rows]

// [ch08-cone-twist-rows]
void addConeTwistRows(RowBuilder& builder, const JointDesc& joint, const JointFrame& frame) {
    addPointRows(builder, joint, frame);
    // Swing: the angle between the axes grows at (wB - wA) . s with s = axisA x axisB normalised;
    // the cone wants coneAngle - swing >= 0. Aligned axes: no direction, and far from any cone.
    const Vec3 swingDirection = frame.axisA.cross(frame.axisB);
    const Real swing = swingAngle(frame);
    const Real swingLength = swingDirection.norm();
    if (swingLength > Real(1e-6))
        builder.limit(negated(angularRow(joint.bodyA, joint.bodyB, swingDirection / swingLength)), joint.coneAngle - swing);
    else
        builder.unused(joint.bodyA, joint.bodyB);
    // Twist about the mean of the two axes (the twist axis of A and B differ by the swing).
    const Vec3 mean = frame.axisA + frame.axisB;
    const Vec3 twistAxis = mean.norm() > Real(1e-6) ? Vec3(mean.normalized()) : frame.axisA;
    const Real twist = twistAngle(frame.deviation, joint.axis);
    addLimitRows(builder, joint, angularRow(joint.bodyA, joint.bodyB, twistAxis), twist, joint.twistLimits);
    // Joint friction (Box2D's ragdoll): zero-speed motors about the world axes.
    for (int axis = 0; axis < 3; ++axis) {
        if (joint.frictionTorque > 0)
            builder.motor(angularRow(joint.bodyA, joint.bodyB, Vec3::Unit(axis)), 0, joint.frictionTorque);
        else
            builder.unused(joint.bodyA, joint.bodyB);
    }
}
// [ch08-cone-twist-rows]

// [ch08-slider-rows]
void addSliderRows(RowBuilder& builder, const JointDesc& joint, const JointFrame& frame) {
    // B's anchor stays on the line through A's anchor along A's axis. The offset d = pB - pA is
    // measured along directions n that turn with A, so d/dt (d . n) also has d . (wA x n): A's arm
    // reaches B's anchor, rA + d.
    const Vec3 gap = frame.anchorB - frame.anchorA;
    const Vec3 armToB = frame.armA + gap;
    Vec3 across[2];
    perpendiculars(frame.axisA, across[0], across[1]);
    for (const Vec3& direction : across)
        builder.equality(linearRow(joint.bodyA, joint.bodyB, armToB, frame.armB, direction), gap.dot(direction));
    addWeldRows(builder, joint, frame);
    const Real travel = gap.dot(frame.axisA);
    addLimitAndMotorRows(builder, joint, linearRow(joint.bodyA, joint.bodyB, armToB, frame.armB, frame.axisA), travel,
                         joint.limits);
}
// [ch08-slider-rows]

// A distance joint's row before its feedback: a spring of its own, or an equality.
struct DistanceRow {
    ConstraintRow row;
    Real error = 0;
    bool spring = false;
    Softness springSoftness;
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

static DistanceRow distanceRow(const JointDesc& joint, const JointFrame& frame, Real h) {
    const DistanceLine line = distanceLine(joint, frame);
    DistanceRow out;
    out.row = linearRow(joint.bodyA, joint.bodyB, frame.armA, frame.armB, line.direction);
    out.error = line.error;
    out.spring = joint.springHertz > 0;
    if (out.spring) out.springSoftness = makeSoftness(joint.springHertz, joint.springDampingRatio, h);
    return out;
}
// [ch08-distance-row]

namespace {

void addDistanceRow(RowBuilder& builder, const JointDesc& joint, const JointFrame& frame, Real h) {
    const DistanceRow distance = distanceRow(joint, frame, h);
    if (distance.spring)
        builder.spring(distance.row, distance.error, distance.springSoftness);
    else
        builder.equality(distance.row, distance.error);
}

void addRowsOf(RowBuilder& builder, const JointDesc& joint, const JointFrame& frame, Real h) {
    switch (joint.type) {
        case JointType::Distance: addDistanceRow(builder, joint, frame, h); break;
        case JointType::BallSocket: addPointRows(builder, joint, frame); break;
        case JointType::Hinge: addHingeRows(builder, joint, frame); break;
        case JointType::ConeTwist: addConeTwistRows(builder, joint, frame); break;
        case JointType::Slider: addSliderRows(builder, joint, frame); break;
        case JointType::Fixed:
            addPointRows(builder, joint, frame);
            addWeldRows(builder, joint, frame);
            break;
    }
}

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
    const bool invertible = scale > 0 && std::abs(k.determinant()) > Real(1e-9) * scale * scale * scale;
    const Mat3 inverse = invertible ? Mat3(k.inverse()) : Mat3::Zero();
    set.pointBlock = invertible && inverse.allFinite();
    set.pointMass = set.pointBlock ? inverse : Mat3::Zero();
    set.pointArmA = frame.armA;
    set.pointArmB = frame.armB;
}

}  // namespace


namespace {

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
    addRowsOf(builder, joint, frame, h);
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
