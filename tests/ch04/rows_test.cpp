// The solver on contacts built by hand: what one row does, the clamps, the bounds, the drop rules,
// infinite masses and bad input.
#include "04_pgs/contact_constraints.h"
#include "04_pgs/solver.h"
#include "ch04_support.h"
#include "support/fixture.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

// A ground (body 0, top at y = 0) and a 1 kg ball of radius 0.5 sunk `depth` into it (body 1),
// with the matching contact in World::contacts. No gravity: the test sets the velocities.
World ballOnGround(Real depth, const Vec3& velocity, const Vec3& angularVelocity = Vec3::Zero()) {
    World world = test::makeWorld(test::zeroGravitySettings());
    test::addGround(world);
    const int ball = test::addSphere(world, Vec3(0, Real(0.5) - depth, 0), Real(0.5), BodyType::Dynamic, 1);
    test::setVelocity(world, ball, velocity, angularVelocity);
    world.contacts.push_back(test::makeContact(0, ball, Vec3::UnitY(), Vec3(0, -depth, 0), depth));
    return world;
}

}  // namespace

TEST_CASE("a normal row stops an approaching ball and records its impulse", "[ch04][rows]") {
    World world = ballOnGround(Real(0.001), Vec3(0, Real(-0.5), 0));  // slower than the restitution threshold
    const SolverStats stats = solveContacts(world, Real(1.0 / 60));
    CHECK(stats.rows == 3);
    const Motion& ball = *world.motionOf(1);
    CHECK(std::abs(ball.linearVelocity.y()) < 1e-5);
    CHECK(ball.angularVelocity.norm() < 1e-5);
    REQUIRE(world.contacts.size() == 1);
    CHECK(world.contacts[0].points[0].normalImpulse == Approx(0.5).epsilon(1e-4));  // m * 0.5 m/s
    CHECK(stats.residualMax < 1e-5);
}

TEST_CASE("effective masses follow J M^-1 J^T", "[ch04][rows]") {
    // A ball touching at its lowest point: the normal passes through the centre (mass m); a
    // tangent at the rim sees m / (1 + m r^2 / I) = m / (1 + 5/2) = 2m/7, the 2/7 of rolling.
    World world = ballOnGround(0, Vec3(0, -1, 0));
    std::vector<SolverBody> bodies = gatherSolverBodies(world);
    const ContactRows contactRows = buildContactRows(world, bodies, Real(1.0 / 60));
    REQUIRE(contactRows.points.size() == 1);
    const ContactRowRef& ref = contactRows.points[0];
    CHECK(contactRows.rows[ref.normalRow].effectiveMass == Approx(1).epsilon(1e-5));
    CHECK(contactRows.rows[ref.tangentRow[0]].effectiveMass == Approx(2.0 / 7).epsilon(1e-4));
    CHECK(contactRows.rows[ref.tangentRow[1]].effectiveMass == Approx(2.0 / 7).epsilon(1e-4));
}

TEST_CASE("Baumgarte asks for beta/dt of the depth beyond the slop, restitution for -e v", "[ch04][rows]") {
    const Real dt = Real(1.0 / 60);
    SECTION("deep and slow: Baumgarte") {
        World world = ballOnGround(Real(0.025), Vec3(0, Real(-0.1), 0));
        std::vector<SolverBody> bodies = gatherSolverBodies(world);
        const ContactRows rows = buildContactRows(world, bodies, dt);
        const Settings& s = world.settings;
        CHECK(rows.rows[rows.points[0].normalRow].bias == Approx(s.baumgarte / dt * (Real(0.025) - s.slop)).epsilon(1e-4));
    }
    SECTION("shallow and fast: restitution, above the threshold only") {
        World world = ballOnGround(Real(0.001), Vec3(0, -3, 0));
        world.bodies[1].material.restitution = Real(0.5);
        std::vector<SolverBody> bodies = gatherSolverBodies(world);
        ContactRows rows = buildContactRows(world, bodies, dt);
        CHECK(rows.rows[rows.points[0].normalRow].bias == Approx(1.5).epsilon(1e-5));
        solveGaussSeidel(rows.rows, bodies, 10);
        CHECK(bodies[1].linearVelocity.y() == Approx(1.5).epsilon(1e-4));

        test::setVelocity(world, 1, Vec3(0, Real(-0.9), 0));  // below restitutionThreshold = 1 m/s
        bodies = gatherSolverBodies(world);
        rows = buildContactRows(world, bodies, dt);
        CHECK(rows.rows[rows.points[0].normalRow].bias == 0);
    }
}

TEST_CASE("a spinning body bounces only off a floor its points can reach in the step", "[ch04][rows]") {
    // A corner 4.2 cm from the centre turning at 458 rad/s falls at 14 m/s, but in a frame of
    // 1/60 s it sweeps 7.6 rad of a circle and comes at most 8.5 cm nearer anything; with the body
    // falling at 8 m/s (13 cm in the frame) a floor 30 cm below the corner is out of reach, and the
    // corner must not bounce off it. Read off its velocity alone (-22 m/s, 36 cm in the frame), it
    // "closed" the gap and bounced (found by fuzz_stepper: 0.16 J to 0.40 J in one frame).
    const Real dt = Real(1.0 / 60);
    const auto spinningAbove = [&](Real gap) {
        World world = test::makeWorld(test::zeroGravitySettings());
        test::addGround(world);
        const int box = test::addBox(world, Vec3(0, gap + Real(0.03), 0), Vec3::Constant(Real(0.03)));
        world.bodies[static_cast<std::size_t>(box)].material.restitution = Real(0.9);
        // The corner (-0.03, -0.03, 0) of the box turns downwards at 458 * 0.03 m/s.
        test::setVelocity(world, box, Vec3(0, -8, 0), Vec3(0, 0, 458));
        world.contacts.push_back(test::makeContact(0, box, Vec3::UnitY(), Vec3(Real(-0.03), gap, 0), -gap));
        return world;
    };
    SECTION("a floor out of reach: the point may close its gap and no faster") {
        World world = spinningAbove(Real(0.3));
        const ContactRows rows = buildContactRows(world, gatherSolverBodies(world), dt);
        CHECK(rows.rows[rows.points[0].normalRow].bias == Approx(-Real(0.3) / dt).epsilon(1e-5));
    }
    SECTION("a floor within reach: the point bounces at -e times its approach") {
        World world = spinningAbove(Real(0.1));
        std::vector<SolverBody> bodies = gatherSolverBodies(world);
        const ContactRows rows = buildContactRows(world, bodies, dt);
        const ContactRowRef& ref = rows.points[0];
        const Real approach = rows.rows[ref.normalRow].linearB.dot(bodies[1].linearVelocity) +
                              rows.rows[ref.normalRow].angularB.dot(bodies[1].angularVelocity);
        REQUIRE(approach < -1);
        CHECK(rows.rows[ref.normalRow].bias == Approx(-Real(0.9) * approach).epsilon(1e-5));
    }
}

TEST_CASE("the accumulated normal impulse is clamped, not each increment", "[ch04][rows]") {
    // Two balls side by side on the ground, touching each other, both pressed down. Gauss-Seidel
    // overshoots on some rows and takes impulse back in later sweeps; at every point the totals
    // must stay pushes, friction inside mu times the normal impulse.
    World world = test::makeWorld(test::zeroGravitySettings());
    test::addGround(world);
    const int left = test::addSphere(world, Vec3(Real(-0.499), Real(0.499), 0), Real(0.5), BodyType::Dynamic, 1);
    const int right = test::addSphere(world, Vec3(Real(0.499), Real(0.499), 0), Real(0.5), BodyType::Dynamic, 3);
    test::setVelocity(world, left, Vec3(2, -1, 0), Vec3(0, 0, 3));
    test::setVelocity(world, right, Vec3(-1, -2, 0));
    world.contacts.push_back(test::makeContact(0, left, Vec3::UnitY(), Vec3(Real(-0.499), Real(-0.001), 0), Real(0.001)));
    world.contacts.push_back(test::makeContact(0, right, Vec3::UnitY(), Vec3(Real(0.499), Real(-0.001), 0), Real(0.001)));
    world.contacts.push_back(test::makeContact(left, right, Vec3::UnitX(), Vec3(Real(-0.001), Real(0.499), 0), Real(0.002)));
    std::vector<SolverBody> bodies = gatherSolverBodies(world);
    ContactRows contactRows = buildContactRows(world, bodies, Real(1.0 / 60));
    REQUIRE(contactRows.points.size() == 3);
    for (int iterations = 1; iterations <= 8; ++iterations) {
        ContactRows rows = contactRows;
        std::vector<SolverBody> solved = bodies;
        solveGaussSeidel(rows.rows, solved, iterations);
        for (const ContactRowRef& ref : rows.points) {
            const Real normalImpulse = rows.rows[ref.normalRow].impulse;
            CHECK(normalImpulse >= 0);
            const ConstraintRow& friction = rows.rows[ref.tangentRow[0]];
            CHECK(std::abs(friction.impulse) <= friction.boundScale * normalImpulse * (1 + 1e-5) + 1e-7);
        }
    }
    ContactRows rows = contactRows;
    solveGaussSeidel(rows.rows, bodies, 200);
    CHECK(measureResidual(rows.rows, bodies).max < 1e-4);
    // Solved: no point still approaches.
    for (const ContactRowRef& ref : rows.points) CHECK(rowVelocity(rows.rows[ref.normalRow], bodies) > -1e-4);
}

TEST_CASE("friction of a sliding ball is bounded by mu times the normal impulse, against the slide", "[ch04][rows]") {
    World world = ballOnGround(Real(0.001), Vec3(3, Real(-0.5), 4));  // slides along (0.6, 0, 0.8)
    world.bodies[0].material.friction = Real(0.3);
    world.bodies[1].material.friction = Real(0.3);
    solveContacts(world, Real(1.0 / 60));
    REQUIRE(world.contacts.size() == 1);
    const ContactPoint& point = world.contacts[0].points[0];
    const Vec3 fixed1 = anyPerpendicular(Vec3::UnitY());
    const Vec3 fixed2 = Vec3::UnitY().cross(fixed1);
    const Vec3 frictionImpulse = point.tangentImpulse[0] * fixed1 + point.tangentImpulse[1] * fixed2;
    CHECK(frictionImpulse.norm() == Approx(0.3 * point.normalImpulse).epsilon(1e-4));  // the cone, not the pyramid
    CHECK(frictionImpulse.normalized().dot(Vec3(Real(-0.6), 0, Real(-0.8))) == Approx(1).epsilon(1e-5));
}

TEST_CASE("pair materials combine as sqrt(f_a f_b) and max(r_a, r_b)", "[ch04][rows]") {
    CHECK(combinedFriction(Material{Real(0.4), 0}, Material{Real(0.9), 0}) == Approx(0.6));
    CHECK(combinedRestitution(Material{0, Real(0.2)}, Material{0, Real(0.7)}) == Approx(0.7));
    CHECK(combinedFriction(Material{Real(-1), 0}, Material{1, 0}) == 0);  // a negative friction is none
}

TEST_CASE("drop rule: after the solves, points that carried nothing leave the contact cache", "[ch04][rows]") {
    SECTION("moving apart faster than the target: no impulse, removed") {
        World world = ballOnGround(Real(0.004), Vec3(1, Real(0.2), 0));
        const SolverStats stats = solveContacts(world, Real(1.0 / 60));
        CHECK(stats.rows == 3);
        CHECK(dropUnloadedContactPoints(world) == 1);
        CHECK(world.contacts.empty());
        CHECK(world.motionOf(1)->linearVelocity.isApprox(Vec3(1, Real(0.2), 0)));  // untouched: no friction either
    }
    SECTION("moving apart, but slower than Baumgarte asks: pushed, kept") {
        World world = ballOnGround(Real(0.03), Vec3(0, Real(0.2), 0));
        solveContacts(world, Real(1.0 / 60));
        CHECK(dropUnloadedContactPoints(world) == 0);
        CHECK(world.contacts.size() == 1);
    }
    SECTION("at rest and unloaded: solved with zero impulse, then removed") {
        World world = ballOnGround(Real(0.002), Vec3::Zero());
        const SolverStats stats = solveContacts(world, Real(1.0 / 60));
        CHECK(stats.rows == 3);
        CHECK(dropUnloadedContactPoints(world) == 1);
        CHECK(world.contacts.empty());
    }
    SECTION("loaded: kept") {
        World world = ballOnGround(Real(0.002), Vec3(0, Real(-0.01), 0));
        solveContacts(world, Real(1.0 / 60));
        CHECK(dropUnloadedContactPoints(world) == 0);
        REQUIRE(world.contacts.size() == 1);
        CHECK(world.contacts[0].points[0].normalImpulse > kDropVelocityChange);
    }
    SECTION("separating when the solve starts, pushed shut by a neighbour during it: kept") {
        // A light ball on the ground with a heavy one on top; the heavy one moves up relative to
        // the light one as the solve starts, but the ground's push on the light ball closes the
        // gap within the same solve, so the upper point must keep its row and ends up loaded.
        World world = test::makeWorld(test::zeroGravitySettings());
        test::addGround(world);
        const int light = test::addSphere(world, Vec3(0, Real(0.399), 0), Real(0.4), BodyType::Dynamic, 1);
        const int heavy = test::addSphere(world, Vec3(0, Real(1.197), 0), Real(0.4), BodyType::Dynamic, 10);
        test::setVelocity(world, light, Vec3(0, Real(-0.5), 0));
        test::setVelocity(world, heavy, Vec3(0, Real(-0.45), 0));
        world.contacts.push_back(test::makeContact(0, light, Vec3::UnitY(), Vec3(0, Real(-0.001), 0), Real(0.001)));
        world.contacts.push_back(test::makeContact(light, heavy, Vec3::UnitY(), Vec3(0, Real(0.797), 0), Real(0.002)));
        solveContacts(world, Real(1.0 / 60));
        CHECK(dropUnloadedContactPoints(world) == 0);
        CHECK(world.contacts.size() == 2);
        CHECK(world.motionOf(heavy)->linearVelocity.y() >= world.motionOf(light)->linearVelocity.y() - 1e-4);
    }
}

TEST_CASE("static and kinematic bodies have infinite mass", "[ch04][rows]") {
    World world = test::makeWorld(test::zeroGravitySettings());
    test::addGround(world);
    const int lift = test::addBox(world, Vec3(0, Real(0.5), 0), Vec3(1, Real(0.5), 1), BodyType::Kinematic);
    const int ball = test::addSphere(world, Vec3(0, Real(1.499), 0), Real(0.5), BodyType::Dynamic, 1);
    test::setVelocity(world, lift, Vec3(0, 2, 0));
    world.contacts.push_back(test::makeContact(lift, ball, Vec3::UnitY(), Vec3(0, Real(0.999), 0), Real(0.001)));
    REQUIRE(world.motionOf(0) == nullptr);
    const std::vector<SolverBody> bodies = gatherSolverBodies(world);
    CHECK(bodies[0].inverseMass == 0);
    CHECK(bodies[lift].inverseMass == 0);
    CHECK(bodies[lift].inverseInertia.isZero());
    solveContacts(world, Real(1.0 / 60));
    CHECK(world.motionOf(lift)->linearVelocity.isApprox(Vec3(0, 2, 0)));  // the lift does not notice
    CHECK(world.motionOf(ball)->linearVelocity.y() == Approx(2).epsilon(1e-4));
    // A contact between two bodies that cannot move gets no rows at all.
    world.contacts.assign(1, test::makeContact(0, lift, Vec3::UnitY(), Vec3::Zero(), Real(0.01)));
    CHECK(solveContacts(world, Real(1.0 / 60)).rows == 0);
}

TEST_CASE("rows that start with impulses push the bodies first (the warm-start seam)", "[ch04][rows]") {
    World world = ballOnGround(Real(0.001), Vec3(1, -2, 0));
    std::vector<SolverBody> bodies = gatherSolverBodies(world);
    const std::vector<SolverBody> initial = bodies;
    ContactRows rows = buildContactRows(world, bodies, Real(1.0 / 60));
    solveGaussSeidel(rows.rows, bodies, 20);
    std::vector<SolverBody> replayed = initial;
    applyRowImpulses(rows.rows, replayed);
    CHECK(replayed[1].linearVelocity.isApprox(bodies[1].linearVelocity, Real(1e-5)));
    CHECK(replayed[1].angularVelocity.isApprox(bodies[1].angularVelocity, Real(1e-5)));
    // Solving on from there changes nothing: the stored impulses are a solution.
    solveGaussSeidel(rows.rows, replayed, 5);
    CHECK((replayed[1].linearVelocity - bodies[1].linearVelocity).norm() < 1e-5);
}

TEST_CASE("bad contacts are skipped, never NaN", "[ch04][rows]") {
    World world = ballOnGround(Real(0.001), Vec3(0, -1, 0));
    world.contacts[0].normal = Vec3(std::nan(""), 1, 0);
    world.contacts.push_back(test::makeContact(0, 1, Vec3::UnitY(), Vec3(0, Real(-0.001), 0), std::numeric_limits<Real>::infinity()));
    const SolverStats stats = solveContacts(world, Real(1.0 / 60));
    CHECK(stats.rows == 0);
    CHECK(world.motionOf(1)->linearVelocity.allFinite());
    world.contacts.assign(1, test::makeContact(0, 1, Vec3::UnitY(), Vec3(0, Real(-0.001), 0), Real(0.001)));
    world.settings.solverIterations = -3;  // no iterations: a defined result
    CHECK(solveContacts(world, Real(1.0 / 60)).residualMax > 0);
    world.contacts.assign(1, test::makeContact(0, 1, Vec3::UnitY(), Vec3(0, Real(-0.001), 0), Real(0.001)));
    CHECK(solveContacts(world, 0).rows == 3);  // dt = 0: no Baumgarte, still finite
    CHECK(world.motionOf(1)->linearVelocity.allFinite());

    // Malformed contacts: a body index out of range, a body against itself, too many points.
    world.contacts.assign(1, test::makeContact(0, 7, Vec3::UnitY(), Vec3::Zero(), Real(0.001)));
    world.contacts.push_back(test::makeContact(1, 1, Vec3::UnitY(), Vec3::Zero(), Real(0.001)));
    world.contacts.push_back(test::makeContact(0, 1, Vec3::UnitY(), Vec3::Zero(), Real(0.001)));
    world.contacts.back().pointCount = 9;
    const SolverStats malformed = solveContacts(world, Real(1.0 / 60));
    CHECK(malformed.rows == 0);
    CHECK(malformed.invalidSkipped > 0);
    dropUnloadedContactPoints(world);
    CHECK(world.contacts.empty());
}
