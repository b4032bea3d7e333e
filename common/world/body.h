#pragma once
// Bodies are plain data. Static bodies have a pose and a shape and nothing else: only moving
// bodies (kinematic and dynamic) own a Motion, so a static body cannot be integrated by mistake.

#include "math/math.h"
#include "world/settings.h"
#include "world/shape.h"

#include <optional>
#include <string>

namespace stepwise {

enum class BodyType { Static, Kinematic, Dynamic };
/// The scene-format spelling: "static", "kinematic", "dynamic".
extern const Names<BodyType> kBodyTypeNames;
const char* toString(BodyType type);

struct Material {
    Real friction = Real(0.6);
    Real restitution = 0;
    /// Resists one body turning on another, rolling or spinning (Box2D v3's rolling resistance,
    /// usually 0 to 1): a round body's turn is held back by at most this times its radius times
    /// the normal impulse. Chapter 10's solve reads it; earlier chapters' solves do not.
    Real rollingResistance = 0;
};

struct Body {
    std::string name;
    BodyType type = BodyType::Dynamic;
    Shape shape;
    Transform transform;        // pose of the shape's origin
    Material material;
    bool bullet = false;        // hint: fast, wants continuous collision
    int motionIndex = -1;       // into World::motions; -1 for static bodies
};

/// The dynamic state of a kinematic or dynamic body.
struct Motion {
    int bodyIndex = -1;
    Vec3 linearVelocity = Vec3::Zero();     // of the centre of mass, world frame, m/s
    Vec3 angularVelocity = Vec3::Zero();    // world frame, rad/s
    Real mass = 0;                          // kg; 0 for kinematic bodies
    Real inverseMass = 0;                   // 0 for kinematic bodies
    Vec3 localCenter = Vec3::Zero();        // centre of mass in the body frame
    Mat3 inertiaLocal = Mat3::Zero();       // about the centre of mass, body axes
    Mat3 inverseInertiaLocal = Mat3::Zero();
    Vec3 force = Vec3::Zero();              // accumulated this step, world frame, N
    Vec3 torque = Vec3::Zero();             // accumulated this step, world frame, N m
    std::optional<IntegratorKind> integrator;  // per-body override of Settings::integrator
    // Sleeping (chapter 10; earlier chapters never set them): a body that stayed slow for a while
    // sleeps with its island and costs nothing until something wakes it.
    bool asleep = false;
    Real sleepTime = 0;                     // s spent below the sleep speeds
};

}  // namespace stepwise
