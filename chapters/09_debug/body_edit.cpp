#include "09_debug/body_edit.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

namespace stepwise {

BodyEdit currentState(const World& world, int body) {
    BodyEdit edit;
    edit.frame = world.frame;
    edit.body = body;
    if (body < 0 || body >= static_cast<int>(world.bodies.size())) return edit;
    edit.transform = world.bodies[static_cast<std::size_t>(body)].transform;
    if (const Motion* motion = world.motionOf(body)) {
        edit.linearVelocity = motion->linearVelocity;
        edit.angularVelocity = motion->angularVelocity;
        edit.mass = motion->mass;
        edit.inertiaLocal = motion->inertiaLocal;
    }
    return edit;
}

std::string validateEdit(const World& world, const BodyEdit& edit) {
    if (edit.body < 0 || edit.body >= static_cast<int>(world.bodies.size()))
        return "body " + std::to_string(edit.body) + " does not exist (the world has " +
               std::to_string(world.bodies.size()) + ")";
    const Body& body = world.bodies[static_cast<std::size_t>(edit.body)];
    const std::string where = "body '" + body.name + "': ";
    if (!edit.transform.position.allFinite()) return where + "position is not finite";
    if (!edit.transform.rotation.coeffs().allFinite()) return where + "orientation is not finite";
    if (std::abs(edit.transform.rotation.norm() - 1) > Real(0.01))
        return where + "orientation is not a unit quaternion (length " + std::to_string(edit.transform.rotation.norm()) + ")";
    if (!edit.linearVelocity.allFinite()) return where + "linear velocity is not finite";
    if (!edit.angularVelocity.allFinite()) return where + "angular velocity is not finite";
    if (body.type != BodyType::Dynamic) return "";
    if (!std::isfinite(edit.mass) || edit.mass <= 0) return where + "mass must be positive and finite, got " + std::to_string(edit.mass);
    if (!edit.inertiaLocal.allFinite()) return where + "inertia is not finite";
    if ((edit.inertiaLocal - edit.inertiaLocal.transpose()).cwiseAbs().maxCoeff() > Real(1e-6) * edit.inertiaLocal.cwiseAbs().maxCoeff())
        return where + "inertia is not symmetric";
    const Eigen::SelfAdjointEigenSolver<Mat3> moments(edit.inertiaLocal);
    if (moments.eigenvalues().minCoeff() <= 0) return where + "inertia is not positive definite (a principal moment <= 0)";
    // A rigid body's principal moments obey the triangle inequality (I1 <= I2 + I3): mass cannot
    // be farther from one axis than the other two allow.
    const Vec3 principal = moments.eigenvalues();
    if (principal[2] > (principal[0] + principal[1]) * Real(1.0001))
        return where + "inertia breaks the triangle inequality (largest moment above the sum of the other two)";
    return "";
}

void applyEdit(World& world, const BodyEdit& edit) {
    const std::string problem = validateEdit(world, edit);
    if (!problem.empty()) throw std::invalid_argument(problem);
    Body& body = world.bodies[static_cast<std::size_t>(edit.body)];
    body.transform.position = edit.transform.position;
    // Unchanged numbers keep their bits: an edit that changes nothing changes nothing.
    const bool unit = std::abs(edit.transform.rotation.squaredNorm() - 1) <= 8 * kEpsilon;
    body.transform.rotation = unit ? edit.transform.rotation : edit.transform.rotation.normalized();
    Motion* motion = world.motionOf(edit.body);
    if (!motion) return;
    // An edited body is a moved body: a sleeping one (chapter 10) wakes with its island.
    if (motion->asleep) wakeBody(world, edit.body);
    motion->linearVelocity = edit.linearVelocity;
    motion->angularVelocity = edit.angularVelocity;
    if (body.type != BodyType::Dynamic) return;
    if (edit.mass != motion->mass) {
        motion->mass = edit.mass;
        motion->inverseMass = 1 / edit.mass;
    }
    if (edit.inertiaLocal != motion->inertiaLocal) {
        motion->inertiaLocal = edit.inertiaLocal;
        motion->inverseInertiaLocal = edit.inertiaLocal.inverse();
    }
}

BodyEdit moveEdit(const World& world, int body, const Transform& transform) {
    BodyEdit edit = currentState(world, body);
    edit.transform = transform;
    edit.linearVelocity = Vec3::Zero();
    edit.angularVelocity = Vec3::Zero();
    return edit;
}

}  // namespace stepwise
