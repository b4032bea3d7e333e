// JointConstraints' relaxOnBiasedRows (chapter 10 turns it on): the relax pass right after a
// biased one takes the biased rows with the feedback taken out, and builds nothing again.
#include "04_pgs/solver.h"
#include "08_joints/chapter.h"
#include "joint_fixture.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("a relax pass on the biased rows drops the feedback and keeps the rest as built", "[ch08][solve]") {
    World world;
    const int post = test::addPost(world);
    BodyDef arm = test::boxBody("arm", Vec3(Real(0.3), Real(0.05), Real(0.05)), 2, Vec3(Real(0.35), 0, 0));
    arm.angularVelocity = Vec3(0, 0, 3);
    const int body = addBody(world, arm);
    JointDesc hinge = test::jointBetween(JointType::Hinge, post, body, Vec3(Real(-0.3), 0, 0), Vec3::UnitZ());
    hinge.localAnchorA = Vec3(Real(0.05), 0, 0);
    hinge.limits = std::make_pair(Real(-0.5), Real(0.5));
    hinge.motor = JointMotor{Real(1.5), Real(10)};
    world.joints.push_back(hinge);
    world.bodies[static_cast<std::size_t>(body)].transform.position += Vec3(0, Real(0.01), 0);  // a gap to feed back

    const Real h = Real(1) / 600;
    std::vector<SolverBody> bodies = gatherSolverBodies(world);
    JointConstraints reused(kDefaultJointOrder, JointFeedback::Kind::Soft, /*relaxOnBiasedRows=*/true);
    reused.prepare(world, bodies, h, /*positionFeedback=*/true);
    const JointRows biased = reused.rows();
    REQUIRE(biased.rows.size() == 8);  // three point rows, two for the axis, two limits, the motor
    const auto turn = [&] {  // the arm turns a little, as it does through a substep
        Transform& pose = world.bodies[static_cast<std::size_t>(body)].transform;
        pose.rotation = (Quat(Eigen::AngleAxis<Real>(Real(0.05), Vec3::UnitZ())) * pose.rotation).normalized();
    };
    turn();
    reused.prepare(world, bodies, h, /*positionFeedback=*/false);
    const JointRows& relax = reused.rows();
    for (std::size_t i = 0; i < biased.rows.size(); ++i) {
        INFO("row " << i);
        CHECK(relax.rows[i].angularB == biased.rows[i].angularB);  // the biased pass's Jacobians
        if (biased.fedBack[i]) {
            CHECK(relax.rows[i].bias == 0);
            CHECK(relax.softness[i].massScale == 1);
            CHECK(relax.softness[i].impulseScale == 0);
        } else {
            CHECK(relax.rows[i].bias == biased.rows[i].bias);  // limits ahead, the motor's speed
        }
    }
    CHECK(biased.fedBack[0]);                          // the point rows are fed back
    CHECK(!biased.fedBack[7]);                         // the motor is not
    CHECK(relax.rows[7].bias == Real(1.5));

    // Without the option the relax pass builds its rows where the bodies are now.
    JointConstraints rebuilt;
    rebuilt.prepare(world, bodies, h, true);
    const Vec3 before = rebuilt.rows().rows[1].angularB;
    turn();
    rebuilt.prepare(world, bodies, h, false);
    CHECK((rebuilt.rows().rows[1].angularB - before).norm() > Real(1e-3));
}
