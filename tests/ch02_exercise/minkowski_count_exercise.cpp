// Exercise check for chapter 2 (`ctest -L ch02-exercise`), the derive exercise: how many
// vertices and faces does A - B have for two boxes? The page's answer: A - B is the sum of six
// segments (the three edge directions of A and of B), a zonotope. Each pair of directions gives
// one pair of parallel parallelogram faces, so F = 2 * C(6, 2) = 30; each face has 4 edges and
// each edge lies on 2 faces, so E = 60; Euler's formula V - E + F = 2 gives V = 32. So of the
// 64 corner differences, 32 are vertices and 32 lie inside. Boxes with parallel edges share
// directions, and A - B has fewer: two aligned boxes give a box (8 and 6).
// The test builds the hull of the 64 differences with the engine's hull builder and counts.
#include "math/random.h"
#include "world/shape.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

using namespace stepwise;

namespace {

std::vector<Vec3> corners(const Vec3& halfExtents, const Transform& pose) {
    std::vector<Vec3> points;
    for (int i = 0; i < 8; ++i) {
        const Vec3 local((i & 1) ? halfExtents.x() : -halfExtents.x(), (i & 2) ? halfExtents.y() : -halfExtents.y(),
                         (i & 4) ? halfExtents.z() : -halfExtents.z());
        points.push_back(pose.apply(local));
    }
    return points;
}

ConvexHull minkowskiDifference(const Vec3& extentsA, const Transform& poseA, const Vec3& extentsB, const Transform& poseB) {
    std::vector<Vec3> differences;
    for (const Vec3& a : corners(extentsA, poseA))
        for (const Vec3& b : corners(extentsB, poseB)) differences.push_back(a - b);
    return buildConvexHull(differences);
}

// Faces with the same corners are one face: float corners make a long face's points coplanar
// only to about 1e-6 of the size, and the hull builder may then find its plane more than once.
std::size_t distinctFaces(const ConvexHull& hull) {
    std::set<std::vector<int>> faces;
    for (const HullFace& face : hull.faces) {
        std::vector<int> corners = face.vertexIndices;
        std::sort(corners.begin(), corners.end());
        faces.insert(corners);
    }
    return faces.size();
}

// General position: no edge direction of A within about 8 degrees of one of B's. Nearly
// parallel edges give faces a few micrometres wide, which the hull builder's tolerance may
// merge or split; exactly parallel ones give fewer faces (the aligned case below).
bool generalPosition(const Quat& a, const Quat& b) {
    const Mat3 axesA = a.toRotationMatrix(), axesB = b.toRotationMatrix();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(axesA.col(i).dot(axesB.col(j))) > Real(0.99)) return false;
    return true;
}

}  // namespace

TEST_CASE("exercise: A - B of two boxes in general position has 32 vertices and 30 faces", "[ch02-exercise]") {
    Random random(202);
    for (int trial = 0; trial < 200; ++trial) {
        Transform poseA, poseB;
        poseA.rotation = random.rotation();
        poseB.rotation = random.rotation();
        if (!generalPosition(poseA.rotation, poseB.rotation)) continue;
        poseB.position = Vec3(Real(random.uniform(-1, 1)), Real(random.uniform(-1, 1)), Real(random.uniform(-1, 1)));
        const Vec3 extentsA(Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)));
        const Vec3 extentsB(Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)), Real(random.uniform(0.2, 1)));
        const ConvexHull hull = minkowskiDifference(extentsA, poseA, extentsB, poseB);
        INFO("trial " << trial);
        CHECK(hull.vertices.size() == 32);
        CHECK(distinctFaces(hull) == 30);
    }
}

TEST_CASE("exercise: A - B of two aligned boxes is a box", "[ch02-exercise]") {
    Transform poseB;
    poseB.position = Vec3(Real(0.3), Real(-0.2), Real(0.1));
    const ConvexHull hull = minkowskiDifference(Vec3(1, Real(0.5), Real(0.25)), Transform{}, Vec3(Real(0.4), Real(0.4), Real(0.4)), poseB);
    CHECK(hull.vertices.size() == 8);
    CHECK(distinctFaces(hull) == 6);
}
