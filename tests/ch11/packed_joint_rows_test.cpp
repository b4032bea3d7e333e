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
#include <cstring>
#include <limits>
#include <random>
#include <utility>

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
                const JointPass::BodyPose a = placeJointBody(world, bodies, pass, static_cast<std::size_t>(pass.entryA[i]));
                const JointPass::BodyPose b = placeJointBody(world, bodies, pass, static_cast<std::size_t>(pass.entryB[i]));
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
            // Joint after joint in the order the packed sweep takes them: its groups' (the joints of
            // a group touch different bodies, so within one the order does not matter).
            std::vector<int> order;
            for (int g = 0; g < pass.packed.groupCount; ++g)
                for (int lane = 0; lane < pass.packed.groups[static_cast<std::size_t>(g)].lanes; ++lane)
                    order.push_back(pass.packed.groups[static_cast<std::size_t>(g)].entry[lane]);
            REQUIRE(order.size() == rows.joints.size());
            for (const int e : order) solveJointRows(rows, rows.joints[static_cast<std::size_t>(e)], reference);
            for (std::size_t i = 0; i < rows.rows.size(); ++i)
                if (rows.fedBack[i]) {
                    rows.rows[i].bias = 0;
                    rows.softness[i] = Softness{};
                }
            for (const int e : order) solveJointRows(rows, rows.joints[static_cast<std::size_t>(e)], reference);

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

TEST_CASE("a distance joint's row is written straight into its room with chapter 8's numbers", "[ch11][joints]") {
    // writeDistanceJoint skips chapter 8's batch; the row it writes must be the batch's to the bit:
    // rigid and as a spring, stretched and slack, and with coincident anchors (no direction: a
    // row without mass, which the sweeps leave out).
    const Real h = Real(1) / Real(600);
    const World gallery = packedTestStirred(buildJointGallery(), 7);
    SolverBodies bodies;
    prepareBodies(gallery, bodies);
    JointPass pass;
    prepareJointPass(gallery, bodies, 1, pass);
    buildJointRows(gallery, bodies, h, /*firstSubstep=*/true, pass);
    const JointFeedback feedback = fastJointFeedback(gallery.settings, h);
    int checked = 0;
    for (std::size_t i = 0; i < pass.joints.size(); ++i) {
        JointDesc joint = gallery.joints[static_cast<std::size_t>(pass.joints[i])];
        if (joint.type != JointType::Distance) continue;
        const JointPass::BodyPose a = placeJointBody(gallery, bodies, pass, static_cast<std::size_t>(pass.entryA[i]));
        const JointPass::BodyPose b = placeJointBody(gallery, bodies, pass, static_cast<std::size_t>(pass.entryB[i]));
        const Real carried = Real(0.03);
        for (const Real springHertz : {Real(0), Real(4)})
            for (const Real length : {Real(0.5), Real(3)})
                for (const bool coincident : {false, true}) {
                    INFO("spring " << springHertz << " Hz, length " << length << " m, coincident " << coincident);
                    joint.springHertz = springHertz;
                    joint.springDampingRatio = Real(0.3);
                    joint.length = length;
                    JointFrame frame = jointRowFrame(joint, a.transform, a.center, b.transform, b.center);
                    if (coincident) frame.anchorB = frame.anchorA;
                    JointImpulses impulses;
                    impulses.slot[0] = carried;
                    // Chapter 8's batch, packed as every other joint is.
                    JointRowBatch batch;
                    REQUIRE(buildJointRowBatch(batch, joint, 0, frame, pass.entryA[i], pass.entryB[i], pass.bodies, h,
                                               feedback, &impulses, JointBatchNeeds{false, false}));
                    PackedJointRows viaBatch, straight;
                    reservePackedJoint(viaBatch, 0, JointRowBatch::kMaxRows, false, false);
                    reservePackedJoint(straight, 0, 1, false, false);
                    REQUIRE(writePackedJoint(batch, pass.bodies, pass.slot, viaBatch, 0));
                    Real carriedStraight = carried;
                    REQUIRE(writeDistanceJoint(joint, frame, pass.entryA[i], pass.entryB[i], h, feedback, carriedStraight,
                                               pass.bodies, pass.slot, straight, 0));
                    REQUIRE(straight.joints[0].rowCount == viaBatch.joints[0].rowCount);
                    CHECK(straight.joints[0].rowCount == (coincident ? 0 : 1));
                    if (coincident) {  // no row: the impulse carried on is the batch's, clamped alike
                        CHECK(carriedStraight == batch.rows[0].impulse);
                        ++checked;
                        continue;
                    }
                    const PackedJointRow x = packedRowOf(straight, 0, 0);
                    const PackedJointRow y = packedRowOf(viaBatch, 0, 0);
                    CHECK((x.linearA == y.linearA && x.angularA == y.angularA && x.linearB == y.linearB &&
                           x.angularB == y.angularB));
                    CHECK((x.moveLinearA == y.moveLinearA && x.moveAngularA == y.moveAngularA &&
                           x.moveLinearB == y.moveLinearB && x.moveAngularB == y.moveAngularB));
                    CHECK(x.effectiveMass == y.effectiveMass);
                    CHECK(x.error == y.error);
                    CHECK(x.bias == y.bias);
                    CHECK((x.soft.biasRate == y.soft.biasRate && x.soft.massScale == y.soft.massScale &&
                           x.soft.impulseScale == y.soft.impulseScale));
                    CHECK((x.kind == y.kind && x.fedBack == y.fedBack && x.turnOnly == y.turnOnly));
                    CHECK((x.impulse == y.impulse && x.lower == y.lower && x.upper == y.upper));
                    CHECK((x.slotA == y.slotA && x.slotB == y.slotB && x.slot == y.slot));
                    ++checked;
                }
        // A non-finite anchor: refused, the room left empty, as chapter 8's batch refuses it.
        JointFrame broken = jointRowFrame(joint, a.transform, a.center, b.transform, b.center);
        broken.anchorB.x() = std::numeric_limits<Real>::quiet_NaN();
        PackedJointRows straight;
        reservePackedJoint(straight, 0, 1, false, false);
        Real none = 0;
        CHECK_FALSE(writeDistanceJoint(joint, broken, pass.entryA[i], pass.entryB[i], h, feedback, none, pass.bodies,
                                       pass.slot, straight, 0));
        CHECK(straight.joints[0].rowCount == 0);
        JointRowBatch batch;
        CHECK_FALSE(buildJointRowBatch(batch, joint, 0, broken, pass.entryA[i], pass.entryB[i], pass.bodies, h, feedback,
                                       nullptr, JointBatchNeeds{false, false}));
    }
    CHECK(checked >= 8);
}

namespace {

bool sameBits(Real a, Real b) { return std::memcmp(&a, &b, sizeof(Real)) == 0; }
bool sameBits(const Vec3& a, const Vec3& b) { return sameBits(a.x(), b.x()) && sameBits(a.y(), b.y()) && sameBits(a.z(), b.z()); }
bool sameBits(const Mat3& a, const Mat3& b) { return std::memcmp(a.data(), b.data(), sizeof(Real) * 9) == 0; }

void packedTestSameRows(const JointPass& lanes, const JointPass& single) {
    REQUIRE(lanes.packed.joints.size() == single.packed.joints.size());
    CHECK(lanes.rowCount == single.rowCount);
    CHECK(lanes.jointsBuilt == single.jointsBuilt);
    CHECK(lanes.invalidSkipped == single.invalidSkipped);
    for (std::size_t e = 0; e < lanes.packed.joints.size(); ++e) {
        INFO("joint " << e);
        const PackedJoint& a = lanes.packed.joints[e];
        const PackedJoint& b = single.packed.joints[e];
        REQUIRE(a.rowCount == b.rowCount);
        CHECK(a.slotCount == b.slotCount);
        CHECK(a.hasBlock == b.hasBlock);
        for (int slot = 0; slot < JointImpulses::kSlots; ++slot)
            CHECK(sameBits(lanes.carried[e].slot[slot], single.carried[e].slot[slot]));
        for (int k = 0; k < a.rowCount; ++k) {
            const PackedJointRow x = packedRowOf(lanes.packed, static_cast<int>(e), k);
            const PackedJointRow y = packedRowOf(single.packed, static_cast<int>(e), k);
            CHECK(x.slot == y.slot);
            CHECK(x.kind == y.kind);
            CHECK(x.fedBack == y.fedBack);
            CHECK(x.turnOnly == y.turnOnly);
            for (const auto& [u, v] : {std::pair{x.linearA, y.linearA}, {x.angularA, y.angularA}, {x.linearB, y.linearB},
                                       {x.angularB, y.angularB}, {x.moveLinearA, y.moveLinearA},
                                       {x.moveAngularA, y.moveAngularA}, {x.moveLinearB, y.moveLinearB},
                                       {x.moveAngularB, y.moveAngularB}})
                CHECK(sameBits(u, v));
            for (const auto& [u, v] : {std::pair{x.effectiveMass, y.effectiveMass}, {x.bias, y.bias}, {x.lower, y.lower},
                                       {x.upper, y.upper}, {x.impulse, y.impulse}, {x.error, y.error},
                                       {x.soft.biasRate, y.soft.biasRate}, {x.soft.massScale, y.soft.massScale},
                                       {x.soft.impulseScale, y.soft.impulseScale}})
                CHECK(sameBits(u, v));
        }
        if (!a.hasBlock) continue;
        const PackedPointBlock x = packedBlockOf(lanes.packed, static_cast<int>(e));
        const PackedPointBlock y = packedBlockOf(single.packed, static_cast<int>(e));
        CHECK(sameBits(x.mass, y.mass));
        CHECK(sameBits(x.inverseInertiaA, y.inverseInertiaA));
        CHECK(sameBits(x.inverseInertiaB, y.inverseInertiaB));
        for (const auto& [u, v] : {std::pair{x.armA, y.armA}, {x.armB, y.armB}, {x.bias, y.bias}, {x.impulse, y.impulse},
                                   {x.error, y.error}})
            CHECK(sameBits(u, v));
        for (const auto& [u, v] : {std::pair{x.inverseMassA, y.inverseMassA}, {x.inverseMassB, y.inverseMassB},
                                   {x.soft.biasRate, y.soft.biasRate}, {x.soft.massScale, y.soft.massScale},
                                   {x.soft.impulseScale, y.soft.impulseScale}})
            CHECK(sameBits(u, v));
        for (int axis = 0; axis < 3; ++axis) CHECK(x.fedBack[axis] == y.fedBack[axis]);
    }
}

}  // namespace

TEST_CASE("a lane group's point joints built at once have the bits of one joint after another", "[ch11][joints]") {
    const Real h = Real(1) / Real(600);
    int kept = 0, builtAgain = 0;
    World friction = buildRagdollPile(3);  // joint friction: the cone twists' three motor rows
    for (JointDesc& joint : friction.joints) joint.frictionTorque = Real(0.5);
    for (const World& start : {buildJointGallery(), buildRagdollPile(3), friction, buildJointsSandbox()}) {
        for (unsigned seed = 1; seed <= 3; ++seed) {
            INFO(start.name << ", seed " << seed);
            const World world = packedTestStirred(start, seed);
            SolverBodies bodies;
            prepareBodies(world, bodies);
            JointPass lanes, single;
            single.laneBuild = false;
            for (JointPass* pass : {&lanes, &single}) {
                prepareJointPass(world, bodies, 1, *pass);
                buildJointRows(world, bodies, h, /*firstSubstep=*/true, *pass);
            }
            REQUIRE(lanes.jointsBuilt > 0);
            packedTestSameRows(lanes, single);
            // A later substep, the bodies turned: the joints that turned far are built again over
            // their kept lanes, the rest keep theirs.
            SolverBodies moved = bodies;
            std::mt19937 rng(seed);
            for (std::size_t slot = 1; slot < moved.states.size(); ++slot) {
                const Quat turn(angleAxis(std::uniform_real_distribution<Real>(0, Real(0.03))(rng),
                                          packedTestRandomVector(rng, 1).normalized()));
                Real* q = moved.states[slot].deltaRotation;
                q[0] = turn.x(), q[1] = turn.y(), q[2] = turn.z(), q[3] = turn.w();
            }
            const int builtFirst = lanes.jointsBuilt;
            for (JointPass* pass : {&lanes, &single}) buildJointRows(world, moved, h, /*firstSubstep=*/false, *pass);
            CHECK(lanes.jointsKept == single.jointsKept);
            kept += lanes.jointsKept;               // some barely turned,
            builtAgain += lanes.jointsBuilt - builtFirst;  // some turned far enough to be built again
            packedTestSameRows(lanes, single);
        }
    }
    CHECK(kept > 0);
    CHECK(builtAgain > 0);
}
