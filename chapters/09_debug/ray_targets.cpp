#include "09_debug/ray_targets.h"

#include "09_debug/scenes.h"

#include <cmath>

namespace stepwise {

std::vector<RayTarget> rayTargets() {
    const Quat tilt(angleAxis(Real(0.7), Vec3(1, 2, 3).normalized()));
    return {{"sphere", Shape::sphere(Real(0.5)), Transform{Vec3(Real(0.2), Real(1), 0), Quat::Identity()}},
            {"box", Shape::box(Vec3(Real(0.5), Real(0.3), Real(0.2))), Transform{Vec3(0, Real(1), Real(0.1)), tilt}},
            {"capsule", Shape::capsule(Real(0.3), Real(0.4)), Transform{Vec3(Real(-0.1), Real(1), 0), tilt}},
            {"hull", Shape::convex(gemPoints()), Transform{Vec3(0, Real(1), 0), tilt}}};
}

Ray aimedRay(const RayTarget& target, Random& random) {
    const Aabb bounds = computeAabb(target.shape, target.pose);
    const Vec3 from = target.pose.position + 3 * random.unitVector();
    // One draw per statement (z, y, x): arguments of one call come in an order the compiler picks.
    const Real fz = random.uniformReal(0, 1);
    const Real fy = random.uniformReal(0, 1);
    const Real fx = random.uniformReal(0, 1);
    const Vec3 fraction(fx, fy, fz);
    const Vec3 at = bounds.min + (bounds.max - bounds.min).cwiseProduct(fraction);
    return Ray{from, (at - from).normalized(), kRealMax};
}

}  // namespace stepwise
