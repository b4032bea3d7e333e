// Exercise check for chapter 6 (`ctest -L ch06-exercise`): rewrite reduceManifold in
// chapters/06_manifolds/reduction.cpp from the page's four rules (the deepest point, the farthest
// from it, the largest triangle, the most area added), and run this. The check has its own greedy
// choice, written apart from the chapter, and asks of yours: never more than four points, none
// twice, the deepest first, and each later point within the page's 5% of the best score for its
// rule; the last three from the touching points first. Degenerate patches (one place, one line)
// must give one and two points.
#include "06_manifolds/reduction.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

namespace {

// Points in the plane y = 0 (the normal is +y); the reduction reads pointA and depth.
ManifoldPoint pointAt(Real x, Real z, Real depth) {
    ManifoldPoint point;
    point.pointA = Vec3(x, 0, z);
    point.pointB = point.pointA - depth * Vec3::UnitY();
    point.depth = depth;
    return point;
}

// Twice the signed area of (a, b, c) seen from +y, as the page measures it.
Real area2(const Vec3& a, const Vec3& b, const Vec3& c) { return (b - a).cross(c - a).dot(Vec3::UnitY()); }

Real areaAdded(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
    Real added = 0;
    for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) added += std::max(Real(0), -area2(u, v, p));
    return added;
}

}  // namespace

TEST_CASE("exercise: four points by the page's rules on random patches", "[ch06-exercise]") {
    Random random(606);
    for (int trial = 0; trial < 500; ++trial) {
        const int count = 1 + static_cast<int>(random.uniform() * 12);
        std::vector<ManifoldPoint> points;
        for (int i = 0; i < count; ++i)
            points.push_back(pointAt(random.uniformReal(-1, 1), random.uniformReal(-1, 1), random.uniformReal(0, Real(0.05))));
        int chosen[kMaxManifoldPoints] = {-1, -1, -1, -1};
        const int kept = reduceManifold(points, Vec3::UnitY(), chosen);
        INFO("trial " << trial << ": " << count << " candidates, your reduction kept " << kept);
        REQUIRE(kept >= 1);
        REQUIRE(kept <= std::min(count, kMaxManifoldPoints));
        for (int k = 0; k < kept; ++k) {
            REQUIRE(chosen[k] >= 0);
            REQUIRE(chosen[k] < count);
            for (int j = 0; j < k; ++j) REQUIRE(chosen[j] != chosen[k]);
        }
        const auto at = [&](int i) -> const Vec3& { return points[static_cast<std::size_t>(i)].pointA; };
        const auto isChosen = [&](int i, int used) { return std::find(chosen, chosen + used, i) != chosen + used; };

        // 1. The deepest point comes first.
        Real deepest = points[0].depth;
        for (const ManifoldPoint& point : points) deepest = std::max(deepest, point.depth);
        INFO("the first point is " << points[static_cast<std::size_t>(chosen[0])].depth << " deep, the deepest "
                                   << deepest);
        REQUIRE(points[static_cast<std::size_t>(chosen[0])].depth >= deepest - Real(1e-4));
        // 2. Then (within 5%) the farthest from it; random points are never all in one place.
        Real farthest = 0;
        for (int i = 0; i < count; ++i) farthest = std::max(farthest, (at(i) - at(chosen[0])).squaredNorm());
        if (count > 1) REQUIRE(kept >= 2);
        if (kept < 2) continue;
        INFO("the second point's squared distance from the first is " << (at(chosen[1]) - at(chosen[0])).squaredNorm()
                                                                      << ", the largest " << farthest);
        REQUIRE((at(chosen[1]) - at(chosen[0])).squaredNorm() >= Real(0.95) * farthest - Real(1e-6));
        // 3. Then the largest triangle with those two, on either side; random points are never all
        // on one line.
        if (count > 2) REQUIRE(kept >= 3);
        if (kept < 3) continue;
        Real largest = 0;
        for (int i = 0; i < count; ++i)
            if (!isChosen(i, 2)) largest = std::max(largest, std::abs(area2(at(chosen[0]), at(chosen[1]), at(i))));
        const Real third = std::abs(area2(at(chosen[0]), at(chosen[1]), at(chosen[2])));
        INFO("the third point's triangle has twice the area " << third << ", the largest " << largest);
        REQUIRE(third >= Real(0.95) * largest - Real(1e-6));
        // 4. Then the point adding the most area to that triangle (oriented counter-clockwise); when
        // every other point lies inside the triangle, none adds any and three points are the answer.
        Vec3 a = at(chosen[0]), b = at(chosen[1]);
        const Vec3 c = at(chosen[2]);
        if (area2(a, b, c) < 0) std::swap(a, b);
        Real most = 0;
        for (int i = 0; i < count; ++i)
            if (!isChosen(i, 3)) most = std::max(most, areaAdded(a, b, c, at(i)));
        INFO("the most area another point adds to the triangle (twice): " << most);
        if (kept < 4) {
            REQUIRE(most <= Real(1e-6) * third);
            continue;
        }
        const Real fourth = areaAdded(a, b, c, at(chosen[3]));
        INFO("the fourth point adds twice the area " << fourth << ", the most any adds " << most);
        REQUIRE(fourth >= Real(0.95) * most - Real(1e-6));
    }
}

TEST_CASE("exercise: a regular octagon keeps a quadrilateral of most of its area", "[ch06-exercise]") {
    std::vector<ManifoldPoint> octagon;
    for (int k = 0; k < 8; ++k) {
        const double angle = k * 3.14159265358979323846 / 4;
        octagon.push_back(pointAt(Real(std::cos(angle)), Real(std::sin(angle)), k == 5 ? Real(0.001) : Real(0)));
    }
    int chosen[kMaxManifoldPoints] = {-1, -1, -1, -1};
    REQUIRE(reduceManifold(octagon, Vec3::UnitY(), chosen) == 4);
    REQUIRE(chosen[0] == 5);  // the deepest
    // The quadrilateral's area with its corners in angular order, against the octagon's 2 sqrt(2).
    std::vector<Vec3> corners;
    for (int k = 0; k < 4; ++k) corners.push_back(octagon[static_cast<std::size_t>(chosen[k])].pointA);
    std::sort(corners.begin(), corners.end(),
              [](const Vec3& p, const Vec3& q) { return std::atan2(p.z(), p.x()) < std::atan2(q.z(), q.x()); });
    Real twiceArea = 0;
    for (int k = 0; k < 4; ++k) twiceArea += std::abs(area2(Vec3::Zero(), corners[static_cast<std::size_t>(k)], corners[static_cast<std::size_t>((k + 1) % 4)]));
    const Real fraction = twiceArea / 2 / Real(2 * std::sqrt(2.0));
    INFO("your four points hold " << fraction * 100 << "% of the octagon's area (the best four hold 71%)");
    REQUIRE(fraction > Real(0.65));
}

TEST_CASE("exercise: a patch in one place gives one point, on one line its two ends", "[ch06-exercise]") {
    int chosen[kMaxManifoldPoints] = {-1, -1, -1, -1};
    const std::vector<ManifoldPoint> same(5, pointAt(Real(0.3), Real(-0.2), Real(0.01)));
    CHECK(reduceManifold(same, Vec3::UnitY(), chosen) == 1);
    std::vector<ManifoldPoint> line;
    for (int k = 0; k < 6; ++k) line.push_back(pointAt(Real(k) * Real(0.2), 0, k == 2 ? Real(0.02) : Real(0.01)));
    REQUIRE(reduceManifold(line, Vec3::UnitY(), chosen) == 2);
    CHECK(chosen[0] == 2);  // the deepest
    CHECK(chosen[1] == 5);  // the end farthest from it
    CHECK(reduceManifold({}, Vec3::UnitY(), chosen) == 0);
}

TEST_CASE("exercise: touching points come before speculative ones", "[ch06-exercise]") {
    // A patch touching along one edge (x = -0.5) whose far corners hang above the reference face.
    std::vector<ManifoldPoint> patch = {pointAt(Real(-0.5), Real(-0.3), Real(0.005)), pointAt(Real(-0.5), Real(0.1), Real(0.0049)),
                                        pointAt(Real(0.45), Real(0.46), Real(-0.007)), pointAt(Real(0.46), Real(-0.45), Real(-0.005))};
    int chosen[kMaxManifoldPoints] = {-1, -1, -1, -1};
    REQUIRE(reduceManifold(patch, Vec3::UnitY(), chosen) >= 2);
    CHECK(chosen[0] == 0);
    INFO("the second point must be the edge's other end (it touches), not a corner above the face");
    CHECK(chosen[1] == 1);
}
