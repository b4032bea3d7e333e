// A point joint whose bodies barely turn within a frame keeps its rows from substep to substep
// (joint_pass.h, kJointRowsKeptTurn): its Jacobians stay where they were built and its errors move
// to first order, C += h J v (advancePackedErrors). What a kept row reads must be what chapter 8
// would build where the bodies stand now, to second order in the turn; a joint that turned more,
// or a slider (whose rows follow the bodies' moves too), is built again. A distance joint keeps its
// row while its line turns as little, its error the line's own length.
#include "08_joints/joint_frame.h"
#include "08_joints/scenes.h"
#include "11_wide_solve/joint_pass.h"
#include "11_wide_solve/solve_steps.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <random>

using namespace stepwise;

namespace {

/// Every moving body given a random velocity and a turn rate of `spin` rad/s about a random axis.
void keptTestStir(SolverBodies& bodies, unsigned seed, Real spin) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<Real> uniform(-1, 1);
    for (std::size_t slot = 1; slot < bodies.states.size(); ++slot) {
        SolverBodyState& state = bodies.states[slot];
        Vec3 axis(uniform(rng), uniform(rng), uniform(rng));
        axis = axis.norm() > Real(0.1) ? Vec3(axis.normalized()) : Vec3::UnitY();
        for (int k = 0; k < 3; ++k) {
            state.linearVelocity[k] = Real(0.5) * uniform(rng);
            state.angularVelocity[k] = spin * axis[k];
        }
    }
}

/// One substep's move as the solve makes it: the positions, then what the move did to the errors,
/// then the next substep's rows.
void keptTestSubstep(const World& world, SolverBodies& bodies, Real h, JointPass& pass) {
    integratePositions(bodies, h, kMostTurnPerSubstep / h, SolverPath::Scalar);
    advanceJointErrors(pass, bodies.states.data(), h);
    buildJointRows(world, bodies, h, /*firstSubstep=*/false, pass);
}

/// Chapter 8's rows of listed joint i where its bodies stand now.
JointRowBatch keptTestFresh(const World& world, const SolverBodies& bodies, JointPass& pass, std::size_t i, Real h) {
    const JointDesc& joint = world.joints[static_cast<std::size_t>(pass.joints[i])];
    const JointPass::BodyPose a = placeJointBody(world, bodies, pass, static_cast<std::size_t>(pass.entryA[i]));
    const JointPass::BodyPose b = placeJointBody(world, bodies, pass, static_cast<std::size_t>(pass.entryB[i]));
    JointRowBatch batch;
    buildJointRowBatch(batch, joint, pass.joints[i], jointRowFrame(joint, a.transform, a.center, b.transform, b.center),
                       pass.entryA[i], pass.entryB[i], pass.bodies, h, fastJointFeedback(world.settings, h), nullptr);
    return batch;
}

/// The packed row of `slot` in joint entry `entry`, if it has one.
std::optional<PackedJointRow> keptTestRow(const PackedJointRows& packed, int entry, int slot) {
    const PackedJoint& joint = packed.joints[static_cast<std::size_t>(entry)];
    for (int k = 0; k < joint.rowCount; ++k) {
        const PackedJointRow row = packedRowOf(packed, entry, k);
        if (row.slot == slot) return row;
    }
    return std::nullopt;
}

}  // namespace

TEST_CASE("a point joint whose bodies barely turn keeps its rows, its errors moved to first order", "[ch11][joints]") {
    const Real h = Real(1) / Real(600);
    // 1 rad/s: 1.7 mrad a substep, so three substeps stay under kJointRowsKeptTurn (10 mrad).
    const Real spin = 1;
    for (const World& world : {buildJointGallery(), buildRagdollPile(2)}) {
        for (unsigned seed = 1; seed <= 3; ++seed) {
            INFO(world.name << ", seed " << seed);
            SolverBodies bodies;
            prepareBodies(world, bodies);
            keptTestStir(bodies, seed, spin);
            JointPass pass;
            prepareJointPass(world, bodies, 1, pass);
            buildJointRows(world, bodies, h, /*firstSubstep=*/true, pass);
            const int listed = static_cast<int>(pass.joints.size());
            REQUIRE(pass.jointsBuilt == listed);
            for (int substep = 1; substep <= 2; ++substep) keptTestSubstep(world, bodies, h, pass);

            int kept = 0, distances = 0;
            for (std::size_t i = 0; i < pass.joints.size(); ++i) {
                const JointDesc& joint = world.joints[static_cast<std::size_t>(pass.joints[i])];
                const bool point = joint.type != JointType::Distance && joint.type != JointType::Slider;
                const int entry = pass.packedEntry[i];
                REQUIRE(entry >= 0);
                if (joint.type == JointType::Distance) {
                    // Kept or built again, its error is the line's own length against its rest length.
                    ++distances;
                    const JointRowBatch fresh = keptTestFresh(world, bodies, pass, i, h);
                    const std::optional<PackedJointRow> row = keptTestRow(pass.packed, entry, 0);
                    if (row && fresh.used[0]) CHECK(std::abs(row->error - fresh.error[0]) <= Real(1e-6));
                }
                if (!point) continue;
                ++kept;
                const JointRowBatch fresh = keptTestFresh(world, bodies, pass, i, h);
                // Second order in the turn, a few micrometres (or microradians) here.
                const Real tolerance = Real(2e-5);
                const PackedJoint& packedJoint = pass.packed.joints[static_cast<std::size_t>(entry)];
                if (packedJoint.hasBlock) {
                    const Vec3 gap = packedBlockOf(pass.packed, entry).error;
                    for (int axis = 0; axis < 3; ++axis) CHECK(std::abs(gap[axis] - fresh.error[axis]) <= tolerance);
                }
                // The turn rows off a hinge's axis are measured along directions made from the
                // axis, which may differ between builds: their pair is compared as a length.
                Real keptAcross = 0, freshAcross = 0;
                for (int slot = 3; slot < fresh.count; ++slot) {
                    const std::optional<PackedJointRow> row = keptTestRow(pass.packed, entry, slot);
                    if (!row || !fresh.used[slot]) continue;
                    if (joint.type == JointType::Hinge && slot <= 4) {
                        keptAcross += row->error * row->error;
                        freshAcross += fresh.error[slot] * fresh.error[slot];
                        continue;
                    }
                    INFO("joint " << pass.joints[i] << " slot " << slot);
                    CHECK(std::abs(row->error - fresh.error[slot]) <= tolerance);
                }
                CHECK(std::abs(std::sqrt(keptAcross) - std::sqrt(freshAcross)) <= tolerance);
            }
            // Every point joint kept both times; a distance joint kept while its line turns little.
            CHECK(pass.jointsKept >= 2 * kept);
            CHECK(pass.jointsKept <= 2 * (kept + distances));
            CHECK(pass.jointsBuilt + pass.jointsKept == 3 * listed);

            // A turn of 20 rad/s (33 mrad a substep) builds every joint again.
            keptTestStir(bodies, seed, 20);
            const int keptBefore = pass.jointsKept;
            keptTestSubstep(world, bodies, h, pass);
            CHECK(pass.jointsKept == keptBefore);
        }
    }
}
