// Exercise check for chapter 2 (`ctest -L ch02-exercise`): rewrite the box's support map
// (boxSupportByExtents in chapters/02_gjk/support.cpp) from the page's three sign tests, and
// run this. It compares your map with a brute-force search over the 8 corners in 10,000
// directions, including directions with zero components, where corners tie.
#include "02_gjk/support.h"

#include <catch2/catch.hpp>

#include <random>

using namespace stepwise;

namespace {

Real bestCornerDot(const Vec3& halfExtents, const Vec3& direction) {
    Real best = -kRealMax;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 vertex((corner & 1) ? halfExtents.x() : -halfExtents.x(),
                          (corner & 2) ? halfExtents.y() : -halfExtents.y(),
                          (corner & 4) ? halfExtents.z() : -halfExtents.z());
        best = std::max(best, vertex.dot(direction));
    }
    return best;
}

}  // namespace

TEST_CASE("exercise: the box support map returns a farthest corner", "[ch02-exercise]") {
    std::mt19937 random(42);
    std::uniform_real_distribution<double> component(-1, 1);
    std::uniform_real_distribution<double> size(0.05, 2);
    std::uniform_int_distribution<int> zeroAxis(-1, 2);
    for (int trial = 0; trial < 10000; ++trial) {
        const Vec3 halfExtents(Real(size(random)), Real(size(random)), Real(size(random)));
        Vec3 direction(Real(component(random)), Real(component(random)), Real(component(random)));
        const int axis = zeroAxis(random);
        if (axis >= 0) direction[axis] = 0;  // a whole face or edge ties
        const Shape box = Shape::box(halfExtents);
        const Vec3 point = localSupport(box, direction, SupportMode::Extents);
        INFO("half extents (" << halfExtents.transpose() << "), direction (" << direction.transpose()
                               << "), your point (" << point.transpose() << ")");
        // A corner: every coordinate is plus or minus the half extent.
        for (int i = 0; i < 3; ++i) REQUIRE(std::abs(std::abs(point[i]) - halfExtents[i]) <= 1e-6);
        // As far along the direction as the best corner.
        REQUIRE(point.dot(direction) >= bestCornerDot(halfExtents, direction) - Real(1e-6));
    }
}

TEST_CASE("exercise: the box support map accepts the zero direction", "[ch02-exercise]") {
    const Vec3 halfExtents(1, 2, 3);
    const Vec3 point = localSupport(Shape::box(halfExtents), Vec3::Zero(), SupportMode::Extents);
    INFO("your point (" << point.transpose() << ")");
    REQUIRE(point.allFinite());
    for (int i = 0; i < 3; ++i) REQUIRE(std::abs(point[i]) <= halfExtents[i]);
}
