#include "07_ccd/closed_form_toi.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

// [ch07-sphere-plane]
std::optional<Real> spherePlaneTimeOfImpact(const Vec3& center0, const Vec3& travel, Real radius,
                                            const Vec3& planeNormal, Real planeOffset, Real target) {
    // The surface's gap to the plane is linear in t: gap(t) = gap0 + t dot(n, travel).
    const Real gap0 = planeNormal.dot(center0) - planeOffset - radius;
    if (gap0 <= target) return Real(0);
    const Real approach = -planeNormal.dot(travel);
    if (approach <= 0) return std::nullopt;
    const Real t = (gap0 - target) / approach;
    if (t > 1) return std::nullopt;
    return t;
}
// [ch07-sphere-plane]

// [ch07-sphere-sphere]
std::optional<Real> sphereSphereTimeOfImpact(const Vec3& centerA, const Vec3& travelA, Real radiusA,
                                             const Vec3& centerB, const Vec3& travelB, Real radiusB, Real target) {
    // |offset + t relative| = reach is a quadratic in t: a t^2 + 2 b t + c = 0.
    const Vec3 offset = centerB - centerA;
    const Vec3 relative = travelB - travelA;
    const Real reach = radiusA + radiusB + target;
    const Real c = offset.squaredNorm() - reach * reach;
    if (c <= 0) return Real(0);
    const Real b = offset.dot(relative);
    if (b >= 0) return std::nullopt;  // not closing
    const Real a = relative.squaredNorm();
    const Real discriminant = b * b - a * c;
    if (discriminant < 0) return std::nullopt;  // they pass each other
    // The smaller root, written as c / (-b + sqrt(...)) so it keeps its digits when a t^2 is tiny.
    const Real t = c / (-b + std::sqrt(discriminant));
    if (t > 1) return std::nullopt;
    return t;
}
// [ch07-sphere-sphere]

ToiResult sphereSweepsTimeOfImpact(Real radiusA, const Sweep& a, Real radiusB, const Sweep& b, const ToiOptions& options) {
    const Real start = std::max(a.alpha0, b.alpha0);
    const Vec3 centerA = poseAt(a, start).apply(a.localCenter);
    const Vec3 centerB = poseAt(b, start).apply(b.localCenter);
    const std::optional<Real> u =
        sphereSphereTimeOfImpact(centerA, a.center1 - centerA, radiusA, centerB, b.center1 - centerB, radiusB, options.target);
    ToiResult result;
    result.iterations = 0;
    if (!u) return result;  // Separated, time 1
    result.time = start + *u * (Real(1) - start);
    result.state = *u == 0 ? ToiState::Touching : ToiState::Hit;
    const Vec3 atA = poseAt(a, result.time).apply(a.localCenter);
    const Vec3 atB = poseAt(b, result.time).apply(b.localCenter);
    const Real centres = (atB - atA).norm();
    result.normal = centres > 0 ? Vec3((atB - atA) / centres) : Vec3::UnitY();
    result.pointA = atA + radiusA * result.normal;
    result.pointB = atB - radiusB * result.normal;
    result.distance = std::max(Real(0), centres - radiusA - radiusB);
    return result;
}

}  // namespace stepwise
