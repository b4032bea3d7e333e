#pragma once
// The closest points of two segments (Ericson, Real-Time Collision Detection, 5.1.9), in any
// precision: the engine runs it in Real for capsules (chapter 3), the exact box oracle of this
// chapter in double to check GJK's distances.

#include <Eigen/Core>

#include <algorithm>
#include <limits>

namespace stepwise {

/// Closest points of segments p1-q1 and p2-q2. A segment may be a point (p = q). Parallel
/// segments are equally close all along their overlap; the middle of it is returned, so one
/// contact point sits in the centre of the touching stretch.
template <class Scalar>
void closestPointsOfSegments(const Eigen::Matrix<Scalar, 3, 1>& p1, const Eigen::Matrix<Scalar, 3, 1>& q1,
                             const Eigen::Matrix<Scalar, 3, 1>& p2, const Eigen::Matrix<Scalar, 3, 1>& q2,
                             Eigen::Matrix<Scalar, 3, 1>& onFirst, Eigen::Matrix<Scalar, 3, 1>& onSecond) {
    using Vector = Eigen::Matrix<Scalar, 3, 1>;
    const Scalar epsilon = std::numeric_limits<Scalar>::epsilon();
    const auto clamp01 = [](Scalar value) { return std::min(std::max(value, Scalar(0)), Scalar(1)); };
    const Vector d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const Scalar a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    // A segment shorter than round-off of the whole configuration is a point.
    const Scalar tiny = epsilon * epsilon * std::max({a, e, r.squaredNorm(), Scalar(1e-30)});
    Scalar s = 0, t = 0;
    if (a <= tiny && e <= tiny) {
        s = t = 0;
    } else if (a <= tiny) {
        t = clamp01(f / e);
    } else {
        const Scalar c = d1.dot(r);
        if (e <= tiny) {
            s = clamp01(-c / a);
        } else {
            const Scalar b = d1.dot(d2);
            const Scalar denominator = a * e - b * b;
            if (denominator > epsilon * a * e) {
                s = clamp01((b * f - c * e) / denominator);
            } else {
                s = Scalar(0.5) * (clamp01((p2 - p1).dot(d1) / a) + clamp01((q2 - p1).dot(d1) / a));
            }
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = clamp01(-c / a);
            } else if (t > 1) {
                t = 1;
                s = clamp01((b - c) / a);
            }
        }
    }
    onFirst = p1 + s * d1;
    onSecond = p2 + t * d2;
}

}  // namespace stepwise
