// Exercise check for chapter 3 (`ctest -L ch03-exercise`): rewrite collideBoxSphere in
// chapters/03_epa/closed_form.cpp from the page (clamp the centre into the box; when the centre
// is inside, leave through the nearest face), and run this. It checks your contact against an
// independent computation in double and against the contact's own promises.
#include "03_epa/closed_form.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

using namespace stepwise;

namespace {

// Signed depth of a sphere in an axis-aligned box, computed another way: distance to the box
// when outside, minus the distance to the nearest face when inside.
double expectedDepth(const Vec3& halfExtents, const Vec3& localCenter, double radius) {
    double outside = 0, inside = 1e30;
    for (int i = 0; i < 3; ++i) {
        const double excess = std::abs(double(localCenter[i])) - double(halfExtents[i]);
        outside += excess > 0 ? excess * excess : 0;
        inside = std::min(inside, -excess);
    }
    return outside > 0 ? radius - std::sqrt(outside) : radius + inside;
}

}  // namespace

TEST_CASE("exercise: box-sphere contacts have the right depth, normal and points", "[ch03-exercise]") {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_real_distribution<double> size(0.1, 2);
    std::normal_distribution<double> gauss;
    for (int trial = 0; trial < 5000; ++trial) {
        const Vec3 halfExtents(Real(size(random)), Real(size(random)), Real(size(random)));
        Transform box;
        box.position = Vec3(Real(unit(random)), Real(unit(random)), Real(unit(random)));
        box.rotation = Quat(Real(gauss(random)), Real(gauss(random)), Real(gauss(random)), Real(gauss(random)));
        box.rotation.normalize();
        // Centres inside, near and outside the box.
        const Vec3 local(Real(1.5 * unit(random) * halfExtents.x()), Real(1.5 * unit(random) * halfExtents.y()),
                         Real(1.5 * unit(random) * halfExtents.z()));
        const Real radius = Real(0.5 * size(random));
        const Vec3 center = box.apply(local);
        const ContactQuery contact = collideBoxSphere(halfExtents, box, center, radius);
        const double depth = expectedDepth(halfExtents, local, radius);
        INFO("trial " << trial << ": half extents (" << halfExtents.transpose() << "), centre in box frame ("
                      << local.transpose() << "), radius " << radius << ", expected depth " << depth
                      << ", yours " << contact.depth);
        REQUIRE(std::abs(contact.depth - depth) < 1e-4);
        REQUIRE(contact.intersect == (contact.depth >= 0));
        REQUIRE(std::abs(contact.normal.norm() - 1) < 1e-4);
        // The points are depth apart along the normal (normal from the box towards the sphere).
        REQUIRE((contact.pointA - contact.pointB - contact.depth * contact.normal).norm() < 1e-4);
        // pointB is on the sphere, pointA on the box's surface.
        REQUIRE(std::abs((contact.pointB - center).norm() - radius) < 1e-4);
        const Vec3 onBox = box.applyInverse(contact.pointA);
        REQUIRE(((onBox.cwiseAbs() - halfExtents).array() <= 1e-4).all());
        REQUIRE((onBox.cwiseAbs() - halfExtents).maxCoeff() > -1e-4);
    }
}
