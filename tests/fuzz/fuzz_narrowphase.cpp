// Fuzz target: chapter 3's narrowphase (GJK, EPA, the closed forms) on random pairs of every
// shape kind, hulls of 4 to 64 hard points included, at random poses and sizes from 3 cm to
// 30 m. Every answer must be finite and hold its invariants (narrowphase.h):
//   - the normal is a unit vector;
//   - intersecting: depth >= 0; separated: depth <= 0 (minus the distance);
//   - pointA - pointB = depth * normal;
//   - pointA lies on A's surface and pointB on B's, within the tolerance below.
// The tolerance is relative to the pair's size plus the round-off that Real positions carry at
// the pair's distance from the origin: 1e-4 of the size (EPA stops at 1e-5 of it; closed forms
// are exact). Where GJK and EPA meet a sphere or a capsule the points are not held to a surface
// tolerance, only recorded: EPA sees a curved surface only through the support points it has
// asked for, a polytope of at most 50 expansions, and its points lie on a face of that polytope,
// inside the curved surface by the face's sag. On deep overlaps with nearly one centre, where
// every direction is as deep as the next, that reached 11% of the size in the first campaign
// (docs/reliability.md). The engine answers sphere and capsule pairs with closed forms;
// hull-sphere and hull-capsule pairs go through EPA and carry this error. At exit the target
// prints the largest error it saw of each kind, relative to the pair's size.
#include "fuzz_input.h"
#include "random_shapes.h"

#include "03_epa/narrowphase.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <algorithm>

using namespace stepwise;
using namespace stepwise::fuzz;

namespace {

constexpr const char* kTarget = "fuzz_narrowphase";

double distanceToSurface(const Shape& shape, const Transform& pose, const Vec3& worldPoint) {
    const Eigen::Vector3d local = pose.rotation.cast<double>().conjugate() *
                                  (worldPoint.cast<double>() - pose.position.cast<double>());
    return signedDistance(shape, local);
}

/// The largest error seen, relative to the pair's size, printed when the fuzzer exits.
struct WorstErrors {
    double flat = 0, curved = 0, alongPlane = 0;
    long flatPairs = 0, curvedPairs = 0;
    void recordAlongPlane(double relative) { alongPlane = std::max(alongPlane, relative); }
    void record(bool isCurved, double relative) {
        (isCurved ? curved : flat) = std::max(isCurved ? curved : flat, relative);
        ++(isCurved ? curvedPairs : flatPairs);
    }
    ~WorstErrors() {
        std::fprintf(stderr, "%s: largest point error / size: %.3g over %ld flat or closed-form pairs, %.3g over %ld curved GJK+EPA pairs; "
                             "EPA's points apart along the contact plane: %.3g\n",
                     kTarget, flat, flatPairs, curved, curvedPairs, alongPlane);
    }
};
WorstErrors worst;

void describeShape(const char* label, const Shape& shape, const Transform& pose) {
    std::fprintf(stderr, "%s: %s half (%.9g %.9g %.9g) radius %.9g half_height %.9g at (%.9g %.9g %.9g) q (%.9g %.9g %.9g %.9g)\n",
                 label, toString(shape.type), double(shape.halfExtents.x()), double(shape.halfExtents.y()),
                 double(shape.halfExtents.z()), double(shape.radius), double(shape.halfHeight), double(pose.position.x()),
                 double(pose.position.y()), double(pose.position.z()), double(pose.rotation.x()), double(pose.rotation.y()),
                 double(pose.rotation.z()), double(pose.rotation.w()));
    if (shape.hull)
        for (const Vec3& vertex : shape.hull->vertices)
            std::fprintf(stderr, "  vertex %.9g %.9g %.9g\n", double(vertex.x()), double(vertex.y()), double(vertex.z()));
}

/// STEPWISE_FUZZ_VERBOSE=1: the pair and the answer, to turn a failing input into a test.
void describe(const Shape& a, const Transform& poseA, const Shape& b, const Transform& poseB, const ContactQuery& query) {
    describeShape("A", a, poseA);
    describeShape("B", b, poseB);
    std::fprintf(stderr, "%s: intersect %d depth %.9g normal (%.9g %.9g %.9g) pointA (%.9g %.9g %.9g) pointB (%.9g %.9g %.9g)\n",
                 query.routine, int(query.intersect), double(query.depth), double(query.normal.x()),
                 double(query.normal.y()), double(query.normal.z()), double(query.pointA.x()), double(query.pointA.y()),
                 double(query.pointA.z()), double(query.pointB.x()), double(query.pointB.y()), double(query.pointB.z()));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzInput input(data, size);
    const double sizeA = input.logUniform(0.03, 30);
    const double sizeB = input.logUniform(0.03, 30);
    const std::optional<Shape> shapeA = randomShape(input, sizeA);
    const std::optional<Shape> shapeB = randomShape(input, sizeB);
    if (!shapeA || !shapeB) return 0;

    // A somewhere within 100 m of the origin; B at a distance that makes overlap and separation
    // both common: up to 1.5 times the sum of the bounding radii, in a random direction.
    Transform poseA, poseB;
    poseA.position = input.vector(-100, 100).cast<Real>();
    poseA.rotation = randomRotation(input);
    const Real reach = boundingRadius(*shapeA) + boundingRadius(*shapeB);
    Vec3 direction = randomRotation(input) * Vec3::UnitX();
    poseB.position = poseA.position + direction * Real(input.uniform(0, 1.5)) * reach;
    poseB.rotation = randomRotation(input);

    CollideOptions options;
    options.closedForms = input.flag();
    const ContactQuery query = collideShapes(*shapeA, poseA, *shapeB, poseB, options);

    if (std::getenv("STEPWISE_FUZZ_VERBOSE")) {
        describe(*shapeA, poseA, *shapeB, poseB, query);
        const GjkResult gjk = gjkIntersect(ConvexProxy{&*shapeA, poseA, options.supportMode},
                                           ConvexProxy{&*shapeB, poseB, options.supportMode});
        std::fprintf(stderr, "gjkIntersect: %s after %d iterations, exit %s, simplex of %d\n",
                     gjk.intersect ? "intersect" : "separated", gjk.iterations, toString(gjk.exit), gjk.simplex.count);
        if (gjk.intersect) {
            const EpaResult epa = epaPenetration(ConvexProxy{&*shapeA, poseA, options.supportMode},
                                                 ConvexProxy{&*shapeB, poseB, options.supportMode}, gjk.simplex, options.epa);
            std::fprintf(stderr, "epaPenetration: %d iterations, exit %s, weights %.6g %.6g %.6g\n", epa.iterations,
                         toString(epa.exit), double(epa.barycentric.x()), double(epa.barycentric.y()),
                         double(epa.barycentric.z()));
        }
        std::fprintf(stderr, "B's origin is %.9g from A's surface, A's origin %.9g from B's\n",
                     distanceToSurface(*shapeA, poseA, poseB.position), distanceToSurface(*shapeB, poseB, poseA.position));
    }
    const bool finite = std::isfinite(query.depth) && query.normal.allFinite() && query.pointA.allFinite() &&
                        query.pointB.allFinite();
    STEPWISE_FUZZ_CHECK(kTarget, finite, query.depth, 0);
    const double pairSize = std::max(double(boundingRadius(*shapeA)), double(boundingRadius(*shapeB)));
    const double farthest = std::max(poseA.position.norm(), poseB.position.norm()) + pairSize;
    const bool curved = query.routine == std::string("gjk_epa") &&
                        (shapeA->type == ShapeType::Sphere || shapeA->type == ShapeType::Capsule ||
                         shapeA->type == ShapeType::Cylinder || shapeB->type == ShapeType::Sphere ||
                         shapeB->type == ShapeType::Capsule || shapeB->type == ShapeType::Cylinder);
    const double tolerance = 1e-4 * pairSize + 64 * double(kEpsilon) * farthest;
    STEPWISE_FUZZ_CHECK(kTarget, std::abs(query.normal.norm() - 1) < 1e-4, query.normal.norm(), 1);
    if (query.intersect)
        STEPWISE_FUZZ_CHECK(kTarget, query.depth >= 0, query.depth, 0);
    else
        STEPWISE_FUZZ_CHECK(kTarget, query.depth <= 0, query.depth, 0);
    if (!query.intersect && !options.separationDistance) return 0;
    // Through EPA the identity is held along the normal; along the contact plane it is recorded.
    // EPA's fallback for a touching pair returns each shape's own extreme point, apart along the
    // plane where the touching features are wide (epa_fallback.cpp, fallbackContact), and an EPA that
    // stops without progress on a sliver face clamps the origin's projection into that face, so
    // its two points can disagree along the plane (0.6% of the size in the first campaign).
    const Vec3 apart = query.pointA - query.pointB - query.depth * query.normal;
    const bool throughEpa = query.intersect && query.routine == std::string("gjk_epa");
    const double gap = throughEpa ? std::abs(double(apart.dot(query.normal))) : double(apart.norm());
    STEPWISE_FUZZ_CHECK(kTarget, gap <= tolerance, gap, tolerance);
    if (throughEpa) worst.recordAlongPlane(double(apart.norm()) / pairSize);
    const double offA = distanceToSurface(*shapeA, poseA, query.pointA);
    const double offB = distanceToSurface(*shapeB, poseB, query.pointB);
    worst.record(curved, std::max(std::abs(offA), std::abs(offB)) / pairSize);
    if (curved) return 0;
    STEPWISE_FUZZ_CHECK(kTarget, std::abs(offA) <= tolerance, offA, tolerance);
    STEPWISE_FUZZ_CHECK(kTarget, std::abs(offB) <= tolerance, offB, tolerance);
    return 0;
}
