// The joints' rows handed from frame to frame (joint_hand_on.h): a resting joint keeps its rows
// across the frame's boundary as it does between substeps, and a joint whose description, bodies,
// impulses or substep changed between the frames is built again, exactly as if nothing had been
// handed on. Each check steps the same world twice: once as it is, once with the handed rows
// dropped (StepState::jointRows), and compares the bits.
#include "08_joints/joint_frame.h"
#include "08_joints/scenes.h"
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/joint_hand_on.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>

using namespace stepwise;

namespace {

bool sameBits(const Transform& a, const Transform& b) {
    return std::memcmp(a.position.data(), b.position.data(), sizeof(Real) * 3) == 0 &&
           std::memcmp(a.rotation.coeffs().data(), b.rotation.coeffs().data(), sizeof(Real) * 4) == 0;
}

/// Awake: a sleeping body's joints are not solved at all.
World awake(World world) {
    world.settings.sleeping = false;
    return world;
}

World stepped(World world, int frames) {
    Pipeline pipeline = makeChapter11Pipeline(world);
    for (int frame = 0; frame < frames; ++frame) pipeline.step(world);
    return world;
}

/// The world stepped on `frames` frames as it is and with its handed rows dropped.
std::pair<World, World> keptAndDropped(const World& world, int frames) {
    World dropped = world;
    dropped.step.jointRows.reset();
    return {stepped(world, frames), stepped(dropped, frames)};
}

/// Chapter 8's rows of `joint` where its bodies stand in the World now.
JointRowBatch freshRows(const World& world, int jointIndex, Real h) {
    const JointDesc& joint = world.joints[static_cast<std::size_t>(jointIndex)];
    std::vector<SolverBody> bodies(2);
    const int ends[2] = {joint.bodyA, joint.bodyB};
    for (int k = 0; k < 2; ++k) {
        bodies[static_cast<std::size_t>(k)].center = worldCenterOfMass(world, ends[k]);
        if (const Motion* motion = world.motionOf(ends[k])) {
            bodies[static_cast<std::size_t>(k)].inverseMass = motion->inverseMass;
            bodies[static_cast<std::size_t>(k)].inverseInertia = worldInverseInertia(world.bodies[static_cast<std::size_t>(ends[k])], *motion);
        }
    }
    const Transform& a = world.bodies[static_cast<std::size_t>(joint.bodyA)].transform;
    const Transform& b = world.bodies[static_cast<std::size_t>(joint.bodyB)].transform;
    JointRowBatch batch;
    buildJointRowBatch(batch, joint, jointIndex, jointRowFrame(joint, a, bodies[0].center, b, bodies[1].center), 0, 1,
                       bodies, h, fastJointFeedback(world.settings, h), nullptr);
    return batch;
}

int jointOf(const World& world, int body) {
    for (std::size_t j = 0; j < world.joints.size(); ++j)
        if (world.joints[j].bodyB == body) return static_cast<int>(j);
    return -1;
}

}  // namespace

TEST_CASE("a resting pile's joints keep their rows from frame to frame", "[ch11][joints]") {
    World world = stepped(awake(buildRagdollPile(4)), 360);
    REQUIRE(world.step.jointRows);
    Pipeline pipeline = makeChapter11Pipeline(world);
    long built = 0, kept = 0;
    for (int frame = 0; frame < 30; ++frame) {
        pipeline.step(world);
        built += world.step.solver.jointsBuilt;
        kept += world.step.solver.jointsKept;
    }
    INFO(built << " built, " << kept << " kept");
    // Every substep of every frame, the first included: almost every joint keeps its rows.
    CHECK(kept > 0);
    CHECK(built * 20 < built + kept);
}

TEST_CASE("a joint whose bodies, description, impulses or substep changed between frames is built again",
          "[ch11][joints]") {
    // The gallery's joints each hold one body under its own post: what one of them does is its own.
    // The hinge's bar rests on its limit after two seconds.
    const World rested = stepped(awake(buildJointGallery()), 120);
    REQUIRE(rested.step.jointRows);
    const int bar = rested.findBody("hinge-limits-bar");
    REQUIRE(bar >= 0);
    const int joint = jointOf(rested, bar);
    REQUIRE(joint >= 0);
    const auto barAfter = [&](const std::function<void(World&)>& edit) {
        World world = rested;
        edit(world);
        const auto [kept, dropped] = keptAndDropped(world, 20);
        return std::pair<Transform, Transform>(kept.bodies[static_cast<std::size_t>(bar)].transform,
                                               dropped.bodies[static_cast<std::size_t>(bar)].transform);
    };
    SECTION("unchanged: its rows are kept, and the bits are not those of a build") {
        const auto [kept, dropped] = barAfter([](World&) {});
        CHECK_FALSE(sameBits(kept, dropped));
    }
    SECTION("its body moved by a user") {
        const auto [kept, dropped] = barAfter([&](World& w) { w.bodies[static_cast<std::size_t>(bar)].transform.position.x() += Real(0.005); });
        CHECK(sameBits(kept, dropped));
    }
    SECTION("its body turned by a user") {
        const auto [kept, dropped] = barAfter([&](World& w) {
            Quat& rotation = w.bodies[static_cast<std::size_t>(bar)].transform.rotation;
            rotation = (Quat(Eigen::AngleAxis<Real>(Real(0.02), Vec3::UnitY())) * rotation).normalized();
        });
        CHECK(sameBits(kept, dropped));
    }
    SECTION("its limits changed") {
        const auto [kept, dropped] = barAfter([&](World& w) {
            w.joints[static_cast<std::size_t>(joint)].limits = {{-40 * kDegree, 40 * kDegree}};
        });
        CHECK(sameBits(kept, dropped));
    }
    SECTION("its body's mass doubled") {
        const auto [kept, dropped] = barAfter([&](World& w) {
            Motion& motion = *w.motionOf(bar);
            motion.mass *= 2;
            motion.inverseMass /= 2;
            motion.inertiaLocal *= 2;
            motion.inverseInertiaLocal /= 2;
        });
        CHECK(sameBits(kept, dropped));
    }
    SECTION("its impulses reset") {
        const auto [kept, dropped] = barAfter([&](World& w) { w.jointImpulses[static_cast<std::size_t>(joint)] = JointImpulses{}; });
        CHECK(sameBits(kept, dropped));
    }
    SECTION("the joints' stiffness changed: every joint is built again") {
        World world = rested;
        world.settings.jointHertz *= Real(0.5);
        const auto [kept, dropped] = keptAndDropped(world, 20);
        for (std::size_t b = 0; b < kept.bodies.size(); ++b) CHECK(sameBits(kept.bodies[b].transform, dropped.bodies[b].transform));
    }
}

TEST_CASE("rows handed across frames read the errors chapter 8 measures where the bodies stand, to second order",
          "[ch11][joints]") {
    // A resting pile keeps most of its rows for many frames; their errors have moved with every
    // substep since they were built, across every frame's boundary, and their bodies have turned
    // at most kJointRowsKeptTurn: the frozen Jacobians miss a few micrometres (microradians).
    World world = stepped(awake(buildRagdollPile(4)), 300);
    Pipeline pipeline = makeChapter11Pipeline(world);
    int compared = 0;
    for (int frame = 0; frame < 60; ++frame) {
        pipeline.step(world);
        if (frame % 15 != 14) continue;
        REQUIRE(world.step.jointRows);
        const HandedJointRows& handed = *world.step.jointRows;
        const Real h = handed.h;
        for (std::size_t i = 0; i < handed.joints.size(); ++i) {
            const int entry = handed.packedEntry[i];
            if (entry < 0) continue;
            const PackedJoint& packed = handed.packed.joints[static_cast<std::size_t>(entry)];
            const JointLaneGroup& group = handed.packed.groups[static_cast<std::size_t>(packed.group)];
            if (!(group.keepableLanes & group.builtLanes & (1u << packed.lane))) continue;
            INFO("frame " << frame << ", joint " << handed.joints[i]);
            const JointRowBatch fresh = freshRows(world, handed.joints[i], h);
            // Second order in the turn: half its square, times the arm for a point (a ragdoll's
            // arms are at most 0.3 m), plus the rounding of many substeps' moves.
            const Real turn = kJointRowsKeptTurn;
            const Real tolerance = turn * turn / 2 + Real(5e-6);
            if (packed.hasBlock) {
                const Vec3 gap = packedBlockOf(handed.packed, entry).error;
                for (int axis = 0; axis < 3; ++axis) CHECK(std::abs(gap[axis] - fresh.error[axis]) <= tolerance);
            }
            // A hinge's two rows across its axis are compared as a length (keptTest's reason).
            const bool hinge = world.joints[static_cast<std::size_t>(handed.joints[i])].type == JointType::Hinge;
            Real keptAcross = 0, freshAcross = 0;
            for (int k = 0; k < packed.rowCount; ++k) {
                const PackedJointRow row = packedRowOf(handed.packed, entry, k);
                if (row.slot < 3 || !fresh.used[row.slot]) continue;
                if (hinge && row.slot <= 4) {
                    keptAcross += row.error * row.error;
                    freshAcross += fresh.error[row.slot] * fresh.error[row.slot];
                    continue;
                }
                INFO("slot " << row.slot << ": kept " << row.error << ", fresh " << fresh.error[row.slot]);
                // A limit's angle (a swing, a twist) bends with the bodies' relative turn, up to twice
                // the bound, and the more the smaller the swing: within the square of that turn where
                // the limit is near (there the row acts, and a cone's swing is wide), within the
                // bound itself far from it.
                const bool limit = row.kind == JointRowKind::Limit;
                const bool near = std::abs(fresh.error[row.slot]) <= turn;
                const Real allowed = !limit ? tolerance : near ? 4 * turn * turn : turn;
                CHECK(std::abs(row.error - fresh.error[row.slot]) <= allowed);
            }
            CHECK(std::abs(std::sqrt(keptAcross) - std::sqrt(freshAcross)) <= tolerance);
            ++compared;
        }
    }
    CHECK(compared >= 4 * 36);  // four ragdolls' joints, four times
}
