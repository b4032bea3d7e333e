#include "07_ccd/time_of_impact.h"

#include "02_gjk/gjk.h"
#include "world/enum_names.h"

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
    static const Names<ToiState> names = {
        {"separated", ToiState::Separated}, {"hit", ToiState::Hit}, {"touching", ToiState::Touching}, {"stalled", ToiState::Stalled}};
    return nameOf(names, state);
}

// [ch07-motion-bound]
Real closingSpeedBound(const Sweep& a, const Shape& shapeA, const Sweep& b, const Shape& shapeB, const Vec3& normal) {
    // Per unit of t: each sweep covers its travel in the fraction of the step it has left.
    const auto rate = [](const Sweep& sweep) { return Real(1) / std::max(Real(1) - sweep.alpha0, kEpsilon); };
    const Vec3 velocityA = (a.center1 - a.center0) * rate(a);
    const Vec3 velocityB = (b.center1 - b.center0) * rate(b);
    // The gap along a fixed direction n is a lower bound of the distance and equals it where n
    // is the closest direction; it shrinks no faster than the centres close along n plus the
    // fastest a point can swing round its centre, |w| r (Mirtich 1996).
    const Real linear = std::max(Real(0), (velocityA - velocityB).dot(normal));
    const Real angular = sweepAngle(a) * rate(a) * maxLeverArm(shapeA, a.localCenter) +
                         sweepAngle(b) * rate(b) * maxLeverArm(shapeB, b.localCenter);
    return linear + angular;
}
// [ch07-motion-bound]

// [ch07-conservative-advancement]
/// The gap between the shapes along a unit direction n (A towards B): how far apart two planes
/// with normal n can be with A behind one and B in front of the other. A lower bound of the
/// distance for every n, and equal to it along the closest direction.
static Real separationAlong(const ConvexProxy& a, const ConvexProxy& b, const Vec3& direction) {
    return direction.dot(b.support(-direction)) - direction.dot(a.support(direction));
}

/// The larger gap along `normal` or along the centres' direction; `normal` becomes the one used
/// (the bound on the closing speed must be taken along the direction whose gap is trusted).
static Real guaranteedGap(const ConvexProxy& a, const ConvexProxy& b, Vec3& normal) {
    Real best = separationAlong(a, b, normal);
    const Vec3 centres = b.center() - a.center();
    if (centres.norm() > 0) {
        const Vec3 across = centres.normalized();
        const Real acrossGap = separationAlong(a, b, across);
        if (acrossGap > best) best = acrossGap, normal = across;
    }
    return best;
}

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
        result.pointA = gap.pointA;
        result.pointB = gap.pointB;
        // A GJK that stopped early (a degenerate simplex, the iteration cap, or no progress at
        // the rounding floor) can report more than the true distance, and an advance by it can
        // jump past the impact (tests/ch07/toi_oracle_test.cpp keeps such a sweep: 11 mm read
        // where 0.6 mm is left). Then the advance trusts a separating plane's gap instead, a lower
        // bound of the distance for any direction: GJK's, or the centres' when that one is poor.
        Real distance = gap.separated ? gap.distance : 0;
        if (gap.separated && gap.distance > 0) {
            result.normal = (gap.pointB - gap.pointA).normalized();
            if (gap.exit == GjkExit::Degenerate || gap.exit == GjkExit::IterationCap || gap.exit == GjkExit::NoProgress)
                distance = std::min(distance, guaranteedGap(proxyA, proxyB, result.normal));
        }
        result.distance = std::max(Real(0), distance);

        // Within reach of the target: an impact now, or a contact the step began with.
        if (!gap.separated || distance <= options.target + options.tolerance) {
            result.state = iteration == 0 ? ToiState::Touching : ToiState::Hit;
            return result;
        }
        // No point closes the gap faster than the bound, so nothing touches before this advance.
        const Real bound = closingSpeedBound(a, shapeA, b, shapeB, result.normal);
        if (bound <= 0) return separatedResult(result);
        t += (distance - options.target) / bound;
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
