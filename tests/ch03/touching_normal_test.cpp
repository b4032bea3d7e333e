// Shapes within round-off of touching: GJK's closest points coincide and give no direction, so the
// normal comes from the axis between the shapes' cores. A wrong normal here is not harmless: a round
// body's contact point is found again as its surface along the normal (followContactPoint), and a
// capsule lying on a box read along the line of centres sits centimetres "deep" in it.
#include "03_epa/chapter.h"
#include "03_epa/narrowphase.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

using namespace stepwise;

TEST_CASE("a capsule lying on a box face, touching within round-off, gets the face's normal", "[ch03][narrowphase]") {
    const Shape box = Shape::box(Vec3(Real(0.35), Real(0.25), Real(0.25)));
    const Shape capsule = Shape::capsule(Real(0.2), Real(0.3));
    const Transform boxPose{Vec3::Zero(), Quat::Identity()};
    // Lying along x, its centre off to the side so the line of centres leans far from the face's normal.
    const Quat lying(Eigen::AngleAxis<Real>(kPi / 2, Vec3::UnitZ()));
    int checked = 0;
    for (Real offset : {Real(-2e-6), Real(-1e-6), Real(0), Real(1e-6), Real(2e-6)}) {
        for (Real x : {Real(0.1), Real(0.3)}) {
            const Transform capsulePose{Vec3(x, Real(0.45) + offset, Real(0.15)), lying};
            const ContactQuery query = collideShapes(box, boxPose, capsule, capsulePose);
            INFO("offset " << offset << ", x " << x << ": depth " << query.depth << ", normal " << query.normal.transpose()
                           << ", routine " << query.routine);
            CHECK(std::abs(query.depth) < Real(1e-5));
            CHECK(query.normal.y() > Real(0.999));
            // The capsule's surface along -normal is where the contact is: no false depth.
            const Vec3 core = capsulePose.position;
            const Vec3 axis = capsulePose.rotation * Vec3::UnitY();
            const Real along = std::clamp(axis.dot(query.pointB - core), -capsule.halfHeight, capsule.halfHeight);
            const Vec3 surface = core + along * axis - capsule.radius * query.normal;
            CHECK(query.normal.dot(query.pointA - surface) < Real(1e-4));
            ++checked;
        }
    }
    CHECK(checked == 10);
}

TEST_CASE("a capsule on a turned box, touching within round-off: the normal the shapes have", "[ch03][narrowphase]") {
    // The pose a dense pile of mixed shapes reached (tests/ch10's cache test finds such pairs).
    const Shape box = Shape::box(Vec3(Real(0.35), Real(0.25), Real(0.25)));
    const Shape capsule = Shape::capsule(Real(0.2), Real(0.3));
    const Transform boxPose{Vec3(Real(-3.74035907), Real(0.249930263), Real(2.59805274)),
                            Quat(Real(0.530129731), Real(0.53024894), Real(-0.467544913), Real(0.468188375)).normalized()};
    const Transform capsulePose{Vec3(Real(-3.35737419), Real(0.609641433), Real(3.1898756)),
                                Quat(Real(0.194868162), Real(0.751376927), Real(0.622484267), Real(0.0998626277)).normalized()};
    const ContactQuery query = collideShapes(box, boxPose, capsule, capsulePose);
    // Nudged 1 mm apart along the normal found, the pair is cleanly separated and GJK's closest points
    // give the normal directly: the touching answer must agree with it.
    const Transform apart{capsulePose.position + Real(0.001) * query.normal, capsulePose.rotation};
    const ContactQuery separated = collideShapes(box, boxPose, capsule, apart);
    INFO("touching normal " << query.normal.transpose() << ", 1 mm apart " << separated.normal.transpose());
    CHECK(std::abs(query.depth) < Real(1e-4));
    CHECK(separated.depth == Approx(-0.001).margin(2e-4));
    CHECK(query.normal.dot(separated.normal) > Real(0.999));
}

TEST_CASE("a sphere sunk a fraction of a millimetre into a cylinder's rim reads the depth it has", "[ch03][narrowphase]") {
    // Where a round body sinks into a rim, A - B is nearly flat around the origin and EPA can be
    // left without a volume to expand (one pose in several thousand here); GJK's distance between
    // the cores then says how deep the radii reach across, exactly. Checked against the closed
    // form of a sphere at a cylinder's rim, over random sizes, poses and depths of 0.1 to 3.1 mm.
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> unit(0, 1);
    int apart = 0, checked = 0;
    Real worst = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Shape cylinder = Shape::cylinder(Real(0.1) + Real(0.4) * unit(rng), Real(0.1) + Real(0.4) * unit(rng));
        const Shape sphere = Shape::sphere(Real(0.1) + Real(0.3) * unit(rng));
        Vec3 axis(unit(rng) - Real(0.5), unit(rng) - Real(0.5), unit(rng) - Real(0.5));
        axis.normalize();
        const Transform cylinderPose{Vec3(unit(rng) * 10 - 5, unit(rng) * 3, unit(rng) * 10 - 5),
                                     Quat(Eigen::AngleAxis<Real>(unit(rng) * 6, axis))};
        // A direction out of the rim (between the cap's normal and the side's) and a depth.
        const Real phi = 2 * kPi * unit(rng), tilt = Real(0.5) * kPi * unit(rng);
        const Vec3 out(std::cos(phi) * std::sin(tilt), std::cos(tilt), std::sin(phi) * std::sin(tilt));
        const Vec3 rim(cylinder.radius * std::cos(phi), cylinder.halfHeight, cylinder.radius * std::sin(phi));
        const Real depth = Real(0.0001) + Real(0.003) * unit(rng);
        const Transform spherePose{cylinderPose.apply(rim + (sphere.radius - depth) * out), Quat::Identity()};
        const ContactQuery query = collideShapes(sphere, spherePose, cylinder, cylinderPose);
        ++checked;
        if (!query.intersect) {
            ++apart;
            continue;
        }
        worst = std::max(worst, std::abs(query.depth - depth));
    }
    INFO(apart << " of " << checked << " sunk spheres read apart; worst depth error " << worst << " m");
    CHECK(apart == 0);
    CHECK(worst < Real(1e-4));
}
