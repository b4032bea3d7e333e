// The simplex sub-algorithm against a brute-force reference in double: for every simplex, the
// closest point to the origin, its weights, and the feature kept.

#include "02_gjk/closest_point.h"
#include "gjk_test_util.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;
using oracle::Vec3d;

namespace {

double pointSegment(const Vec3d& a, const Vec3d& b) {
    return oracle::segmentSegmentDistance(a, b, Vec3d::Zero(), Vec3d::Zero());
}

// Distance from the origin to a triangle: the plane distance when the projection falls inside
// (all three edge tests agree in sign), else the nearest edge.
double pointTriangle(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    double best = std::min({pointSegment(a, b), pointSegment(b, c), pointSegment(c, a)});
    const Vec3d normal = (b - a).cross(c - a);
    if (normal.squaredNorm() < 1e-30) return best;
    const Vec3d projection = normal * (normal.dot(a) / normal.squaredNorm());
    const double u = (b - projection).cross(c - projection).dot(normal);
    const double v = (c - projection).cross(a - projection).dot(normal);
    const double w = (a - projection).cross(b - projection).dot(normal);
    if ((u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0)) best = std::min(best, projection.norm());
    return best;
}

double pointTetrahedron(const Vec3d p[4]) {
    // Inside when the origin and each vertex lie on the same side of the opposite face.
    const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
    bool inside = true;
    double best = 1e300;
    for (const auto& f : faces) {
        const Vec3d normal = (p[f[1]] - p[f[0]]).cross(p[f[2]] - p[f[0]]);
        if ((-p[f[0]]).dot(normal) * (p[f[3]] - p[f[0]]).dot(normal) < 0) inside = false;
        best = std::min(best, pointTriangle(p[f[0]], p[f[1]], p[f[2]]));
    }
    return inside ? 0 : best;
}

double reference(const Vec3 points[4], int count) {
    Vec3d p[4];
    for (int i = 0; i < count; ++i) p[i] = points[i].cast<double>();
    switch (count) {
        case 1: return p[0].norm();
        case 2: return pointSegment(p[0], p[1]);
        case 3: return pointTriangle(p[0], p[1], p[2]);
        default: return pointTetrahedron(p);
    }
}

}  // namespace

TEST_CASE("closest point of every simplex size matches the reference", "[ch02][simplex]") {
    Random random(11);
    int dropped[5] = {0, 0, 0, 0, 0};
    for (int count = 1; count <= 4; ++count) {
        for (int trial = 0; trial < 3000; ++trial) {
            Vec3 points[4];
            const Vec3 shift = random.unitVector() * Real(random.uniform(0, 1.5));
            for (int i = 0; i < count; ++i)
                points[i] = shift + random.unitVector() * Real(random.uniform(0.05, 1));
            const SimplexClosest closest = closestPointToOrigin(points, count, 2);
            const double expected = reference(points, count);
            INFO("count " << count << " trial " << trial);
            REQUIRE(double(closest.point.norm()) == Approx(expected).margin(2e-6));
            // The weights rebuild the point and form a convex combination of the kept vertices.
            Vec3 rebuilt = Vec3::Zero();
            Real sum = 0;
            for (int i = 0; i < count; ++i) {
                CHECK(closest.weights[i] >= Real(-1e-6));
                rebuilt += closest.weights[i] * points[i];
                sum += closest.weights[i];
            }
            CHECK(sum == Approx(1).margin(1e-5));
            CHECK((rebuilt - closest.point).norm() == Approx(0).margin(2e-5));
            REQUIRE(closest.keptCount >= 1);
            REQUIRE(closest.keptCount <= count);
            if (std::find(closest.kept, closest.kept + closest.keptCount, count - 1) == closest.kept + closest.keptCount)
                ++dropped[count];
        }
    }
    // Random simplices (unlike GJK's) often have the origin nearest an old vertex: every region
    // must be handled, and is.
    CHECK(dropped[2] > 0);
    CHECK(dropped[3] > 0);
    CHECK(dropped[4] > 0);
}

TEST_CASE("degenerate simplices: repeated points, collinear triangles, flat tetrahedra", "[ch02][simplex][degenerate]") {
    const Vec3 a(1, 1, 0), b(1, -1, 0), c(1, 0, 0);
    SECTION("two equal points") {
        const Vec3 points[2] = {a, a};
        const SimplexClosest closest = closestPointToOrigin(points, 2, 2);
        CHECK(closest.degenerate);
        CHECK(closest.point.isApprox(a));
    }
    SECTION("collinear triangle") {
        const Vec3 points[3] = {a, b, c};
        const SimplexClosest closest = closestPointToOrigin(points, 3, 2);
        CHECK(closest.point.allFinite());
        CHECK(closest.point.norm() == Approx(1));
    }
    SECTION("flat tetrahedron around the origin's projection, and through the origin") {
        const Vec3 flat[4] = {Vec3(1, 1, 0), Vec3(1, -1, 1), Vec3(1, -1, -1), Vec3(1, 0, 0)};
        const SimplexClosest off = closestPointToOrigin(flat, 4, 2);
        CHECK(off.degenerate);
        CHECK_FALSE(off.inside);
        CHECK(off.point.norm() == Approx(1));
        const Vec3 through[4] = {Vec3(0, 1, 0), Vec3(0, -1, 1), Vec3(0, -1, -1), Vec3(0, 0, Real(0.1))};
        const SimplexClosest on = closestPointToOrigin(through, 4, 2);
        CHECK(on.point.norm() == Approx(0).margin(1e-6));
    }
    SECTION("all four points equal") {
        const Vec3 same[4] = {a, a, a, a};
        const SimplexClosest closest = closestPointToOrigin(same, 4, 2);
        CHECK(closest.point.allFinite());
        CHECK(closest.point.isApprox(a));
    }
}
