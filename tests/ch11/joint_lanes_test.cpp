// The fast solve sweeps its joints a group at a time, one joint per lane (packed_joint_rows.h):
// the joints of a group share no moving body. The sweep over the groups must then give the same
// bits as the sweep joint after joint in the groups' order, which this file writes out with Eigen,
// the rows read back one lane at a time; and the feedback a kept joint's rows make again, a group
// at a time, must be chapter 8's rule row by row.
#include "08_joints/builders.h"
#include "08_joints/scenes.h"
#include "11_wide_solve/joint_pass.h"
#include "11_wide_solve/scenes.h"
#include "11_wide_solve/solve_steps.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <random>

using namespace stepwise;

namespace {

Vec3 lanesTestLinear(const SolverBodyState& s) { return Vec3(s.linearVelocity[0], s.linearVelocity[1], s.linearVelocity[2]); }
Vec3 lanesTestAngular(const SolverBodyState& s) { return Vec3(s.angularVelocity[0], s.angularVelocity[1], s.angularVelocity[2]); }

void lanesTestPush(std::vector<SolverBodyState>& states, int slot, const Vec3& linear, const Vec3& angular) {
    if (slot == 0) return;
    SolverBodyState& s = states[static_cast<std::size_t>(slot)];
    for (int k = 0; k < 3; ++k) {
        s.linearVelocity[k] += linear[k];
        s.angularVelocity[k] += angular[k];
    }
}

Vec3 lanesTestAnchorsRate(const PackedPointBlock& block, const std::vector<SolverBodyState>& states) {
    const SolverBodyState& a = states[static_cast<std::size_t>(block.slotA)];
    const SolverBodyState& b = states[static_cast<std::size_t>(block.slotB)];
    return lanesTestLinear(b) + lanesTestAngular(b).cross(block.armB) - lanesTestLinear(a) - lanesTestAngular(a).cross(block.armA);
}

void lanesTestPushBlock(const PackedPointBlock& block, const Vec3& impulse, std::vector<SolverBodyState>& states) {
    lanesTestPush(states, block.slotA, -block.inverseMassA * impulse, -(block.inverseInertiaA * block.armA.cross(impulse)));
    lanesTestPush(states, block.slotB, block.inverseMassB * impulse, block.inverseInertiaB * block.armB.cross(impulse));
}

Real lanesTestRowRate(const PackedJointRow& row, const std::vector<SolverBodyState>& states) {
    const SolverBodyState& a = states[static_cast<std::size_t>(row.slotA)];
    const SolverBodyState& b = states[static_cast<std::size_t>(row.slotB)];
    return row.linearA.dot(lanesTestLinear(a)) + row.angularA.dot(lanesTestAngular(a)) + row.linearB.dot(lanesTestLinear(b)) +
           row.angularB.dot(lanesTestAngular(b));
}

void lanesTestPushRow(const PackedJointRow& row, Real applied, std::vector<SolverBodyState>& states) {
    lanesTestPush(states, row.slotA, applied * row.moveLinearA, applied * row.moveAngularA);
    lanesTestPush(states, row.slotB, applied * row.moveLinearB, applied * row.moveAngularB);
}

/// One joint's rows and block read back from the lanes.
struct LanesTestJoint {
    int entry = 0;  // PackedJointRows::joints
    bool hasBlock = false;
    PackedPointBlock block;
    std::vector<PackedJointRow> rows;
};

/// The joints read back in the groups' order (group after group, lane after lane): the order the
/// sweep over the groups solves them in.
std::vector<LanesTestJoint> lanesTestRead(const PackedJointRows& packed) {
    std::vector<LanesTestJoint> joints;
    for (int g = 0; g < packed.groupCount; ++g) {
        const JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        for (int lane = 0; lane < group.lanes; ++lane) {
            const int e = group.entry[lane];
            LanesTestJoint joint;
            joint.entry = e;
            joint.hasBlock = packed.joints[static_cast<std::size_t>(e)].hasBlock;
            if (joint.hasBlock) joint.block = packedBlockOf(packed, e);
            for (int k = 0; k < packed.joints[static_cast<std::size_t>(e)].rowCount; ++k) joint.rows.push_back(packedRowOf(packed, e, k));
            joints.push_back(joint);
        }
    }
    return joints;
}

// The sweeps joint after joint, in the groups' order, written out with Eigen.
void lanesTestWarmStart(const std::vector<LanesTestJoint>& joints, std::vector<SolverBodyState>& states) {
    for (const LanesTestJoint& joint : joints) {
        if (joint.hasBlock) lanesTestPushBlock(joint.block, joint.block.impulse, states);
        for (const PackedJointRow& row : joint.rows)
            if (row.impulse != 0) lanesTestPushRow(row, row.impulse, states);
    }
}

void lanesTestSweep(std::vector<LanesTestJoint>& joints, std::vector<SolverBodyState>& states, bool relax) {
    for (LanesTestJoint& joint : joints) {
        if (joint.hasBlock) {
            PackedPointBlock& block = joint.block;
            const Vec3 relative = lanesTestAnchorsRate(block, states);
            Vec3 bias = block.bias;
            for (int axis = 0; axis < 3; ++axis)
                if (relax && block.fedBack[axis]) bias[axis] = 0;
            const Softness soft = relax && block.fedBack[0] ? Softness{} : block.soft;
            const Vec3 impulse = soft.massScale * (block.mass * (bias - relative)) - soft.impulseScale * block.impulse;
            block.impulse += impulse;
            lanesTestPushBlock(block, impulse, states);
        }
        for (PackedJointRow& row : joint.rows) {
            const Real velocity = lanesTestRowRate(row, states);
            const bool plain = relax && row.fedBack;
            const Softness soft = plain ? Softness{} : row.soft;
            const Real bias = plain ? Real(0) : row.bias;
            const Real previous = row.impulse;
            const Real increment = soft.massScale * row.effectiveMass * (bias - velocity) - soft.impulseScale * previous;
            row.impulse = std::clamp(previous + increment, row.lower, row.upper);
            lanesTestPushRow(row, row.impulse - previous, states);
        }
    }
}

void lanesTestAdvance(std::vector<LanesTestJoint>& joints, const PackedJointRows& packed,
                      const std::vector<SolverBodyState>& states, Real h) {
    for (LanesTestJoint& joint : joints) {
        if (!packed.joints[static_cast<std::size_t>(joint.entry)].keepable) continue;
        if (joint.hasBlock) joint.block.error += h * lanesTestAnchorsRate(joint.block, states);
        for (PackedJointRow& row : joint.rows)
            if (row.kind != JointRowKind::Free) row.error += h * lanesTestRowRate(row, states);
    }
}

bool lanesTestSameBits(const std::vector<SolverBodyState>& a, const std::vector<SolverBodyState>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::memcmp(a[i].linearVelocity, b[i].linearVelocity, sizeof(a[i].linearVelocity)) != 0 ||
            std::memcmp(a[i].angularVelocity, b[i].angularVelocity, sizeof(a[i].angularVelocity)) != 0)
            return false;
    return true;
}

bool lanesTestSameBits(Real a, Real b) { return std::memcmp(&a, &b, sizeof(Real)) == 0; }

/// Every impulse and error of the lanes against the joint-after-joint sweep's.
void lanesTestCompare(const PackedJointRows& packed, const std::vector<LanesTestJoint>& reference) {
    const std::vector<LanesTestJoint> lanes = lanesTestRead(packed);
    for (std::size_t e = 0; e < lanes.size(); ++e) {
        if (lanes[e].hasBlock)
            for (int axis = 0; axis < 3; ++axis) {
                CHECK(lanesTestSameBits(lanes[e].block.impulse[axis], reference[e].block.impulse[axis]));
                CHECK(lanesTestSameBits(lanes[e].block.error[axis], reference[e].block.error[axis]));
            }
        for (std::size_t k = 0; k < lanes[e].rows.size(); ++k) {
            CHECK(lanesTestSameBits(lanes[e].rows[k].impulse, reference[e].rows[k].impulse));
            CHECK(lanesTestSameBits(lanes[e].rows[k].error, reference[e].rows[k].error));
        }
    }
}

/// The feedback made again from the moved errors, a group at a time, against joint after joint
/// (refreshPackedFeedback, chapter 8's rule per row), every field it writes bit for bit.
void lanesTestFeedback(PackedJointRows& packed, const JointFeedback& feedback, Real h) {
    PackedJointRows scalar = packed;
    for (std::size_t e = 0; e < packed.joints.size(); ++e) refreshPackedFeedback(scalar, static_cast<int>(e), feedback, h);
    for (int g = 0; g < packed.groupCount; ++g) {
        const unsigned all = (1u << packed.groups[static_cast<std::size_t>(g)].lanes) - 1u;
        refreshPackedFeedbackLanes(packed, g, all, feedback, h);
    }
    int compared = 0;
    for (std::size_t e = 0; e < packed.joints.size(); ++e) {
        const int entry = static_cast<int>(e);
        if (packed.joints[e].hasBlock) {
            const PackedPointBlock a = packedBlockOf(packed, entry), b = packedBlockOf(scalar, entry);
            for (int axis = 0; axis < 3; ++axis) {
                CHECK(lanesTestSameBits(a.bias[axis], b.bias[axis]));
                CHECK(a.fedBack[axis] == b.fedBack[axis]);
            }
            CHECK((lanesTestSameBits(a.soft.massScale, b.soft.massScale) && lanesTestSameBits(a.soft.impulseScale, b.soft.impulseScale)));
        }
        for (int k = 0; k < packed.joints[e].rowCount; ++k) {
            const PackedJointRow a = packedRowOf(packed, entry, k), b = packedRowOf(scalar, entry, k);
            INFO("joint " << e << " row " << k << " kind " << static_cast<int>(a.kind));
            CHECK(lanesTestSameBits(a.bias, b.bias));
            CHECK(a.fedBack == b.fedBack);
            CHECK((lanesTestSameBits(a.soft.biasRate, b.soft.biasRate) && lanesTestSameBits(a.soft.massScale, b.soft.massScale) &&
                   lanesTestSameBits(a.soft.impulseScale, b.soft.impulseScale)));
            ++compared;
        }
    }
    CHECK(compared > 0);
}

}  // namespace

TEST_CASE("the joints' lane groups sweep with the same bits as one joint after another", "[ch11][joints]") {
    const Real h = Real(1) / Real(600);
    for (const World& start : {buildJointGallery(), buildRagdollPile(3), buildJointsSandbox(), buildRagdollField(12)}) {
        for (unsigned seed = 1; seed <= 3; ++seed) {
            INFO(start.name << ", seed " << seed);
            World world = start;
            std::mt19937 rng(seed);
            std::uniform_real_distribution<Real> uniform(-2, 2);
            for (Motion& motion : world.motions) {
                motion.linearVelocity = Vec3(uniform(rng), uniform(rng), uniform(rng));
                motion.angularVelocity = Vec3(uniform(rng), uniform(rng), uniform(rng));
            }
            world.jointImpulses.assign(world.joints.size(), JointImpulses{});
            for (JointImpulses& impulses : world.jointImpulses)
                for (Real& slot : impulses.slot) slot = uniform(rng) * Real(0.02);
            SolverBodies bodies;
            prepareBodies(world, bodies);
            JointPass pass;
            prepareJointPass(world, bodies, 1, pass);
            buildJointRows(world, bodies, h, /*firstSubstep=*/true, pass);
            REQUIRE(pass.packed.groupCount > 0);
            // Groups hold joints that share no moving body.
            for (int g = 0; g < pass.packed.groupCount; ++g) {
                const JointLaneGroup& group = pass.packed.groups[static_cast<std::size_t>(g)];
                std::vector<int> slots;
                for (int lane = 0; lane < group.lanes; ++lane)
                    for (const int slot : {group.slotA[lane], group.slotB[lane]})
                        if (slot != 0) slots.push_back(slot);
                std::sort(slots.begin(), slots.end());
                CHECK(std::adjacent_find(slots.begin(), slots.end()) == slots.end());
            }

            std::vector<LanesTestJoint> reference = lanesTestRead(pass.packed);
            std::vector<SolverBodyState> expected = bodies.states;
            SolverBodyState* states = bodies.states.data();
            lanesTestWarmStart(reference, expected);
            warmStartJoints(pass, states, true);
            CHECK(lanesTestSameBits(bodies.states, expected));
            lanesTestSweep(reference, expected, /*relax=*/false);
            solveJoints(pass, states, /*relax=*/false);
            CHECK(lanesTestSameBits(bodies.states, expected));
            lanesTestAdvance(reference, pass.packed, expected, h);
            advanceJointErrors(pass, states, h);
            lanesTestFeedback(pass.packed, fastJointFeedback(world.settings, h), h);
            // The relax pass reads the remade feedback (checked above): the reference takes it too.
            const std::vector<LanesTestJoint> remade = lanesTestRead(pass.packed);
            for (std::size_t e = 0; e < reference.size(); ++e) {
                if (reference[e].hasBlock) {
                    reference[e].block.bias = remade[e].block.bias;
                    reference[e].block.soft = remade[e].block.soft;
                    for (int axis = 0; axis < 3; ++axis) reference[e].block.fedBack[axis] = remade[e].block.fedBack[axis];
                }
                for (std::size_t k = 0; k < reference[e].rows.size(); ++k) {
                    reference[e].rows[k].bias = remade[e].rows[k].bias;
                    reference[e].rows[k].soft = remade[e].rows[k].soft;
                    reference[e].rows[k].fedBack = remade[e].rows[k].fedBack;
                }
            }
            lanesTestSweep(reference, expected, /*relax=*/true);
            solveJoints(pass, states, /*relax=*/true);
            CHECK(lanesTestSameBits(bodies.states, expected));
            lanesTestCompare(pass.packed, reference);
        }
    }
}

/// The lane groups and colours the frame's first substep lays out for a world's joints.
struct LanesTestLayout {
    int groups = 0;
    std::vector<int> colourSizes;  // joints per colour
};

LanesTestLayout lanesTestLayout(const World& world) {
    SolverBodies bodies;
    prepareBodies(world, bodies);
    JointPass pass;
    prepareJointPass(world, bodies, 1, pass);
    buildJointRows(world, bodies, Real(1) / Real(600), /*firstSubstep=*/true, pass);
    LanesTestLayout layout;
    layout.groups = pass.packed.groupCount;
    const std::vector<int>& start = pass.packed.colourStart;
    for (std::size_t c = 0; c + 1 < start.size(); ++c) layout.colourSizes.push_back(start[c + 1] - start[c]);
    // Every group inside one colour, and no group holds a moving body twice.
    for (int g = 0; g < pass.packed.groupCount; ++g) {
        const JointLaneGroup& group = pass.packed.groups[static_cast<std::size_t>(g)];
        for (int lane = 0; lane < group.lanes; ++lane) {
            const int colour = pass.packed.colourOfJoint[static_cast<std::size_t>(group.entry[lane])];
            CHECK(colour == pass.packed.colourOfJoint[static_cast<std::size_t>(group.entry[0])]);
            for (int other = 0; other < lane; ++other)
                for (const int slot : {group.slotA[lane], group.slotB[lane]})
                    CHECK((slot == 0 || (slot != group.slotA[other] && slot != group.slotB[other])));
        }
    }
    return layout;
}

/// The groups a layout of these colours takes at `lanes` lanes: each colour cut into full groups.
int lanesTestGroupsOf(const std::vector<int>& colourSizes, int lanes) {
    int groups = 0;
    for (const int size : colourSizes) groups += (size + lanes - 1) / lanes;
    return groups;
}

TEST_CASE("joints pack into as few lane groups as their shared bodies allow", "[ch11][joints]") {
    World chain = emptyWorld("chain");
    ChainSpec spec;
    spec.direction = Vec3(1, 0, 0);
    addChain(chain, spec);
    // A chain's joints each share a body with the next, so two colours hold it: every other link's
    // joint (20 joints: ten and ten; at eight lanes, four groups).
    const LanesTestLayout chainLayout = lanesTestLayout(chain);
    CHECK(chainLayout.colourSizes == std::vector<int>{10, 10});
    CHECK(chainLayout.groups == lanesTestGroupsOf(chainLayout.colourSizes, kWideLanes));
    // A ragdoll's chest holds four joints, so no layout has fewer than four colours, and the greedy
    // colouring in the sweep's order of joints finds four; at eight lanes one ragdoll takes four
    // groups, two take five and a hundred 126 (exercise 9).
    for (const int ragdolls : {1, 2, 100}) {
        const LanesTestLayout layout = lanesTestLayout(buildRagdollField(ragdolls, 0));
        CHECK(layout.colourSizes.size() == 4);
        CHECK(layout.groups == lanesTestGroupsOf(layout.colourSizes, kWideLanes));
        const int fullGroups = (10 * ragdolls + kWideLanes - 1) / kWideLanes;
        CHECK(layout.groups >= fullGroups);
        CHECK(layout.groups <= fullGroups + 3);  // each colour's last group part full
        if (kWideLanes == 8) CHECK(layout.groups == (ragdolls == 1 ? 4 : ragdolls == 2 ? 5 : 126));
    }
}

TEST_CASE("a lane group keeps a joint's rows exactly when the scalar turn test would", "[ch11][joints]") {
    // Turns near the bound kJointRowsKeptTurn, where the last bit of the quaternions' dot product
    // decides: the lanes must sum its four products as Eigen does.
    std::mt19937 rng(5);
    std::uniform_real_distribution<Real> unit(-1, 1), near(Real(0.95), Real(1.05));
    const auto randomTurn = [&](Real angle) {
        const Vec3 axis = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
        return Quat(angleAxis(angle, axis));
    };
    const auto scalarLittle = [](const Quat& built, const Quat& now) {
        const Real w = built.coeffs().dot(now.coeffs());
        return 1 - w * w <= kJointRowsKeptTurn * kJointRowsKeptTurn / 4;
    };
    int kept = 0, compared = 0;
    for (int trial = 0; trial < 400; ++trial) {
        JointLaneGroup group;
        std::vector<SolverBodyState> states(1 + 2 * kWideLanes);
        std::vector<Quat> builtA(kWideLanes), builtB(kWideLanes), nowA(kWideLanes), nowB(kWideLanes);
        group.lanes = kWideLanes;
        for (int lane = 0; lane < kWideLanes; ++lane) {
            group.slotA[lane] = 1 + 2 * lane;
            group.slotB[lane] = 2 + 2 * lane;
            builtA[lane] = randomTurn(Real(0.3) * unit(rng));
            builtB[lane] = randomTurn(Real(0.3) * unit(rng));
            nowA[lane] = randomTurn(kJointRowsKeptTurn * near(rng)) * builtA[lane];
            nowB[lane] = randomTurn(kJointRowsKeptTurn * Real(0.5) * near(rng)) * builtB[lane];
            group.builtA.x[lane] = builtA[lane].x(), group.builtA.y[lane] = builtA[lane].y();
            group.builtA.z[lane] = builtA[lane].z(), group.builtA.w[lane] = builtA[lane].w();
            group.builtB.x[lane] = builtB[lane].x(), group.builtB.y[lane] = builtB[lane].y();
            group.builtB.z[lane] = builtB[lane].z(), group.builtB.w[lane] = builtB[lane].w();
            for (int k = 0; k < 4; ++k) {
                states[static_cast<std::size_t>(group.slotA[lane])].deltaRotation[k] = nowA[lane].coeffs()[k];
                states[static_cast<std::size_t>(group.slotB[lane])].deltaRotation[k] = nowB[lane].coeffs()[k];
            }
        }
        const unsigned lanes = lanesTurnedAtMost(group, states.data(), kJointRowsKeptTurn);
        for (int lane = 0; lane < kWideLanes; ++lane) {
            const bool expected = scalarLittle(builtA[lane], nowA[lane]) && scalarLittle(builtB[lane], nowB[lane]);
            CHECK(((lanes >> lane & 1u) != 0) == expected);
            kept += expected ? 1 : 0;
            ++compared;
        }
    }
    CHECK(kept > compared / 10);  // both sides of the bound are exercised
    CHECK(kept < compared * 9 / 10);
}
