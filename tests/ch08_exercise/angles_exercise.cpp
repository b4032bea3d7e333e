// Exercise check for chapter 8 (`ctest -L ch08-exercise`): rewrite twistAngle and swingAngle in
// chapters/08_joints/joint_frame.cpp from the page (the twist is the deviation's part along the
// axis, 2 atan2(v . a, w); the swing is the angle between the axis as A and as B carry it), and
// run this. Deviations are built as a swing about an axis across the twist axis times a twist
// about it, with known angles: both functions must give them back, down to swings of a tenth of
// a milliradian, which the arc cosine of a float dot product cannot resolve.
#include "08_joints/joint_frame.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

namespace {


Vec3 randomUnit(Random& random) {
    Vec3 v;
    do v = Vec3(Real(random.uniform(-1, 1)), Real(random.uniform(-1, 1)), Real(random.uniform(-1, 1)));
    while (v.norm() < Real(0.1) || v.norm() > 1);
    return v.normalized();
}

struct Case {
    Vec3 axis;         // the twist axis, A's frame
    double swing = 0;  // rad, about a direction across the axis
    double twist = 0;  // rad, about the axis
    Quat deviation;    // swing * twist
    Quat rotationA;
};

Case makeCase(Random& random, double swing, double twist) {
    Case c;
    c.axis = randomUnit(random);
    const Vec3 across = c.axis.cross(randomUnit(random)).normalized();
    c.swing = swing;
    c.twist = twist;
    c.deviation = Quat(Eigen::AngleAxis<Real>(Real(swing), across)) * Quat(Eigen::AngleAxis<Real>(Real(twist), c.axis));
    c.rotationA = Quat(Eigen::AngleAxis<Real>(Real(random.uniform(-3, 3)), randomUnit(random)));
    return c;
}

// The frame a joint with this deviation has, built as jointFrame builds it.
JointFrame frameOf(const Case& c) {
    JointFrame frame;
    frame.rotationA = c.rotationA;
    frame.deviation = c.deviation;
    frame.axisA = c.rotationA * c.axis;
    frame.axisB = c.rotationA * (c.deviation * c.axis);
    return frame;
}

}  // namespace

TEST_CASE("exercise: the twist of swing * twist is the twist, whatever the swing", "[ch08-exercise]") {
    Random random(808);
    for (int trial = 0; trial < 2000; ++trial) {
        const Case c = makeCase(random, random.uniform(0, 2.5), random.uniform(-3.1, 3.1));
        const double got = double(twistAngle(c.deviation, c.axis));
        INFO("trial " << trial << ": swing " << c.swing << ", twist " << c.twist << " rad; your twist " << got);
        REQUIRE(std::abs(got - c.twist) < 1e-4);
    }
}

TEST_CASE("exercise: the swing is the angle between the two copies of the axis, whatever the twist", "[ch08-exercise]") {
    Random random(809);
    for (int trial = 0; trial < 2000; ++trial) {
        const Case c = makeCase(random, random.uniform(0, double(kPi) - 0.05), random.uniform(-3.1, 3.1));
        const double got = double(swingAngle(frameOf(c)));
        INFO("trial " << trial << ": swing " << c.swing << ", twist " << c.twist << " rad; your swing " << got);
        REQUIRE(std::abs(got - c.swing) < 1e-4);
    }
}

TEST_CASE("exercise: swings of a tenth of a milliradian read true", "[ch08-exercise]") {
    // The arc cosine of the float just below 1 is 3.45e-4 rad: a swing smaller than that reads
    // 0 or 3.45e-4 through acos of the dot product. atan2 of the cross and dot products keeps it.
    Random random(810);
    for (int trial = 0; trial < 200; ++trial) {
        const double swing = 1e-4 * (1 + trial % 3);
        const Case c = makeCase(random, swing, random.uniform(-3, 3));
        const double got = double(swingAngle(frameOf(c)));
        INFO("trial " << trial << ": swing " << swing << " rad; your swing " << got);
        REQUIRE(std::abs(got - swing) < 2e-5);
    }
}
