#include "08_joints/joint_solver.h"

#include "06_manifolds/chapter.h"
#include "world/enum_names.h"

#include <algorithm>
#include <deque>

namespace stepwise {

const char* toString(JointOrder order) {
    static const Names<JointOrder> names = {
        {"as_listed", JointOrder::AsListed}, {"leaves_first", JointOrder::LeavesFirst}, {"ground_first", JointOrder::GroundFirst}};
    return nameOf(names, order);
}

// [ch08-depth]
std::vector<int> jointSolveOrder(const World& world, JointOrder order) {
    const int jointCount = static_cast<int>(world.joints.size());
    std::vector<int> sequence(static_cast<std::size_t>(jointCount));
    for (int i = 0; i < jointCount; ++i) sequence[static_cast<std::size_t>(i)] = i;
    if (order == JointOrder::AsListed) return sequence;

    // Breadth-first from the ground (static and kinematic bodies), then from the first body of
    // each tree still unreached: a body's depth is the number of joints between it and its root.
    const std::size_t bodyCount = world.bodies.size();
    std::vector<std::vector<int>> jointsOfBody(bodyCount);
    const auto valid = [&](const JointDesc& joint) {
        return joint.bodyA >= 0 && joint.bodyB >= 0 && std::size_t(joint.bodyA) < bodyCount &&
               std::size_t(joint.bodyB) < bodyCount;
    };
    for (int i = 0; i < jointCount; ++i) {
        const JointDesc& joint = world.joints[static_cast<std::size_t>(i)];
        if (!valid(joint)) continue;
        jointsOfBody[static_cast<std::size_t>(joint.bodyA)].push_back(i);
        jointsOfBody[static_cast<std::size_t>(joint.bodyB)].push_back(i);
    }
    std::vector<int> depth(bodyCount, -1);
    std::deque<int> queue;
    const auto spread = [&] {
        while (!queue.empty()) {
            const int body = queue.front();
            queue.pop_front();
            for (int jointIndex : jointsOfBody[static_cast<std::size_t>(body)]) {
                const JointDesc& joint = world.joints[static_cast<std::size_t>(jointIndex)];
                const int other = joint.bodyA == body ? joint.bodyB : joint.bodyA;
                if (depth[static_cast<std::size_t>(other)] >= 0) continue;
                depth[static_cast<std::size_t>(other)] = depth[static_cast<std::size_t>(body)] + 1;
                queue.push_back(other);
            }
        }
    };
    for (std::size_t body = 0; body < bodyCount; ++body)
        if (world.bodies[body].type != BodyType::Dynamic) {
            depth[body] = 0;
            queue.push_back(static_cast<int>(body));
        }
    spread();
    for (std::size_t body = 0; body < bodyCount; ++body)
        if (depth[body] < 0 && !jointsOfBody[body].empty()) {
            depth[body] = 0;
            queue.push_back(static_cast<int>(body));
            spread();
        }
    std::vector<int> jointDepth(static_cast<std::size_t>(jointCount), 0);
    for (int i = 0; i < jointCount; ++i) {
        const JointDesc& joint = world.joints[static_cast<std::size_t>(i)];
        if (valid(joint))
            jointDepth[static_cast<std::size_t>(i)] =
                std::max(depth[static_cast<std::size_t>(joint.bodyA)], depth[static_cast<std::size_t>(joint.bodyB)]);
    }
    std::stable_sort(sequence.begin(), sequence.end(), [&](int left, int right) {
        const int dl = jointDepth[static_cast<std::size_t>(left)], dr = jointDepth[static_cast<std::size_t>(right)];
        return order == JointOrder::LeavesFirst ? dl > dr : dl < dr;
    });
    return sequence;
}
// [ch08-depth]

// [ch08-joint-feedback]
JointFeedback jointFeedback(const Settings& settings, Real h, JointFeedback::Kind kind) {
    JointFeedback feedback;
    feedback.kind = kind;
    feedback.baumgarte = settings.baumgarte;
    feedback.soft = makeSoftness(kJointHertzPerStepRate / h, kJointDampingRatio, h);
    return feedback;
}
// [ch08-joint-feedback]

// [ch08-joint-solve]
void JointConstraints::prepare(const World& world, const std::vector<SolverBody>& bodies, Real h,
                               bool positionFeedback) {
    if (!positionFeedback && relaxOnBiasedRows_ && biasedStep_ == h && !rows_.rows.empty()) {
        // The relax pass on the biased pass's rows: its impulses are already in the rows.
        for (std::size_t i = 0; i < rows_.rows.size(); ++i) {
            if (!rows_.fedBack[i]) continue;
            rows_.rows[i].bias = 0;
            rows_.softness[i] = Softness{};
        }
        biasedStep_ = 0;
        return;
    }
    biasedStep_ = positionFeedback ? h : Real(0);
    // Cleared, not replaced: the vectors keep their room for the solve's other substeps and passes.
    rows_.clear();
    JointFeedback feedback = jointFeedback(world.settings, h, feedback_);
    if (!positionFeedback) feedback.kind = JointFeedback::Kind::None;
    // The biased pass starts from last solve's impulses only with warm starting on; the relax pass
    // always starts from the impulses the biased pass applied.
    const bool carry = !positionFeedback || world.settings.warmStarting;
    for (int jointIndex : sweep_.order(world, order_))
        appendJointRows(rows_, world, jointIndex, bodies, h, feedback, carry);
}

const std::vector<int>& JointSweep::order(const World& world, JointOrder order) {
    std::vector<int>& key = scratch_;
    key.clear();
    key.push_back(static_cast<int>(world.bodies.size()));
    const auto moves = [&](int body) {
        return body >= 0 && static_cast<std::size_t>(body) < world.bodies.size() &&
               world.bodies[static_cast<std::size_t>(body)].type == BodyType::Dynamic;
    };
    for (const JointDesc& joint : world.joints)
        key.insert(key.end(), {joint.bodyA, joint.bodyB, moves(joint.bodyA), moves(joint.bodyB)});
    // Never equal before the first: the key holds the body count.
    if (key == key_ && order == keyOrder_) return sweep_;
    key_.swap(key);
    keyOrder_ = order;
    sweep_ = jointSolveOrder(world, order);
    return sweep_;
}

void JointConstraints::warmStart(std::vector<SolverBody>& bodies) {
    for (const ConstraintRow& row : rows_.rows)
        if (row.impulse != 0) applyRowImpulse(row, row.impulse, bodies);
}

void JointConstraints::iterate(std::vector<SolverBody>& bodies) {
    for (const JointRowSet& set : rows_.joints) solveJointRows(rows_, set, bodies);
}

void JointConstraints::store(World& world) const {
    world.jointImpulses.resize(world.joints.size());
    for (const JointRowSet& set : rows_.joints) {
        JointImpulses& carried = world.jointImpulses[static_cast<std::size_t>(set.joint)];
        for (int slot = 0; slot < set.rowCount && slot < JointImpulses::kSlots; ++slot)
            carried.slot[slot] = rows_.rows[static_cast<std::size_t>(set.firstRow + slot)].impulse;
    }
    world.step.solver.jointRows = static_cast<int>(rows_.rows.size());
    world.step.solver.jointsSkipped = rows_.invalidSkipped;
}
// [ch08-joint-solve]

void solveWithJoints(World& world, Real dt, bool splitOrder, JointOrder order, JointFeedback::Kind feedback) {
    JointConstraints joints(order, feedback);
    solveWithJoints(world, dt, splitOrder, joints);
}

void solveWithJoints(World& world, Real dt, bool splitOrder, JointConstraints& joints) {
    runStabilisedSolve(world, dt, splitOrder, world.joints.empty() ? nullptr : &joints);
}

}  // namespace stepwise
