#include "07_ccd/time_of_impact.h"

#include "02_gjk/gjk.h"

#include <algorithm>

namespace stepwise {

static ToiResult separatedResult(ToiResult result);

ToiOptions toiOptionsFor(const Settings& settings) {
    ToiOptions options;
    options.target = kToiTargetSlops * settings.slop;
    options.tolerance = kToiToleranceSlops * settings.slop;
    return options;
}

const char* toString(ToiState state) {
    switch (state) {
        case ToiState::Separated: return "separated";
        case ToiState::Hit: return "hit";
        case ToiState::Touching: return "touching";
        case ToiState::Stalled: return "stalled";
    }
    return "?";
}

// [ch07-motion-bound]
Real closingSpeedBound(const Sweep& a, const Shape& shapeA, const Sweep& b, const Shape& shapeB, const Vec3& normal) {
    // Per unit of t: each sweep covers its travel in the fraction of the step it has left.
    const auto rate = [](const Sweep& sweep) { return Real(1) / std::max(Real(1) - sweep.alpha0, kEpsilon); };
    const Vec3 velocityA = (a.center1 - a.center0) * rate(a);
    const Vec3 velocityB = (b.center1 - b.center0) * rate(b);
    // The gap along a fixed direction n is a lower bound of the distance and equals it where n
    // is the closest direction; it shrinks no faster than the centres close along n plus the
    // fastest a point can swing round its centre, |w| r (Zhang et al. 2007, eq. 4).
    const Real linear = std::max(Real(0), (velocityA - velocityB).dot(normal));
    const Real angular = sweepAngle(a) * rate(a) * maxLeverArm(shapeA, a.localCenter) +
                         sweepAngle(b) * rate(b) * maxLeverArm(shapeB, b.localCenter);
    return linear + angular;
}
// [ch07-motion-bound]

// [ch07-conservative-advancement]
ToiResult timeOfImpact(const Shape& shapeA, const Sweep& a, const Shape& shapeB, const Sweep& b,
                       const ToiOptions& options) {
    ToiResult result;
    Real t = std::max(a.alpha0, b.alpha0);
    for (int iteration = 0; iteration < std::max(1, options.maxIterations); ++iteration) {
        const ConvexProxy proxyA{&shapeA, poseAt(a, t)};
        const ConvexProxy proxyB{&shapeB, poseAt(b, t)};
        const GjkDistanceResult gap = gjkDistance(proxyA, proxyB);
        result.iterations = iteration + 1;
        result.time = t;
        result.distance = gap.separated ? gap.distance : 0;
        result.pointA = gap.pointA;
        result.pointB = gap.pointB;
        if (gap.separated && gap.distance > 0) result.normal = (gap.pointB - gap.pointA) / gap.distance;

        // Within reach of the target: an impact now, or a contact the step began with.
        if (!gap.separated || gap.distance <= options.target + options.tolerance) {
            result.state = iteration == 0 ? ToiState::Touching : ToiState::Hit;
            return result;
        }
        // No point closes the gap faster than the bound, so nothing touches before this advance.
        const Real bound = closingSpeedBound(a, shapeA, b, shapeB, result.normal);
        if (bound <= 0) return separatedResult(result);
        t += (gap.distance - options.target) / bound;
        if (t >= 1) return separatedResult(result);
    }
    result.state = ToiState::Stalled;
    return result;
}
// [ch07-conservative-advancement]

ToiResult separatedResult(ToiResult result) {
    result.state = ToiState::Separated;
    result.time = 1;
    return result;
}

}  // namespace stepwise
