#pragma once
// The World as Bullet's (bullet_peer.h, docs/peers.md): what the peer refuses, the bodies and
// constraints it builds from the engine's, and poses between the shape frame and Bullet's body
// frame. Internal to the peer, as bullet_shapes.h is.

#include "peers/bullet_shapes.h"

#include <memory>
#include <vector>

namespace stepwise::peers::detail {

/// Shape pose -> Bullet body pose, and back.
btTransform bulletPose(const Transform& pose, const PrincipalFrame& frame);
Transform shapePose(const btTransform& body, const PrincipalFrame& frame);

/// Throws BulletUnsupported, before anything is built, for what Bullet cannot do as the engine does.
void checkSupported(const World& world);

/// Everything Bullet needs, owned in one place and torn down in the order Bullet requires.
struct BulletScene {
    btDefaultCollisionConfiguration configuration;
    btCollisionDispatcher dispatcher{&configuration};
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld dynamics{&dispatcher, &broadphase, &solver, &configuration};
    detail::ShapeStore store;                               // the shapes and what they point into
    std::vector<std::unique_ptr<btRigidBody>> bodies;       // one per World body
    std::vector<std::unique_ptr<btTypedConstraint>> joints;
    std::vector<PrincipalFrame> frames;                     // one per World body

    BulletScene() = default;
    BulletScene(const BulletScene&) = delete;
    BulletScene& operator=(const BulletScene&) = delete;
    ~BulletScene() {
        for (auto& joint : joints) dynamics.removeConstraint(joint.get());
        for (auto& body : bodies) dynamics.removeRigidBody(body.get());
    }

    /// The Bullet transform of a joint frame (origin `anchor`, axes `basis`, in the shape frame).
    btTransform jointFrame(int body, const Vec3& anchor, const Mat3& basis) const {
        const PrincipalFrame& frame = frames[std::size_t(body)];
        return btPose(frame.axes.transpose() * basis, frame.axes.transpose() * (anchor - frame.center));
    }
};

/// One Bullet body per World body, in order, with the world's materials, damping and settings.
void addBodies(BulletScene& scene, const World& world, bool internalEdges);

/// One Bullet constraint per World joint; `subDt`, the substep, turns a hinge's motor and friction
/// torques into Bullet's impulses.
void addJoints(BulletScene& scene, const World& world, btScalar subDt);

}  // namespace stepwise::peers::detail
