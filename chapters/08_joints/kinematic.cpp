#include "08_joints/kinematic.h"

#include <cmath>

namespace stepwise {

// [ch08-move-kinematic]
void moveKinematic(World& world, int bodyIndex, const Transform& target, Real dt) {
    if (bodyIndex < 0 || std::size_t(bodyIndex) >= world.bodies.size() || !(dt > 0)) return;
    const Body& body = world.bodies[static_cast<std::size_t>(bodyIndex)];
    Motion* motion = world.motionOf(bodyIndex);
    if (body.type != BodyType::Kinematic || !motion) return;
    // The turn from here to the target as an angle about an axis, spread over the step.
    Quat turn = target.rotation * body.transform.rotation.conjugate();
    if (turn.w() < 0) turn.coeffs() = -turn.coeffs();
    // Angle and axis as Eigen::AngleAxis reads a quaternion (2 atan2(|v|, w), axis v / |v|), with
    // this build's atan2 (common/math/functions.h).
    turn.normalize();
    const Real sine = turn.vec().norm();
    motion->angularVelocity = Vec3::Zero();
    if (sine > 0) motion->angularVelocity = (turn.vec() / sine) * (2 * math::atan2(sine, turn.w()) / dt);
    // The centre of mass moves from where it is to where the target pose puts it.
    const Vec3 centerNow = body.transform.apply(motion->localCenter);
    const Vec3 centerThen = target.apply(motion->localCenter);
    motion->linearVelocity = (centerThen - centerNow) / dt;
}
// [ch08-move-kinematic]

Vec3 pathPosition(const KinematicPath& path, double time) {
    const double angle = 2 * 3.14159265358979323846 * time / double(path.period) + double(path.phase);
    return path.center + path.amplitude * static_cast<Real>(math::sin(angle));
}

void driveKinematicPaths(World& world, Real dt) {
    const double end = world.time + double(world.step.substep + 1) * double(dt);
    for (const KinematicPath& path : world.kinematicPaths) {
        if (path.body < 0 || std::size_t(path.body) >= world.bodies.size()) continue;
        Transform target = world.bodies[static_cast<std::size_t>(path.body)].transform;
        const Motion* motion = world.motionOf(path.body);
        const Vec3 spin = motion ? motion->angularVelocity : Vec3::Zero();
        target.position = pathPosition(path, end);
        moveKinematic(world, path.body, target, dt);
        if (Motion* moving = world.motionOf(path.body)) {
            // Keep the body's own spin; only the line is the path's.
            moving->angularVelocity = spin;
        }
    }
}

}  // namespace stepwise
