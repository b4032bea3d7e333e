#include "01_integrators/forces.h"

namespace stepwise {

MotionState readMotionState(const World& world, const Motion& motion) {
    const Body& body = world.bodies[motion.bodyIndex];
    MotionState state;
    state.rotation = body.transform.rotation;
    state.center = body.transform.apply(motion.localCenter);
    state.linearVelocity = motion.linearVelocity;
    state.angularVelocity = motion.angularVelocity;
    return state;
}

void readMotionStates(const World& world, std::vector<MotionState>& states) {
    states.resize(world.motions.size());
    for (size_t i = 0; i < world.motions.size(); ++i) states[i] = readMotionState(world, world.motions[i]);
}

void writeMotionState(World& world, Motion& motion, const MotionState& state) {
    Body& body = world.bodies[motion.bodyIndex];
    body.transform.rotation = state.rotation;
    body.transform.position = state.center - state.rotation * motion.localCenter;
    motion.linearVelocity = state.linearVelocity;
    motion.angularVelocity = state.angularVelocity;
}

Mat3 worldInertiaAt(const Motion& motion, const Quat& rotation) {
    const Mat3 r = rotation.toRotationMatrix();
    return r * motion.inertiaLocal * r.transpose();
}

Mat3 worldInverseInertiaAt(const Motion& motion, const Quat& rotation) {
    const Mat3 r = rotation.toRotationMatrix();
    return r * motion.inverseInertiaLocal * r.transpose();
}

namespace {

// One end of a spring at the candidate states: where it is, how fast it moves, and which
// motion (if any) feels the force there.
struct SpringEnd {
    Vec3 point = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    Vec3 center = Vec3::Zero();
    int motionIndex = -1;   // -1: the world or a static body, which take no force
};

SpringEnd springEnd(const World& world, const std::vector<MotionState>& states, int bodyIndex, const Vec3& anchor) {
    SpringEnd end;
    if (bodyIndex < 0) {  // a fixed point in the world
        end.point = anchor;
        return end;
    }
    const Body& body = world.bodies[bodyIndex];
    if (body.motionIndex < 0) {  // static bodies never move
        end.point = body.transform.apply(anchor);
        return end;
    }
    const Motion& motion = world.motions[body.motionIndex];
    const MotionState& state = states[body.motionIndex];
    // The anchor is given relative to the body origin; measure it from the centre of mass.
    const Vec3 arm = state.rotation * (anchor - motion.localCenter);
    end.point = state.center + arm;
    end.velocity = state.linearVelocity + state.angularVelocity.cross(arm);
    end.center = state.center;
    end.motionIndex = body.motionIndex;
    return end;
}

bool validBody(const World& world, int bodyIndex) {
    return bodyIndex >= 0 && bodyIndex < static_cast<int>(world.bodies.size());
}

void addForceAtPoint(std::vector<Wrench>& wrenches, const SpringEnd& end, const Vec3& force) {
    if (end.motionIndex < 0) return;
    wrenches[end.motionIndex].force += force;
    wrenches[end.motionIndex].torque += (end.point - end.center).cross(force);
}

}  // namespace

// [ch01-forces]
void evaluateForces(const World& world, const std::vector<MotionState>& states, std::vector<Wrench>& wrenches) {
    wrenches.assign(world.motions.size(), Wrench{});
    auto isDynamic = [&](int motionIndex) {
        return world.bodies[world.motions[motionIndex].bodyIndex].type == BodyType::Dynamic;
    };

    // Gravity: F = m g through the centre of mass, so it makes no torque.
    for (size_t i = 0; i < world.motions.size(); ++i)
        if (isDynamic(static_cast<int>(i))) wrenches[i].force += world.motions[i].mass * world.settings.gravity;

    // Springs (Hooke's law plus a dashpot along the spring):
    //   F_A = (k (L - L0) + c (v_B - v_A) . u) u,   F_B = -F_A,   u = (p_B - p_A) / L.
    // Applied at the anchors, so an off-centre anchor also makes a torque (p - c) x F.
    for (const Spring& spring : world.springs) {
        if (!validBody(world, spring.bodyA) || spring.bodyB >= static_cast<int>(world.bodies.size())) continue;
        const SpringEnd endA = springEnd(world, states, spring.bodyA, spring.localAnchorA);
        const SpringEnd endB = springEnd(world, states, spring.bodyB, spring.anchorB);
        const Vec3 delta = endB.point - endA.point;
        const Vec3 relativeVelocity = endB.velocity - endA.velocity;
        const Real length = delta.norm();
        Vec3 force;
        if (length > Real(1e-6)) {
            const Vec3 direction = delta / length;
            force = (spring.stiffness * (length - spring.restLength) + spring.damping * relativeVelocity.dot(direction)) *
                    direction;
        } else {
            // The ends coincide and the spring has no direction. k d + c dv is the limit for a
            // zero-rest-length spring (exact there) and a defined, tiny force otherwise.
            force = spring.stiffness * delta + spring.damping * relativeVelocity;
        }
        addForceAtPoint(wrenches, endA, force);
        addForceAtPoint(wrenches, endB, -force);
    }

    // Drag: F = -b_lin m v, T = -b_ang I w (units 1/s, so the decay rate is mass independent).
    for (const Damping& damping : world.dampings) {
        for (size_t i = 0; i < world.motions.size(); ++i) {
            const Motion& motion = world.motions[i];
            const bool selected = damping.body < 0 || damping.body == motion.bodyIndex;
            if (!selected || !isDynamic(static_cast<int>(i))) continue;
            wrenches[i].force -= damping.linear * motion.mass * states[i].linearVelocity;
            wrenches[i].torque -= damping.angular * (worldInertiaAt(motion, states[i].rotation) * states[i].angularVelocity);
        }
    }

    // Kinematic bodies follow their set velocities; whatever a spring pulls on them is dropped.
    for (size_t i = 0; i < world.motions.size(); ++i)
        if (!isDynamic(static_cast<int>(i))) wrenches[i] = Wrench{};
}
// [ch01-forces]

Acceleration accelerationAt(const Motion& motion, const MotionState& state, const Wrench& wrench, bool gyroscopic) {
    Acceleration acceleration;
    acceleration.linear = motion.inverseMass * wrench.force;
    Vec3 torque = wrench.torque;
    if (gyroscopic) {
        // Euler's equation in world axes: I dw/dt = torque - w x (I w).
        torque -= state.angularVelocity.cross(worldInertiaAt(motion, state.rotation) * state.angularVelocity);
    }
    acceleration.angular = worldInverseInertiaAt(motion, state.rotation) * torque;
    return acceleration;
}

Vec3 angularMomentum(const World& world, int bodyIndex) {
    const Motion* motion = world.motionOf(bodyIndex);
    if (!motion) return Vec3::Zero();
    return worldInertiaAt(*motion, world.bodies[bodyIndex].transform.rotation) * motion->angularVelocity;
}

}  // namespace stepwise
