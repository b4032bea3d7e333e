#pragma once
// The whole simulation state as plain data. Stages (chapters) read and write it; nothing in
// here knows which stages exist.

#include "world/body.h"
#include "world/broadphase_state.h"
#include "world/contact.h"
#include "world/settings.h"
#include "world/step_state.h"

#include <optional>
#include <functional>
#include <string>
#include <vector>

namespace stepwise {

/// A damped spring between an anchor on body A and either a world point or an anchor on B.
struct Spring {
    int bodyA = -1;
    int bodyB = -1;                      // -1: anchored to the world point anchorB
    Vec3 localAnchorA = Vec3::Zero();    // body A frame
    Vec3 anchorB = Vec3::Zero();         // body B frame, or world frame when bodyB == -1
    Real restLength = 0;                 // m
    Real stiffness = 0;                  // N/m
    Real damping = 0;                    // N s/m along the spring
};

/// Velocity-proportional drag, F = -linear * m * v and T = -angular * I * w.
struct Damping {
    int body = -1;                       // -1: every dynamic body
    Real linear = 0;                     // 1/s
    Real angular = 0;                    // 1/s
};

enum class JointType { Distance, BallSocket, Hinge, ConeTwist, Slider, Fixed };

/// The scene-format spelling: "distance", "ball_socket", "hinge", "cone_twist", "slider", "fixed".
extern const Names<JointType> kJointTypeNames;
const char* toString(JointType type);

/// A hinge's or slider's motor: drives the joint's speed along its axis towards `speed` (rad/s or
/// m/s) with at most `maxForce` (N m for a hinge, N for a slider).
struct JointMotor {
    Real speed = 0;
    Real maxForce = 0;
};

/// A joint as the scene describes it; chapter 8 turns these into constraint rows.
struct JointDesc {
    JointType type = JointType::BallSocket;
    int bodyA = -1;
    int bodyB = -1;
    Vec3 localAnchorA = Vec3::Zero();
    Vec3 localAnchorB = Vec3::Zero();
    Vec3 axis = Vec3::UnitY();           // unit, body A's frame: hinge and slider axis, cone-twist twist axis
    /// B's orientation in A's frame when the joint is at rest (angle zero): what hinge, cone-twist,
    /// slider and fixed joints measure their angles from. Taken from the bodies' poses at load
    /// unless the scene gives it.
    Quat referenceRotation = Quat::Identity();
    std::optional<Real> length;          // distance joint, m; the loader sets the anchors' distance at load when absent (code that leaves it unset gets no length held)
    Real springHertz = 0;                // distance joint: > 0 makes it a spring of this frequency
    Real springDampingRatio = 0;
    std::optional<std::pair<Real, Real>> limits;      // hinge (rad) and slider (m)
    Real coneAngle = 0;                  // cone-twist: largest swing of the twist axis, rad
    std::optional<std::pair<Real, Real>> twistLimits; // cone-twist, rad
    std::optional<JointMotor> motor;     // hinge and slider
    Real frictionTorque = 0;             // cone-twist, hinge without motor: N m resisting the turn (joint friction)
    bool collideConnected = false;       // whether the two bodies still collide with each other
};

/// What a joint carries from one solve to the next: the accumulated impulses of its rows, for the
/// warm start (chapter 8). One per World::joints entry; the slots' meaning is the joint type's.
struct JointImpulses {
    static constexpr int kSlots = 10;
    Real slot[kSlots] = {};
};

/// A kinematic body moved back and forth along a line (a moving platform, chapter 8): its origin
/// at time t is center + amplitude sin(2 pi t / period + phase). The stage that drives it sets the
/// body's velocity each step to land exactly there.
struct KinematicPath {
    int body = -1;
    Vec3 center = Vec3::Zero();
    Vec3 amplitude = Vec3::Zero();   // m
    Real period = 1;                 // s
    Real phase = 0;                  // rad at t = 0
};

/// Everything needed to create one body: what a scene file's bodies[] entry says.
struct BodyDef {
    std::string name;
    BodyType type = BodyType::Dynamic;
    Shape shape;
    Transform transform;
    Vec3 linearVelocity = Vec3::Zero();
    Vec3 angularVelocity = Vec3::Zero();
    std::optional<Real> mass;            // kg; wins over density when set
    Real density = 1000;                 // kg/m^3
    Material material;
    bool bullet = false;
    std::optional<IntegratorKind> integrator;
    std::optional<KinematicPath> path;   // kinematic bodies: amplitude, period, phase (body and centre are filled in)
};

struct World {
    std::string name = "untitled";
    Settings settings;
    std::vector<Body> bodies;
    std::vector<Motion> motions;         // one per kinematic or dynamic body
    std::vector<Spring> springs;
    std::vector<Damping> dampings;
    std::vector<JointDesc> joints;
    std::vector<JointImpulses> jointImpulses;  // parallel to joints once a joint solve ran
    std::vector<KinematicPath> kinematicPaths;

    // Collision state. candidatePairs is rebuilt every frame by whatever finds candidates (all
    // pairs in chapter 3, a broadphase from chapter 5); pairs lists the pairs the last narrowphase
    // found overlapping. contacts is the contact cache: one record per touching pair, sorted by
    // pair, kept from step to step (contact.h).
    std::vector<BodyPair> candidatePairs;
    std::vector<BodyPair> pairs;
    std::vector<Contact> contacts;
    std::vector<PairGap> pairGaps;       // chapter 10: candidate pairs known apart, sorted by pair
    BroadphaseState broadphase;          // what the broadphase keeps between steps (chapter 5)

    StepState step;                      // what stages hand each other, and what they measured

    double time = 0;                     // s simulated
    long frame = 0;

    int findBody(const std::string& bodyName) const;  // -1 when absent
    // Inline: the solves and the planner ask it for every contact's bodies every frame.
    Motion* motionOf(int bodyIndex) {
        const int motionIndex = bodies[static_cast<std::size_t>(bodyIndex)].motionIndex;
        return motionIndex < 0 ? nullptr : &motions[static_cast<std::size_t>(motionIndex)];
    }
    const Motion* motionOf(int bodyIndex) const {
        const int motionIndex = bodies[static_cast<std::size_t>(bodyIndex)].motionIndex;
        return motionIndex < 0 ? nullptr : &motions[static_cast<std::size_t>(motionIndex)];
    }
    int dynamicBodyCount() const;
};

/// An empty world named `name`: where a scene builder starts. The collision chapters' scenes pass
/// zero gravity, so their bodies stay where the scene puts them and only the queries move.
World emptyWorld(const std::string& name, const Vec3& gravity = Settings{}.gravity);

/// Adds a body and, for moving bodies, its Motion with mass properties from the shape.
/// Returns the body index. Static bodies get no Motion.
int addBody(World& world, const BodyDef& def);

/// Adds a static box (ground, walls, posts) and returns its index.
int addStaticBox(World& world, const std::string& name, const Vec3& position, const Vec3& halfExtents,
                 const Quat& rotation = Quat::Identity(), const Material& material = Material{});

/// Wakes a body and, when it sleeps, its whole sleeping island: every sleeping body joined to it
/// through touching contacts, joints or springs (chapter 10's sleeping; Box2D v3's b2Body_SetAwake
/// wakes the body's solver set the same way). Restarts the timers, so what was edited (the demo's
/// inspector, a recording's edit) gets time_to_sleep before it may sleep again. Static bodies: no-op.
void wakeBody(World& world, int bodyIndex);

/// Centre of mass of a body in world space.
Vec3 worldCenterOfMass(const World& world, int bodyIndex);

/// Inverse inertia in world axes: R I^-1 R^T. Zero for static and kinematic bodies.
Mat3 worldInverseInertia(const Body& body, const Motion& motion);

struct Energy {
    double kinetic = 0;
    double gravity = 0;    // potential, relative to y = 0
    double springs = 0;    // potential
    double total() const { return kinetic + gravity + springs; }
};

/// Mechanical energy of the dynamic bodies (kinematic and static bodies carry none). With
/// `countsBody`, only the bodies it accepts, and the springs whose A end is such a body: the
/// energy of one chain of several in a scene.
Energy computeEnergy(const World& world, const std::function<bool(int bodyIndex)>& countsBody = {});

}  // namespace stepwise
