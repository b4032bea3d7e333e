// Exercise check for chapter 3 (`ctest -L ch03-exercise`), the derive exercise: two cubes of
// half size 1, A at the origin, B turned 45 degrees about z and centred at (2.2, 0, 0). Which
// depth, normal and contact points does the narrowphase give? The page's answer, from the
// separating axes (the depth is the smallest overlap over the candidate directions, chapter 2's
// box oracle): along x, A reaches 1 and B's leading edge (the corner line x = 2.2 - sqrt 2,
// y = 0) reaches back to 2.2 - sqrt 2, an overlap of d = 1 + sqrt 2 - 2.2 = 0.2142 m; along B's
// face normals (x + y) / sqrt 2 the overlap is sqrt 2 + 1 - 2.2 / sqrt 2 = 0.858 m; along y and
// z it is larger still. So d = 0.2142 m along n = (1, 0, 0), point B on B's leading edge and
// point A = point B + d n on A's face x = 1. Which point of the edge is not fixed by the
// geometry: one contact point cannot say it (chapter 6 keeps several).
#include "03_epa/narrowphase.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

TEST_CASE("exercise: the turned cube's depth, normal and points are the derived ones", "[ch03-exercise]") {
    const Shape cube = Shape::box(Vec3(1, 1, 1));
    Transform poseA, poseB;
    poseB.position = Vec3(Real(2.2), 0, 0);
    poseB.rotation = Quat(Eigen::AngleAxis<Real>(Real(3.14159265358979323846 / 4), Vec3::UnitZ()));
    const ContactQuery contact = collideShapes(cube, poseA, cube, poseB);
    const double root2 = std::sqrt(2.0);
    const double depth = 1 + root2 - 2.2;
    INFO("routine " << contact.routine << ", depth " << contact.depth << ", normal (" << contact.normal.transpose()
                    << "), point A (" << contact.pointA.transpose() << "), point B (" << contact.pointB.transpose() << ")");
    REQUIRE(contact.intersect);
    CHECK(contact.depth == Approx(depth).epsilon(1e-4));
    CHECK(contact.normal.x() == Approx(1).margin(1e-4));
    CHECK(contact.pointB.x() == Approx(2.2 - root2).margin(1e-4));
    CHECK(contact.pointB.y() == Approx(0).margin(1e-4));
    CHECK(std::abs(contact.pointB.z()) <= 1 + 1e-4);
    CHECK(contact.pointA.x() == Approx(1).margin(1e-4));
    CHECK((contact.pointA - contact.pointB - contact.depth * contact.normal).norm() < 1e-4);
}
