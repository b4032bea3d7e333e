// Warm starting: carried impulses become the rows' starting impulses, friction projected onto
// this step's directions and kept in the cone; a solve that starts from last step's answer needs
// no iterations to hold a resting box.
#include "06_manifolds/chapter.h"
#include "06_manifolds/stabilisation.h"
#include "06_manifolds/warm_start.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

/// A unit box of 1 kg resting on the ground, settled for 2 s through chapter 6's pipeline.
World settledBox(Stabilisation stabilisation = Stabilisation::Baumgarte) {
    World world = test::makeWorld();
    world.settings.stabilisation = stabilisation;
    test::addGround(world);
    test::addBox(world, Vec3(0, Real(0.5), 0), Vec3(Real(0.5), Real(0.5), Real(0.5)), BodyType::Dynamic,
                 Quat::Identity(), 1);
    Pipeline pipeline = makeChapter06Pipeline(world);
    test::simulate(world, pipeline, 2.0);
    return world;
}

}  // namespace

TEST_CASE("carried impulses load into the rows: normal as is, friction projected and kept in the cone", "[ch06][warm]") {
    World world = settledBox();
    REQUIRE(world.contacts.size() == 1);
    Contact& contact = world.contacts[0];
    REQUIRE(contact.pointCount == 4);
    Vec3 basis1, basis2;
    tangentBasis(contact.normal, basis1, basis2);
    contact.points[0].normalImpulse = 2;
    contact.points[0].tangentImpulse[0] = Real(0.3);   // inside the cone of 0.6 x 2
    contact.points[0].tangentImpulse[1] = Real(-0.4);
    contact.points[1].normalImpulse = 1;
    contact.points[1].tangentImpulse[0] = 3;           // far outside the cone of 0.6 x 1
    contact.points[1].tangentImpulse[1] = 0;
    std::vector<SolverBody> bodies = gatherSolverBodies(world);
    ContactRows rows = buildContactRows(world, bodies, world.settings.dt);
    loadCarriedImpulses(world, rows);
    REQUIRE(rows.points.size() == 4);
    const auto frictionOf = [&](const ContactRowRef& ref) {
        return Vec3(rows.rows[ref.tangentRow[0]].impulse * ref.tangent[0] + rows.rows[ref.tangentRow[1]].impulse * ref.tangent[1]);
    };
    CHECK(rows.rows[rows.points[0].normalRow].impulse == Approx(2));
    CHECK((frictionOf(rows.points[0]) - (Real(0.3) * basis1 - Real(0.4) * basis2)).norm() < 1e-5);
    CHECK(rows.rows[rows.points[1].normalRow].impulse == Approx(1));
    CHECK(frictionOf(rows.points[1]).norm() == Approx(0.6).epsilon(1e-4));        // mu times the normal impulse
    CHECK(frictionOf(rows.points[1]).normalized().dot(basis1) == Approx(1).epsilon(1e-4));  // same direction
}

TEST_CASE("a solve warm started from last step's answer holds a resting box with no iterations at all", "[ch06][warm]") {
    for (bool warm : {true, false}) {
        World world = settledBox();
        world.settings.warmStarting = warm;
        world.settings.solverIterations = 0;
        const Real before = world.bodies[1].transform.position.y();
        Pipeline pipeline = makeChapter06Pipeline(world);
        pipeline.step(world);
        const Real speed = world.motionOf(1)->linearVelocity.norm();
        INFO((warm ? "warm" : "cold") << ": speed " << speed << " m/s");
        if (warm)
            CHECK(speed < 1e-3);  // the carried impulses alone cancel gravity's g dt = 0.16 m/s
        else
            CHECK(speed == Approx(9.81 / 60).epsilon(1e-3));
        CHECK(world.bodies[1].transform.position.y() <= before);
    }
}

TEST_CASE("warm starting converges: ten iterations leave a smaller residual than ten cold ones", "[ch06][warm]") {
    double residual[2] = {0, 0};
    for (int warm = 0; warm < 2; ++warm) {
        World world = test::makeWorld();
        world.settings.stabilisation = Stabilisation::Baumgarte;
        world.settings.warmStarting = warm == 1;
        test::addGround(world);
        for (int i = 0; i < 6; ++i)
            test::addBox(world, Vec3(0, Real(0.5) + static_cast<Real>(i), 0), Vec3(Real(0.5), Real(0.5), Real(0.5)),
                         BodyType::Dynamic, Quat::Identity(), 1);
        Pipeline pipeline = makeChapter06Pipeline(world);
        test::simulate(world, pipeline, 1.0);
        residual[warm] = static_cast<double>(world.step.solver.residualMax);
    }
    INFO("largest row residual: cold " << residual[0] << " m/s, warm " << residual[1] << " m/s");
    CHECK(residual[1] < 0.1 * residual[0]);
}

TEST_CASE("soft contacts: Box2D's coefficients, and a rigid row when the frequency is zero", "[ch06][warm]") {
    const Softness soft = makeSoftness(30, 10, Real(1.0 / 240));
    const double omega = 2 * kPi * 30, h = 1.0 / 240, a1 = 2 * 10 + h * omega, a2 = h * omega * a1;
    CHECK(soft.biasRate == Approx(omega / a1).epsilon(1e-5));
    CHECK(soft.massScale == Approx(a2 / (1 + a2)).epsilon(1e-5));
    CHECK(soft.impulseScale == Approx(1 / (1 + a2)).epsilon(1e-5));
    const Softness rigid = makeSoftness(0, 10, Real(1.0 / 240));
    CHECK(rigid.massScale == 1);
    CHECK(rigid.impulseScale == 0);
}
