// The bounds' speed bound measures its lever arm from the centre of mass: a hull whose mass sits
// off its origin, spinning fast, reaches farther in a frame than |v| + |w| r with r taken about
// the origin, and a pair it comes to touch must be a candidate at the start of the frame.
#include "01_integrators/integrate.h"
#include "03_epa/narrowphase.h"
#include "05_sap/chapter.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

namespace {

// A pyramid whose corners all lie on the unit ball about its origin: apex at x = -1, a thin base
// at x = 0.9. Its centre of mass is a quarter of the way from the base to the apex (x = 0.425),
// so the apex is 1.425 m from it: 42% farther than the origin's ball.
const Vec3 kApex(-1, 0, 0);

Shape offCentrePyramid() {
    const Real y = Real(0.02), z = Real(0.435);
    return Shape::convex({kApex, Vec3(Real(0.9), y, z), Vec3(Real(0.9), -y, z), Vec3(Real(0.9), y, -z),
                          Vec3(Real(0.9), -y, -z)});
}

struct SpinningHull {
    World world;
    Vec3 apexAtEnd;  // where the apex is after one frame of the spin, world
};

/// The pyramid at rest, spinning about z at 36 rad/s (0.6 rad in a 1/60 s frame), and a small
/// static ball where its apex ends the frame, 3 cm deep.
SpinningHull spinningHullAndBall() {
    SpinningHull scene;
    World& world = scene.world;
    BodyDef hull;
    hull.name = "pyramid";
    hull.shape = offCentrePyramid();
    hull.transform.position = Vec3(0, 5, 0);
    hull.angularVelocity = Vec3(0, 0, 36);
    addBody(world, hull);
    const Vec3 centre = hull.transform.apply(world.motions[0].localCenter);
    const Real turn = hull.angularVelocity.norm() * world.settings.dt;
    scene.apexAtEnd = centre + Eigen::AngleAxis<Real>(turn, Vec3::UnitZ()) * (kApex - world.motions[0].localCenter);
    BodyDef ball;
    ball.name = "ball";
    ball.type = BodyType::Static;
    ball.shape = Shape::sphere(Real(0.1));
    ball.transform.position = scene.apexAtEnd - Vec3(0, Real(0.07), 0);
    addBody(world, ball);
    return scene;
}

/// The bound with the arm taken about the origin: boundingRadius alone.
Aabb originArmBounds(const World& world, int bodyIndex) {
    const Body& body = world.bodies[static_cast<std::size_t>(bodyIndex)];
    const Motion& motion = *world.motionOf(bodyIndex);
    const Real dt = world.settings.dt;
    const Real speed = motion.linearVelocity.norm() + motion.angularVelocity.norm() * boundingRadius(body.shape);
    const Real grow = dt * (speed + world.settings.gravity.norm() * dt) + kBoundsMargin;
    Aabb box = computeAabb(body.shape, body.transform);
    box.min.array() -= grow;
    box.max.array() += grow;
    return box;
}

}  // namespace

TEST_CASE("the speed bound's lever arm is measured from the centre of mass", "[ch05][sap][bounds]") {
    SpinningHull scene = spinningHullAndBall();
    World& world = scene.world;
    const Motion& motion = world.motions[0];
    REQUIRE(world.bodies[0].shape.hull->vertexRadius == Approx(1).epsilon(1e-3));
    REQUIRE(motion.localCenter.x() == Approx(0.425).epsilon(1e-3));

    // The apex moves at |w| x 1.425 m: faster than |w| r about the origin, within the new bound.
    const Vec3 apexArm = world.bodies[0].transform.rotation * (kApex - motion.localCenter);
    const Real apexSpeed = (motion.linearVelocity + motion.angularVelocity.cross(apexArm)).norm();
    CHECK(apexSpeed > motion.angularVelocity.norm() * boundingRadius(world.bodies[0].shape) * Real(1.4));
    CHECK(apexSpeed <= pointSpeedBound(world, 0));
    CHECK(pointSpeedBound(world, 0) ==
          Approx(motion.angularVelocity.norm() * maxLeverArm(world.bodies[0].shape, motion.localCenter)));

    // The arm about the origin leaves the ball out; the broadphase keeps the pair.
    const Aabb ballBox = computeAabb(world.bodies[1].shape, world.bodies[1].transform);
    CHECK_FALSE(originArmBounds(world, 0).overlaps(ballBox));
    sweepAndPrune(world);
    CHECK(std::find(world.candidatePairs.begin(), world.candidatePairs.end(), BodyPair{0, 1}) !=
          world.candidatePairs.end());
    bruteForceBroadphase(world);
    CHECK(std::find(world.candidatePairs.begin(), world.candidatePairs.end(), BodyPair{0, 1}) !=
          world.candidatePairs.end());

    // ... and the pair does touch by the end of the frame.
    integrate(world, world.settings.dt);
    const Vec3 apex = world.bodies[0].transform.apply(kApex);
    CHECK((apex - scene.apexAtEnd).norm() < Real(0.01));
    CollideOptions options;
    options.separationDistance = false;
    const ContactQuery query = collideShapes(world.bodies[0].shape, world.bodies[0].transform, world.bodies[1].shape,
                                             world.bodies[1].transform, options);
    CHECK(query.intersect);
    CHECK(query.depth > Real(0.02));
}

TEST_CASE("a body whose centre of mass is its origin keeps the bound it had", "[ch05][sap][bounds]") {
    World world;
    BodyDef box;
    box.shape = Shape::box(Vec3(Real(0.5), Real(0.2), Real(0.3)));
    box.linearVelocity = Vec3(3, 0, 0);
    box.angularVelocity = Vec3(0, 10, 0);
    addBody(world, box);
    REQUIRE(world.motions[0].localCenter.norm() == 0);
    CHECK(pointSpeedBound(world, 0) == Approx(3 + 10 * boundingRadius(world.bodies[0].shape)));
    std::vector<Aabb> bounds;
    std::vector<char> dynamic;
    computeBroadphaseBounds(world, bounds, dynamic);
    const Aabb old = originArmBounds(world, 0);
    CHECK((bounds[0].min - old.min).cwiseAbs().maxCoeff() < Real(1e-5));
    CHECK((bounds[0].max - old.max).cwiseAbs().maxCoeff() < Real(1e-5));
}
