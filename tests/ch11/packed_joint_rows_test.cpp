// The fast solve sweeps a substep's joint rows packed (packed_joint_rows.h): each row's M^-1 J^T
// made once, the bodies' states read by slot, the unused slots left out. The sweep must be
// chapter 8's, to rounding: the same impulses and the same velocities after a warm start, a
// biased and a relax sweep, for every joint type, between two moving bodies and against a post.
#include "08_joints/joint_frame.h"
#include "08_joints/joint_solver.h"
#include "08_joints/scenes.h"
#include "11_wide_solve/joint_pass.h"
#include "11_wide_solve/solve_steps.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <random>

using namespace stepwise;

namespace {

Vec3 packedTestRandomVector(std::mt19937& rng, Real scale) {
    std::uniform_real_distribution<Real> uniform(-scale, scale);
    return Vec3(uniform(rng), uniform(rng), uniform(rng));
}

/// Random velocities, turns and carried impulses, so that every row (limits past and open, motors,
/// springs) has something to do.
World packedTestStirred(World world, unsigned seed) {
    std::mt19937 rng(seed);
    for (Motion& motion : world.motions) {
        motion.linearVelocity = packedTestRandomVector(rng, 2);
        motion.angularVelocity = packedTestRandomVector(rng, 3);
    }
    world.jointImpulses.assign(world.joints.size(), JointImpulses{});
    for (JointImpulses& impulses : world.jointImpulses)
        for (Real& slot : impulses.slot) slot = packedTestRandomVector(rng, Real(0.05)).x();
    return world;
}

Vec3 packedTestLinear(const SolverBodyState& s) { return Vec3(s.linearVelocity[0], s.linearVelocity[1], s.linearVelocity[2]); }
Vec3 packedTestAngular(const SolverBodyState& s) {
    return Vec3(s.angularVelocity[0], s.angularVelocity[1], s.angularVelocity[2]);
}

void packedTestClose(const Vec3& packed, const Vec3& reference) {
    const Real tolerance = Real(2e-4) * (1 + reference.norm());
    CHECK((packed - reference).norm() <= tolerance);
}

}  // namespace

TEST_CASE("packed joint rows sweep as chapter 8's rows do", "[ch11][joints]") {
    const Real h = Real(1) / Real(600);
    for (const World& start : {buildJointGallery(), buildRagdollPile(2), buildJointsSandbox()}) {
        for (unsigned seed = 1; seed <= 3; ++seed) {
            INFO(start.name << ", seed " << seed);
            const World world = packedTestStirred(start, seed);
            SolverBodies bodies;
            prepareBodies(world, bodies);
            JointPass pass;
            prepareJointPass(world, bodies, 1, pass);
            buildJointRows(world, bodies, h, /*firstSubstep=*/true, pass);
            REQUIRE(!pass.packed.joints.empty());

            // Chapter 8's rows of the same joints, where the pass's bodies stand, from the same
            // carried impulses.
            JointRows rows;
            const JointFeedback feedback = fastJointFeedback(world.settings, h);
            for (std::size_t i = 0; i < pass.joints.size(); ++i) {
                const JointDesc& joint = world.joints[static_cast<std::size_t>(pass.joints[i])];
                const JointPass::BodyPose& a = pass.poses[static_cast<std::size_t>(pass.entryA[i])];
                const JointPass::BodyPose& b = pass.poses[static_cast<std::size_t>(pass.entryB[i])];
                appendJointRows(rows, joint, static_cast<int>(i), jointRowFrame(joint, a.transform, a.center, b.transform, b.center),
                                pass.entryA[i], pass.entryB[i], pass.bodies, h, feedback, &pass.carried[i]);
            }
            REQUIRE(rows.joints.size() == pass.packed.joints.size());
            CHECK(static_cast<int>(rows.rows.size()) == pass.rowCount);

            // Chapter 8's sweep over the same rows and bodies.
            std::vector<SolverBody> reference = pass.bodies;
            for (std::size_t e = 0; e < reference.size(); ++e) {
                reference[e].linearVelocity = packedTestLinear(bodies.states[static_cast<std::size_t>(pass.slot[e])]);
                reference[e].angularVelocity = packedTestAngular(bodies.states[static_cast<std::size_t>(pass.slot[e])]);
            }
            for (const ConstraintRow& row : rows.rows)
                if (row.impulse != 0) applyRowImpulse(row, row.impulse, reference);
            for (const JointRowSet& set : rows.joints) solveJointRows(rows, set, reference);
            for (std::size_t i = 0; i < rows.rows.size(); ++i)
                if (rows.fedBack[i]) {
                    rows.rows[i].bias = 0;
                    rows.softness[i] = Softness{};
                }
            for (const JointRowSet& set : rows.joints) solveJointRows(rows, set, reference);

            // The packed sweep.
            SolverBodyState* states = bodies.states.data();
            warmStartJoints(pass, states, true);
            solveJoints(pass, states, /*relax=*/false);
            solveJoints(pass, states, /*relax=*/true);
            keepJointImpulses(pass);

            for (std::size_t e = 0; e < reference.size(); ++e) {
                const SolverBodyState& state = bodies.states[static_cast<std::size_t>(pass.slot[e])];
                packedTestClose(packedTestLinear(state), reference[e].linearVelocity);
                packedTestClose(packedTestAngular(state), reference[e].angularVelocity);
            }
            for (const JointRowSet& set : rows.joints)
                for (int slot = 0; slot < set.rowCount; ++slot) {
                    const Real expected = rows.rows[static_cast<std::size_t>(set.firstRow + slot)].impulse;
                    const Real packed = pass.carried[static_cast<std::size_t>(set.joint)].slot[slot];
                    CHECK(std::abs(packed - expected) <= Real(2e-4) * (Real(1e-3) + std::abs(expected)));
                }
            // A static body's state is never written.
            CHECK(packedTestLinear(bodies.states[0]) == Vec3::Zero());
            CHECK(packedTestAngular(bodies.states[0]) == Vec3::Zero());
        }
    }
}
