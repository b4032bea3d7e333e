#pragma once
// Joints in the solve: chapter 6's solve takes them as ExtraConstraints, so they are built,
// warm started, iterated and stored in the same passes as the contacts, substep by substep.
//
// The order matters for Gauss-Seidel on a chain without warm starting: each row only sees what
// the rows before it did in this sweep. From the ground out, the anchor's "stop" travels down a
// hanging chain in one sweep; from the leaves in, the loads travel up. With warm starting the
// impulses carried from the last substep already hold the chain and the order does not show
// (`stepwise bench joints` measures the three: ground first wins by up to 9% without warm
// starting, and by nothing with it). The chapter sweeps ground first.

#include "06_manifolds/stabilisation.h"
#include "08_joints/joint_rows.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

// [ch08-order]
/// The order the joints are swept in. The depth of a joint is how many joints separate its
/// farther body from the ground (a static or kinematic body), or from the first body of a tree
/// that touches no ground (a ragdoll in the air).
enum class JointOrder {
    AsListed,      // World::joints order
    LeavesFirst,   // deepest joints first: loads travel to the ground within one sweep
    GroundFirst,   // shallowest first
};
const char* toString(JointOrder order);
// [ch08-order]

/// The joint order the chapter uses (the bench's measurement chose it).
constexpr JointOrder kDefaultJointOrder = JointOrder::GroundFirst;

/// The joints' sweep order (indices into World::joints).
std::vector<int> jointSolveOrder(const World& world, JointOrder order);

/// jointSolveOrder kept from solve to solve: the joints do not change within a solve, and seldom
/// between frames, so the order is found again only when a joint's bodies, or whether they move,
/// changed (a hand edit in chapter 9's debugger).
class JointSweep {
public:
    const std::vector<int>& order(const World& world, JointOrder order);

private:
    std::vector<int> sweep_;
    std::vector<int> key_;       // what the order depends on: each joint's bodies, and which move
    std::vector<int> scratch_;
    JointOrder keyOrder_ = JointOrder::AsListed;
};

// [ch08-joint-softness]
/// Joints are soft in the biased pass, whatever the contacts use: a spring-damper of a quarter of
/// the (sub)step rate (150 Hz at 60 Hz with 10 substeps), damping ratio 2 (Box2D v3's). Rigid
/// Baumgarte rows with one iteration per substep make a 10-link chain diverge within a second
/// (tests/ch08/chain_test.cpp keeps that measured); the spring's damping is what keeps an
/// unconverged Gauss-Seidel solve from feeding its error back. A quarter of the rate is as stiff
/// as the step resolves: at half the rate the same chain diverges again.
constexpr Real kJointHertzPerStepRate = Real(0.25);
constexpr Real kJointDampingRatio = 2;
// [ch08-joint-softness]

/// The feedback of a solve's biased pass: `kind` with the chapter's softness or Settings::baumgarte.
JointFeedback jointFeedback(const Settings& settings, Real h, JointFeedback::Kind kind = JointFeedback::Kind::Soft);

class JointConstraints final : public ExtraConstraints {
public:
    /// With `relaxOnBiasedRows`, a relax pass right after a biased one at the same h takes the
    /// biased pass's rows with the feedback taken out (no bias, rigid), where the biased pass's
    /// Jacobians stand, instead of building them again where the bodies moved (Box2D v3 keeps a
    /// joint's rows for its whole step; chapter 10 asks for this).
    explicit JointConstraints(JointOrder order = kDefaultJointOrder,
                              JointFeedback::Kind feedback = JointFeedback::Kind::Soft, bool relaxOnBiasedRows = false)
        : order_(order), feedback_(feedback), relaxOnBiasedRows_(relaxOnBiasedRows) {}

    bool active(const World& world) const override { return !world.joints.empty(); }
    void prepare(const World& world, const std::vector<SolverBody>& bodies, Real h, bool positionFeedback) override;
    void warmStart(std::vector<SolverBody>& bodies) override;
    void iterate(std::vector<SolverBody>& bodies) override;
    void store(World& world) const override;

    const JointRows& rows() const { return rows_; }

private:
    JointOrder order_;
    JointFeedback::Kind feedback_;
    bool relaxOnBiasedRows_ = false;
    Real biasedStep_ = 0;            // h of the biased prepare whose rows the next relax may take; 0: none
    JointSweep sweep_;
    JointRows rows_;
};

/// Chapter 6's solve step (runStabilisedSolve) with the world's joints in it.
void solveWithJoints(World& world, Real dt, bool splitOrder, JointOrder order = kDefaultJointOrder,
                     JointFeedback::Kind feedback = JointFeedback::Kind::Soft);
/// The same with `joints` kept by the caller (the pipeline) from frame to frame: every prepare
/// rebuilds its rows from the World, so it carries nothing between frames, but its vectors keep
/// their room and the sweep order its answer, and a step allocates nothing.
void solveWithJoints(World& world, Real dt, bool splitOrder, JointConstraints& joints);

}  // namespace stepwise
