#include "07_ccd/separation_root.h"

#include "02_gjk/gjk.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace stepwise {

namespace {

/// The gap along the fixed world direction n (A towards B) with both bodies at time t.
Real separationAt(const Shape& shapeA, const Sweep& a, const Shape& shapeB, const Sweep& b, const Vec3& normal, Real t) {
    const ConvexProxy proxyA{&shapeA, poseAt(a, t)};
    const ConvexProxy proxyB{&shapeB, poseAt(b, t)};
    return normal.dot(proxyB.support(-normal)) - normal.dot(proxyA.support(normal));
}

/// Box2D's face separation functions in small: when the closest direction is within a hundredth
/// of a radian of a face normal of either polytope, the face's own normal is the axis. On a large
/// face a direction off by a little finds a far corner and understates the gap by the face's
/// size times the error, and the roots then creep towards the impact instead of reaching it.
Vec3 faceAxis(const Shape& shape, const Transform& pose, const Vec3& direction) {
    std::vector<Vec3> normals;
    if (shape.type == ShapeType::Box)
        for (int axis = 0; axis < 3; ++axis) normals.push_back(pose.rotation * Vec3::Unit(axis));
    else if (shape.type == ShapeType::Convex)
        for (const HullFace& face : shape.hull->faces) normals.push_back(pose.rotation * face.normal);
    Vec3 best = direction;
    Real bestCosine = Real(0.99995);
    for (const Vec3& normal : normals) {
        const Real cosine = std::abs(normal.dot(direction));
        if (cosine > bestCosine) bestCosine = cosine, best = normal.dot(direction) > 0 ? normal : Vec3(-normal);
    }
    return best;
}

}  // namespace

// [ch07-separation-root]
ToiResult timeOfImpactByRoots(const Shape& shapeA, const Sweep& a, const Shape& shapeB, const Sweep& b,
                              const ToiOptions& options) {
    ToiResult result;
    Real t1 = std::max(a.alpha0, b.alpha0);
    for (int axis = 0; axis < options.maxIterations; ++axis) {
        // The closest features at t1, and their direction: the separating axis.
        const ConvexProxy proxyA{&shapeA, poseAt(a, t1)};
        const ConvexProxy proxyB{&shapeB, poseAt(b, t1)};
        const GjkDistanceResult gap = gjkDistance(proxyA, proxyB);
        ++result.iterations;
        result.time = t1;
        result.pointA = gap.pointA;
        result.pointB = gap.pointB;
        result.distance = gap.separated ? gap.distance : 0;
        if (!gap.separated || gap.distance <= options.target + options.tolerance) {
            result.state = axis == 0 ? ToiState::Touching : ToiState::Hit;
            return result;
        }
        const Vec3 closest = (gap.pointB - gap.pointA).normalized();
        const Vec3 normal = faceAxis(shapeB, proxyB.transform, faceAxis(shapeA, proxyA.transform, closest));
        result.normal = normal;
        // Where the axis says the pair ends the step: apart, then no impact on it.
        const auto separation = [&](Real t) { return separationAt(shapeA, a, shapeB, b, normal, t); };
        Real t2 = 1;
        const Real s2 = separation(t2);
        ++result.iterations;
        if (s2 > options.target + options.tolerance) {
            result.state = ToiState::Separated;
            result.time = 1;
            return result;
        }
        if (s2 > options.target - options.tolerance) {  // within the band at the end of the step
            t1 = t2;
            continue;
        }
        // Between t1 (apart along the axis) and t2 (within the target) the separation crosses the
        // target: bisection and false position, alternating, as b2TimeOfImpact does. The bracket's
        // low end always has the pair apart along the axis, so it is a safe place to go on from.
        Real low = t1, high = t2;
        Real sLow = separation(low), sHigh = s2;
        ++result.iterations;
        Real next = low;  // where the next axis is looked for
        for (int step = 0; step < kRootMaxIterations; ++step) {
            const Real t = (step & 1) ? Real(0.5) * (low + high)
                                      : low + (sLow - options.target) * (high - low) / (sLow - sHigh);
            const Real s = separation(t);
            ++result.iterations;
            if (s > options.target) low = t, sLow = s;
            else high = t, sHigh = s;
            // Converged: within an eighth of the tolerance of the target, still apart.
            if (std::abs(s - options.target) < Real(0.125) * options.tolerance) {
                next = t;
                break;
            }
            next = low;
        }
        t1 = next;
    }
    result.state = ToiState::Stalled;
    return result;
}
// [ch07-separation-root]

}  // namespace stepwise
