// Fuzz target: chapter 3's narrowphase (GJK, EPA, the closed forms) on random pairs of every
// shape kind, hulls of 4 to 64 hard points included, at random poses and sizes from 3 cm to
// 30 m. Every answer must be finite and hold its invariants (narrowphase.h):
//   - the normal is a unit vector;
//   - intersecting: depth >= 0; separated: depth <= 0 (minus the distance);
//   - pointA - pointB = depth * normal;
//   - pointA lies on A's surface and pointB on B's, within the tolerance below.
// The tolerance is relative to the pair's size (EPA stops at 1e-5 of it; the closed forms are
// exact) plus the round-off that Real positions carry at the pair's distance from the origin.
#include "fuzz_input.h"
#include "random_shapes.h"

#include "03_epa/narrowphase.h"

#include <cmath>
#include <cstddef>
#include <cstdint>

using namespace stepwise;
using namespace stepwise::fuzz;

namespace {

constexpr const char* kTarget = "fuzz_narrowphase";

double distanceToSurface(const Shape& shape, const Transform& pose, const Vec3& worldPoint) {
    const Eigen::Vector3d local = pose.rotation.cast<double>().conjugate() *
                                  (worldPoint.cast<double>() - pose.position.cast<double>());
    return signedDistance(shape, local);
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
    poseA.position = Vec3(Real(input.uniform(-100, 100)), Real(input.uniform(-100, 100)), Real(input.uniform(-100, 100)));
    poseA.rotation = randomRotation(input);
    const Real reach = boundingRadius(*shapeA) + boundingRadius(*shapeB);
    Vec3 direction = randomRotation(input) * Vec3::UnitX();
    poseB.position = poseA.position + direction * Real(input.uniform(0, 1.5)) * reach;
    poseB.rotation = randomRotation(input);

    CollideOptions options;
    options.closedForms = input.flag();
    const ContactQuery query = collideShapes(*shapeA, poseA, *shapeB, poseB, options);

    const bool finite = std::isfinite(query.depth) && query.normal.allFinite() && query.pointA.allFinite() &&
                        query.pointB.allFinite();
    STEPWISE_FUZZ_CHECK(kTarget, finite, query.depth, 0);
    const double pairSize = std::max(double(boundingRadius(*shapeA)), double(boundingRadius(*shapeB)));
    const double farthest = std::max(poseA.position.norm(), poseB.position.norm()) + pairSize;
    const double tolerance = 1e-4 * pairSize + 64 * double(kEpsilon) * farthest;
    STEPWISE_FUZZ_CHECK(kTarget, std::abs(query.normal.norm() - 1) < 1e-4, query.normal.norm(), 1);
    if (query.intersect)
        STEPWISE_FUZZ_CHECK(kTarget, query.depth >= 0, query.depth, 0);
    else
        STEPWISE_FUZZ_CHECK(kTarget, query.depth <= 0, query.depth, 0);
    if (!query.intersect && !options.separationDistance) return 0;
    const double gap = (query.pointA - query.pointB - query.depth * query.normal).norm();
    STEPWISE_FUZZ_CHECK(kTarget, gap <= tolerance, gap, tolerance);
    const double offA = distanceToSurface(*shapeA, poseA, query.pointA);
    const double offB = distanceToSurface(*shapeB, poseB, query.pointB);
    STEPWISE_FUZZ_CHECK(kTarget, std::abs(offA) <= tolerance, offA, tolerance);
    STEPWISE_FUZZ_CHECK(kTarget, std::abs(offB) <= tolerance, offB, tolerance);
    return 0;
}
