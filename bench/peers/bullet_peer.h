#pragma once
// A Bullet 3 peer: the same World the engine steps, stepped by Bullet's btDiscreteDynamicsWorld,
// as a yardstick for speed and behaviour (docs/peers.md). Plain data in and out; no Bullet type
// appears here, so code that includes this header needs no Bullet headers.
//
// What the peer maps and what it refuses is listed in docs/peers.md: the engine's convex shapes,
// compounds, static meshes and height fields, and its joints. A feature it cannot map
// (a distance joint, springs, an RK4 integrator, ...) throws BulletUnsupported naming the body,
// joint or setting: a run is never silently different from the scene.

#include "app/peer.h"
#include "world/world.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace stepwise::peers {

/// A scene feature the peer cannot give to Bullet. what() names it, e.g.
/// "joints[0] (distance, \"b0\" - \"ball\"): unsupported: Bullet has no distance constraint".
struct BulletUnsupported : std::runtime_error {
    explicit BulletUnsupported(const std::string& message) : std::runtime_error(message) {}
};

/// How Bullet runs. Everything not here is Bullet's default (docs/peers.md lists them).
struct BulletOptions {
    int solverIterations = 0;   // per (sub)step; 0: the world's settings.solverIterations
    int substeps = 0;           // per frame; 0: the world's settings.substeps
    bool splitImpulse = true;   // Bullet's default: penetration recovery apart from the velocities
    bool sleeping = false;      // Bullet's deactivation; off so every body is stepped every step
    /// Bullet's own internal-edge correction on meshes and height fields (btInternalEdgeUtility):
    /// the engine corrects its triangle contacts' normals too (chapter 13).
    bool internalEdges = true;
};

/// What Bullet was given for one body (read back from its btRigidBody): the engine's mass and
/// inertia in Bullet's body frame, which is the principal frame at the centre of mass.
struct BulletMass {
    Real mass = 0;                          // 0 for static and kinematic bodies
    Vec3 principalInertia = Vec3::Zero();   // kg m^2, about the centre of mass
    Vec3 localCenter = Vec3::Zero();        // centre of mass in the shape's frame
    Quat principalRotation = Quat::Identity();  // principal axes in the shape's frame
    /// The inertia tensor in the shape's axes: R diag(I) R^T (what the engine's Motion holds).
    Mat3 inertiaInShapeAxes() const;
};

struct BulletRun {
    long frames = 0;
    int solverIterations = 0;               // what ran
    int substeps = 0;
    std::vector<double> stepMs;             // one per frame: every stepSimulation call of the frame
    /// One per frame, after it: the deepest penetration of a contact with a static body, m, as
    /// Bullet measures it (a contact point's distance below zero); 0 when none penetrates.
    std::vector<double> staticPenetration;
    std::vector<Transform> finalPoses;      // per World body, same order: pose of the shape origin
    std::vector<Vec3> finalLinearVelocities;    // of the centre of mass, m/s
    std::vector<Vec3> finalAngularVelocities;   // rad/s
    std::vector<BulletMass> masses;         // per World body
};

/// Called after each frame with every body's pose (shape origin), outside the timed region.
using BulletFrameCallback = std::function<void(long frame, const std::vector<Transform>& poses)>;

/// Builds the Bullet world from `world`, steps it `frames` frames and reads back the final
/// state. Throws BulletUnsupported for what cannot be mapped (before any step).
BulletRun runBullet(const World& world, long frames, const BulletOptions& options = {},
                    const BulletFrameCallback& afterFrame = {});

/// A copy of `world` holding Bullet's final poses and velocities (for energies and reports).
World worldAfterRun(const World& world, const BulletRun& run);

/// "bullet 3.24": the version of the Bullet library linked.
std::string bulletVersion();

/// The peer as the benches ask for one (app/peer.h): runBullet with the default options, for a
/// program (or a test) to register with setPeerEngine.
PeerEngine bulletPeerEngine();

}  // namespace stepwise::peers
