// Sweep and prune, piece by piece (sweep_and_prune.h): the bounds, the axis and the sorts (the
// sweep and the pairs' order: sweep_pairs.cpp); broadphase.cpp strings the pieces into the stage.
#include "05_sap/sweep_and_prune.h"

#include "03_epa/chapter.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stepwise {

// [ch05-bounds]
Real pointSpeedBound(const World& world, int bodyIndex) {
    const Motion* motion = world.motionOf(bodyIndex);
    if (!motion) return 0;
    // v is the centre of mass's velocity and the body turns about that centre, so the arm is
    // measured from it: the shape's ball about its origin plus the centre's offset.
    const Shape& shape = world.bodies[static_cast<std::size_t>(bodyIndex)].shape;
    return motion->linearVelocity.norm() + motion->angularVelocity.norm() * maxLeverArm(shape, motion->localCenter);
}

Real boundsGrowth(const World& world, int bodyIndex) {
    // The fastest point's travel over the frame, plus what gravity adds over it.
    const Real dt = world.settings.dt;
    return dt * (pointSpeedBound(world, bodyIndex) + world.settings.gravity.norm() * dt) + kBoundsMargin;
}
// [ch05-bounds]

namespace {

/// A placed shape's world box, and the radius of the smallest ball about the body's origin that
/// holds the shape (boundingRadius), in one pass over the shape: one rotation matrix, each hull
/// vertex turned once.
struct PlacedShape {
    Aabb box;
    Real radius = 0;
};

PlacedShape placeShape(const Shape& shape, const Transform& pose) {
    PlacedShape placed;
    if (shape.type == ShapeType::Sphere) {  // turning changes nothing
        placed.box.min = pose.position - Vec3::Constant(shape.radius);
        placed.box.max = pose.position + Vec3::Constant(shape.radius);
        placed.radius = shape.radius;
        return placed;
    }
    const Mat3 rotation = pose.rotation.toRotationMatrix();
    Vec3 reach = Vec3::Zero();
    switch (shape.type) {
        case ShapeType::Box:
            reach = rotation.cwiseAbs() * shape.halfExtents;
            placed.radius = shape.halfExtents.norm();
            break;
        case ShapeType::Sphere: break;  // above
        case ShapeType::Capsule:
            reach = rotation.col(1).cwiseAbs() * shape.halfHeight + Vec3::Constant(shape.radius);
            placed.radius = shape.halfHeight + shape.radius;
            break;
        case ShapeType::Convex: {
            if (!shape.hull) break;
            // The box of the turned vertices, then moved: rounding keeps the order of sums, so
            // position + the least turned vertex is the least of the moved ones, to the bit.
            Aabb turned;
            for (const Vec3& vertex : shape.hull->vertices) turned.grow(rotation * vertex);
            placed.box.min = pose.position + turned.min;
            placed.box.max = pose.position + turned.max;
            placed.radius = shape.hull->vertexRadius;
            return placed;
        }
        case ShapeType::Cylinder:
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField:  // chapter 13's kinds: the shape's own box
            placed.box = computeAabb(shape, pose);
            placed.radius = boundingRadius(shape);
            return placed;
    }
    placed.box.min = pose.position - reach;
    placed.box.max = pose.position + reach;
    return placed;
}

}  // namespace

// [ch05-bounds-pass]
void computeBroadphaseBounds(const World& world, std::vector<Aabb>& bounds, std::vector<char>& dynamic) {
    bounds.resize(world.bodies.size());
    dynamic.resize(world.bodies.size());
    // boundsGrowth, with the shape's radius from the same pass as its box (maxLeverArm's sum,
    // radius plus the centre of mass's offset, written out).
    const Real dt = world.settings.dt;
    const Real gravityGain = world.settings.gravity.norm() * dt;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        dynamic[i] = body.type == BodyType::Dynamic ? 1 : 0;
        const PlacedShape placed = placeShape(body.shape, body.transform);
        Real speed = 0;  // bound on the speed of the body's points, m/s
        if (body.motionIndex >= 0) {
            const Motion& motion = world.motions[static_cast<std::size_t>(body.motionIndex)];
            const Real leverArm = placed.radius + motion.localCenter.norm();
            speed = motion.linearVelocity.norm() +
                    motion.angularVelocity.norm() * std::max(leverArm, std::numeric_limits<Real>::min());
        }
        const Real grow = dt * (speed + gravityGain) + kBoundsMargin;
        Aabb box = placed.box;
        box.min.array() -= grow;
        box.max.array() += grow;
        // A NaN would break the sort's order; an empty box overlaps nothing and sorts last. x - x
        // is 0 for a finite x and NaN for an infinite or NaN one: one test checks all six.
        const Real notFinite = (box.min - box.min).sum() + (box.max - box.max).sum();
        if (notFinite != 0) box = Aabb{};
        bounds[i] = box;
    }
}
// [ch05-bounds-pass]

// [ch05-axis]
Vec3 centreVariance(const std::vector<Aabb>& bounds) {
    // One pass, in double, over each centre's offset from the first one: offsets from a centre
    // among the bodies keep the sum of squares from cancelling far from the origin.
    double reference[3] = {0, 0, 0}, sum[3] = {0, 0, 0}, sumSquares[3] = {0, 0, 0};
    long count = 0;
    for (const Aabb& box : bounds) {
        if (!(box.min.x() <= box.max.x()) || !(box.min.y() <= box.max.y()) || !(box.min.z() <= box.max.z()))
            continue;  // empty: no place to count
        for (int axis = 0; axis < 3; ++axis) {
            const double centre = 0.5 * (static_cast<double>(box.min[axis]) + static_cast<double>(box.max[axis]));
            if (count == 0) reference[axis] = centre;
            const double offset = centre - reference[axis];
            sum[axis] += offset;
            sumSquares[axis] += offset * offset;
        }
        ++count;
    }
    if (count == 0) return Vec3::Zero();
    const double n = static_cast<double>(count);
    Vec3 variance;
    for (int axis = 0; axis < 3; ++axis) {
        const double mean = sum[axis] / n;
        variance[axis] = static_cast<Real>(std::max(0.0, sumSquares[axis] / n - mean * mean));
    }
    return variance;
}

int chooseSweepAxis(const Vec3& variance, int previousAxis) {
    int widest = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (variance[axis] > variance[widest]) widest = axis;
    if (previousAxis < 0 || previousAxis > 2) return widest;
    return variance[widest] > kAxisSwitchRatio * variance[previousAxis] ? widest : previousAxis;
}

SweepAxes sweepAxes(const Vec3& variance, int sweepAxis) {
    const int next = (sweepAxis + 1) % 3, last = (sweepAxis + 2) % 3;
    return variance[last] > variance[next] ? SweepAxes{sweepAxis, last, next} : SweepAxes{sweepAxis, next, last};
}
// [ch05-axis]

void makeEndpoints(const std::vector<Aabb>& bounds, int axis, std::vector<SweepEndpoint>& endpoints) {
    endpoints.resize(bounds.size());
    for (std::size_t i = 0; i < bounds.size(); ++i) endpoints[i] = SweepEndpoint{bounds[i].min[axis], static_cast<int>(i)};
}

void refreshEndpointValues(const std::vector<Aabb>& bounds, int axis, std::vector<SweepEndpoint>& endpoints) {
    for (SweepEndpoint& end : endpoints) end.value = bounds[static_cast<std::size_t>(end.body)].min[axis];
}

// [ch05-insertion-sort]
long insertionSortEndpoints(std::vector<SweepEndpoint>& endpoints, long moveBudget) {
    long moves = 0;
    for (std::size_t i = 1; i < endpoints.size(); ++i) {
        const SweepEndpoint end = endpoints[i];
        std::size_t j = i;
        // Bodies that moved little since the last step are already in place: one comparison.
        while (j > 0 && endpointBefore(end, endpoints[j - 1])) {
            endpoints[j] = endpoints[j - 1];
            --j;
        }
        endpoints[j] = end;
        moves += static_cast<long>(i - j);
        if (moves > moveBudget) return -1;  // too much moved: a full sort is cheaper from here
    }
    return moves;
}
// [ch05-insertion-sort]

void fullSortEndpoints(std::vector<SweepEndpoint>& endpoints) {
    // A lambda, not the function's address: std::sort then compares inline.
    std::sort(endpoints.begin(), endpoints.end(),
              [](const SweepEndpoint& a, const SweepEndpoint& b) { return endpointBefore(a, b); });
}

}  // namespace stepwise
