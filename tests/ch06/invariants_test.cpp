// Chapter 6's manifolds on random pairs of every shape kind, at random poses, sizes from 5 cm to
// 20 m and distances from the origin up to 1 km: whatever the pair, the answer holds its
// invariants. At most four points, all finite; a unit normal; each point's depth is its points'
// distance along the normal; and for boxes and hulls, whose points are corners and their
// projections, every point lies on its body's surface.
#include "06_manifolds/manifold.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

using namespace stepwise;

namespace {

/// Distance of a world point from a box's or hull's surface, outward positive (for a point near a
/// face: exact; the largest plane distance, which is what a point on the surface makes zero).
double planeDistance(const Shape& shape, const Transform& pose, const Vec3& worldPoint) {
    const Eigen::Vector3d local = pose.rotation.cast<double>().normalized().conjugate() *
                                  (worldPoint.cast<double>() - pose.position.cast<double>());
    if (shape.type == ShapeType::Box) {
        const Eigen::Vector3d outside = local.cwiseAbs() - shape.halfExtents.cast<double>();
        return outside.maxCoeff();
    }
    double largest = -1e300;
    for (const HullFace& face : shape.hull->faces)
        largest = std::max(largest, face.normal.cast<double>().dot(local) - double(face.offset));
    return largest;
}

struct RandomPair {
    Shape a, b;
    Transform ta, tb;
    double size = 1;
};

Shape randomShape(std::mt19937& random, double size) {
    std::uniform_real_distribution<double> unit(0.2, 1.0);
    switch (random() % 4) {
        case 0: return Shape::box(Vec3(Real(size * unit(random)), Real(size * unit(random)), Real(size * unit(random))));
        case 1: return Shape::sphere(Real(size * unit(random)));
        case 2: return Shape::capsule(Real(size * 0.5 * unit(random)), Real(size * unit(random)));
        default: {
            std::normal_distribution<double> normal;
            std::vector<Vec3> points;
            const int count = 4 + static_cast<int>(random() % 20);
            for (int i = 0; i < count; ++i)
                points.emplace_back(Real(size * normal(random)), Real(size * normal(random)), Real(size * normal(random)));
            try {
                return Shape::convex(points);
            } catch (const HullError&) {
                return Shape::box(Vec3::Constant(Real(size)));
            }
        }
    }
}

Quat randomRotation(std::mt19937& random) {
    std::normal_distribution<double> normal;
    Quat q(Real(normal(random)), Real(normal(random)), Real(normal(random)), Real(normal(random)));
    return q.normalized();
}

RandomPair randomPair(std::mt19937& random) {
    RandomPair pair;
    std::uniform_real_distribution<double> logSize(std::log(0.05), std::log(20.0));
    pair.size = std::exp(logSize(random));
    pair.a = randomShape(random, pair.size);
    pair.b = randomShape(random, pair.size * std::exp(0.5 * logSize(random) / std::log(20.0)));
    std::uniform_real_distribution<double> unit(-1, 1);
    const double far = (random() % 4 == 0) ? 1000.0 : 0.0;
    const Vec3 origin(Real(far * unit(random)), Real(far * unit(random)), Real(far * unit(random)));
    pair.ta = Transform{origin, randomRotation(random)};
    // B within reach of A: from overlapping deeply to just apart.
    const Vec3 offset(Real(unit(random)), Real(unit(random)), Real(unit(random)));
    pair.tb = Transform{origin + offset * Real(pair.size * 1.5), randomRotation(random)};
    return pair;
}

bool isPolytopeShape(const Shape& shape) { return shape.type == ShapeType::Box || shape.type == ShapeType::Convex; }

}  // namespace

TEST_CASE("random pairs: every manifold holds its invariants", "[ch06][manifold][invariants]") {
    std::mt19937 random(2606);
    int contacts = 0, polytopePairs = 0, points = 0, multiPointPolytopes = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const RandomPair pair = randomPair(random);
        // Positions far out carry round-off of their own magnitude: an ulp of 1 km is 6e-5 m in float.
        const double reach = pair.ta.position.cast<double>().norm() + pair.size;
        const double tolerance = 2e-4 * pair.size + 64 * double(std::numeric_limits<Real>::epsilon()) * reach;
        const Real keep = Real(0.02 * pair.size);
        Contact contact;
        const bool found = collideManifold(pair.a, pair.ta, pair.b, pair.tb, keep, contact);
        std::ostringstream description;
        description << "trial " << trial << ": " << toString(pair.a.type) << " / " << toString(pair.b.type) << ", size "
                    << pair.size << ", " << contact.pointCount << " points";
        INFO(description.str());
        REQUIRE(contact.pointCount >= 0);
        REQUIRE(contact.pointCount <= 4);
        REQUIRE(found == (contact.pointCount > 0));
        if (!found) continue;
        ++contacts;
        points += contact.pointCount;
        REQUIRE(isFinite(contact.normal));
        REQUIRE(std::abs(contact.normal.norm() - 1) < 1e-4);
        const bool polytopes = isPolytopeShape(pair.a) && isPolytopeShape(pair.b);
        polytopePairs += polytopes ? 1 : 0;
        multiPointPolytopes += polytopes && contact.pointCount > 1 ? 1 : 0;
        for (int i = 0; i < contact.pointCount; ++i) {
            const ContactPoint& point = contact.points[i];
            INFO("point " << i << " depth " << point.depth);
            REQUIRE(isFinite(point.pointA));
            REQUIRE(isFinite(point.pointB));
            REQUIRE(isFinite(point.localAnchorA));
            REQUIRE(isFinite(point.depth));
            // Clipped and edge-edge points always know their features (a speculative single point of
            // round shapes may not: GJK's distance names none).
            if (polytopes) REQUIRE(point.featureId != 0);
            REQUIRE(-point.depth <= keep + tolerance);
            REQUIRE(std::abs(contact.normal.dot(point.pointA - point.pointB) - point.depth) < tolerance);
            // The anchors give the points back.
            REQUIRE((pair.ta.apply(point.localAnchorA) - point.pointA).norm() < tolerance);
            if (polytopes) {
                REQUIRE(std::abs(planeDistance(pair.a, pair.ta, point.pointA)) < tolerance);
                REQUIRE(std::abs(planeDistance(pair.b, pair.tb, point.pointB)) < tolerance);
            }
        }
    }
    INFO(contacts << " contacts, " << polytopePairs << " between polytopes (" << multiPointPolytopes
                  << " with several points), " << points << " points");
    CHECK(contacts > 1000);
    CHECK(polytopePairs > 300);
    CHECK(multiPointPolytopes > polytopePairs / 4);
}
