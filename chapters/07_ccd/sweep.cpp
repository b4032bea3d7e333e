#include "07_ccd/sweep.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

Sweep stillSweep(const Transform& pose, const Vec3& localCenter) { return sweepBetween(pose, pose, localCenter); }

Sweep sweepBetween(const Transform& start, const Transform& end, const Vec3& localCenter, Real alpha0) {
    Sweep sweep;
    sweep.localCenter = localCenter;
    sweep.center0 = start.apply(localCenter);
    sweep.center1 = end.apply(localCenter);
    sweep.rotation0 = start.rotation;
    sweep.rotation1 = end.rotation;
    sweep.alpha0 = alpha0;
    return sweep;
}

Transform poseAt(const Sweep& sweep, Real t) {
    const Real span = Real(1) - sweep.alpha0;
    const Real u = span > 0 ? std::clamp((t - sweep.alpha0) / span, Real(0), Real(1)) : Real(1);
    Transform pose;
    pose.rotation = slerp(sweep.rotation0, u, sweep.rotation1).normalized();
    const Vec3 center = sweep.center0 + u * (sweep.center1 - sweep.center0);
    pose.position = center - pose.rotation * sweep.localCenter;
    return pose;
}

Real sweepAngle(const Sweep& sweep) {
    const Real cosine = std::min(Real(1), std::abs(sweep.rotation0.dot(sweep.rotation1)));
    return Real(2) * math::acos(cosine);
}

Real sweepTravel(const Sweep& sweep, const Shape& shape) {
    return (sweep.center1 - sweep.center0).norm() + sweepAngle(sweep) * maxLeverArm(shape, sweep.localCenter);
}

Aabb sweptBounds(const Sweep& sweep, const Shape& shape) {
    Aabb bounds = computeAabb(shape, poseAt(sweep, sweep.alpha0));
    bounds.grow(computeAabb(shape, poseAt(sweep, 1)));
    const Real bulge = sweepAngle(sweep) * maxLeverArm(shape, sweep.localCenter);
    bounds.min.array() -= bulge;
    bounds.max.array() += bulge;
    return bounds;
}

}  // namespace stepwise
