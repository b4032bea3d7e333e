// Chapter 6's reduction of a contact patch to at most four points (reduceManifold) and the
// clipped polygon's clean-up (removeRedundantVertices): the deepest point first, most of the
// patch's area kept, a corner rather than a point part way along an edge, both ends of a line
// that touches before any speculative corner, and no repeated or collinear vertex.
#include "06_manifolds/clipping.h"
#include "06_manifolds/manifold.h"
#include "06_manifolds/reduction.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace stepwise;

TEST_CASE("the reduction keeps the deepest point and at most four", "[ch06][manifold][reduction]") {
    std::mt19937 random(4);
    std::uniform_real_distribution<Real> unit(-1, 1);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<ManifoldPoint> points(static_cast<std::size_t>(3 + trial % 12));
        for (ManifoldPoint& point : points) {
            point.pointA = Vec3(unit(random), 0, unit(random));
            point.depth = Real(0.01) * unit(random);
        }
        int chosen[kMaxManifoldPoints] = {-1, -1, -1, -1};
        const int count = reduceManifold(points, Vec3::UnitY(), chosen);
        REQUIRE(count >= 1);
        REQUIRE(count <= 4);
        Real deepest = -1;
        for (const ManifoldPoint& point : points) deepest = std::max(deepest, point.depth);
        REQUIRE(points[static_cast<std::size_t>(chosen[0])].depth >= deepest - Real(1e-4));
        for (int i = 0; i < count; ++i)
            for (int k = i + 1; k < count; ++k) REQUIRE(chosen[i] != chosen[k]);
    }
    SECTION("a regular octagon keeps a quadrilateral of most of its area") {
        std::vector<ManifoldPoint> octagon(8);
        for (int k = 0; k < 8; ++k) {
            const Real angle = static_cast<Real>(k) * Real(3.14159265358979323846 / 4.0);
            octagon[static_cast<std::size_t>(k)].pointA = Vec3(std::cos(angle), 0, std::sin(angle));
        }
        octagon[5].depth = Real(0.001);
        int chosen[kMaxManifoldPoints];
        REQUIRE(reduceManifold(octagon, Vec3::UnitY(), chosen) == 4);
        REQUIRE(chosen[0] == 5);
        // Area of the chosen quadrilateral (its points in angular order), against the octagon's 2 sqrt 2.
        std::vector<Real> angles;
        for (int i = 0; i < 4; ++i) angles.push_back(std::atan2(octagon[static_cast<std::size_t>(chosen[i])].pointA.z(),
                                                                octagon[static_cast<std::size_t>(chosen[i])].pointA.x()));
        std::sort(angles.begin(), angles.end());
        Real area = 0;
        for (int i = 0; i < 4; ++i) area += Real(0.5) * std::sin(angles[static_cast<std::size_t>((i + 1) % 4)] - angles[static_cast<std::size_t>(i)] +
                                                               (i == 3 ? 2 * Real(3.14159265358979323846) : 0));
        CHECK(area > Real(0.65) * 2 * std::sqrt(Real(2)));
    }
    SECTION("points all in one place are one point; on a line, two") {
        std::vector<ManifoldPoint> same(5);
        int chosen[kMaxManifoldPoints];
        CHECK(reduceManifold(same, Vec3::UnitY(), chosen) == 1);
        std::vector<ManifoldPoint> line(5);
        for (int k = 0; k < 5; ++k) line[static_cast<std::size_t>(k)].pointA = Vec3(static_cast<Real>(k), 0, 0);
        CHECK(reduceManifold(line, Vec3::UnitY(), chosen) == 2);
    }
}

TEST_CASE("equally deep points: the reduction starts from a corner of the patch, not from the first point",
          "[ch06][manifold][reduction]") {
    // A unit square's patch as two coincident faces clip it: a point part way along an edge comes
    // first, the corners after it, all equally deep.
    std::vector<ManifoldPoint> patch(5);
    const Vec3 positions[5] = {Vec3(Real(0.5), 0, Real(0.26)), Vec3(Real(0.5), 0, Real(0.5)), Vec3(Real(-0.5), 0, Real(0.5)),
                               Vec3(Real(-0.5), 0, Real(-0.5)), Vec3(Real(0.5), 0, Real(-0.5))};
    for (int k = 0; k < 5; ++k) {
        patch[static_cast<std::size_t>(k)].pointA = positions[k];
        patch[static_cast<std::size_t>(k)].depth = Real(1e-4) + Real(1e-9) * static_cast<Real>(k % 2);
    }
    int chosen[kMaxManifoldPoints];
    REQUIRE(reduceManifold(patch, Vec3::UnitY(), chosen) == 4);
    for (int i = 0; i < 4; ++i) CHECK(chosen[i] != 0);
}

TEST_CASE("clipping drops the vertices that add nothing: repeats and points on an edge", "[ch06][manifold]") {
    std::vector<ClipVertex> polygon;
    for (const Vec3& position : {Vec3(0, 0, 0), Vec3(Real(0.4), 0, Real(1e-9)), Vec3(1, 0, 0), Vec3(1, 0, Real(1e-9)),
                                 Vec3(1, 0, 1), Vec3(0, 0, 1), Vec3(Real(0.3), 0, Real(0.5))}) {
        ClipVertex vertex;
        vertex.position = position;
        polygon.push_back(vertex);
    }
    removeRedundantVertices(polygon, Real(1e-5));
    // The square's four corners, and the dent at (0.3, 0, 0.5) kept: it is no repeat and not on a line.
    // Of the corner's two copies either may stay.
    REQUIRE(polygon.size() == 5);
    const Vec3 expected[5] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(0, 0, 1), Vec3(Real(0.3), 0, Real(0.5))};
    for (int k = 0; k < 5; ++k) CHECK((polygon[static_cast<std::size_t>(k)].position - expected[k]).norm() < 1e-8);
}

TEST_CASE("a patch touching along a line keeps both ends before any speculative point", "[ch06][manifold][reduction]") {
    // A hull tilted half a degree on another: the patch touches along one edge (its two ends 5 mm
    // and 4.9 mm deep) and its far corners hang up to 7 mm above the reference face. Both touching
    // ends hold the body; a speculative corner chosen instead of one of them (it lies farther away)
    // leaves the body on one touching point and a gap, and it rocks (the angular pile of chapter
    // 10's scenes never fell asleep so).
    std::vector<ManifoldPoint> patch(6);
    const Vec3 positions[6] = {Vec3(Real(-0.5), 0, Real(-0.33)), Vec3(Real(-0.5), 0, Real(0.13)),
                               Vec3(Real(-0.47), 0, Real(-0.47)), Vec3(Real(0.45), 0, Real(0.46)),
                               Vec3(Real(0.46), 0, Real(-0.45)), Vec3(Real(-0.46), 0, Real(0.46))};
    const Real depths[6] = {Real(0.005), Real(0.0049), Real(-0.0005), Real(-0.007), Real(-0.005), Real(-0.002)};
    for (int k = 0; k < 6; ++k) {
        patch[static_cast<std::size_t>(k)].pointA = positions[k];
        patch[static_cast<std::size_t>(k)].depth = depths[k];
    }
    int chosen[kMaxManifoldPoints] = {-1, -1, -1, -1};
    const int count = reduceManifold(patch, Vec3::UnitY(), chosen);
    REQUIRE(count == 4);
    CHECK(chosen[0] == 0);
    CHECK(chosen[1] == 1);  // the other touching end, though the speculative corners lie farther
    // The last two spread the patch for the speculative rows: the largest triangle, then the most area.
    CHECK(std::find(chosen, chosen + 4, 3) != chosen + 4);
}
