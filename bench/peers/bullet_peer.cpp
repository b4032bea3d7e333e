// The Bullet peer (bullet_peer.h, docs/peers.md): a stepwise World handed to Bullet 3's
// btDiscreteDynamicsWorld with the engine's own masses, inertias, materials and joints
// (bullet_scene.cpp builds it), stepped with the engine's combining rules and read back.

#include "peers/bullet_peer.h"
#include "peers/bullet_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace stepwise::peers {
namespace {

using detail::addBodies;
using detail::addJoints;
using detail::btVec;
using detail::BulletScene;
using detail::bulletPose;
using detail::checkSupported;
using detail::shapePose;
using detail::vec;

/// The engine's combining rules (chapter 4, contact_constraints.cpp): friction is the geometric
/// mean, restitution the larger of the two. Bullet's own rules multiply both.
btScalar engineFriction(const btCollisionObject* a, const btCollisionObject* b) {
    return std::sqrt(std::max(btScalar(0), a->getFriction()) * std::max(btScalar(0), b->getFriction()));
}
btScalar engineRestitution(const btCollisionObject* a, const btCollisionObject* b) {
    return std::max(a->getRestitution(), b->getRestitution());
}
/// Rolling resistance (chapter 10): each body's is set as resistance x round radius, a length, as
/// Bullet's rolling and spinning friction are; the pair takes the larger.
btScalar engineRollingFriction(const btCollisionObject* a, const btCollisionObject* b) {
    return std::max(a->getRollingFriction(), b->getRollingFriction());
}
btScalar engineSpinningFriction(const btCollisionObject* a, const btCollisionObject* b) {
    return std::max(a->getSpinningFriction(), b->getSpinningFriction());
}

/// Bullet's combining callbacks are process-wide; this puts the engine's in for one run.
struct CombineRules {
    CalculateCombinedCallback friction = gCalculateCombinedFrictionCallback;
    CalculateCombinedCallback restitution = gCalculateCombinedRestitutionCallback;
    CalculateCombinedCallback rolling = gCalculateCombinedRollingFrictionCallback;
    CalculateCombinedCallback spinning = gCalculateCombinedSpinningFrictionCallback;
    CombineRules() {
        gCalculateCombinedFrictionCallback = engineFriction;
        gCalculateCombinedRestitutionCallback = engineRestitution;
        gCalculateCombinedRollingFrictionCallback = engineRollingFriction;
        gCalculateCombinedSpinningFrictionCallback = engineSpinningFriction;
    }
    ~CombineRules() {
        gCalculateCombinedFrictionCallback = friction;
        gCalculateCombinedRestitutionCallback = restitution;
        gCalculateCombinedRollingFrictionCallback = rolling;
        gCalculateCombinedSpinningFrictionCallback = spinning;
    }
    CombineRules(const CombineRules&) = delete;
    CombineRules& operator=(const CombineRules&) = delete;
};

/// Moves the kinematic bodies to where they are at time `t` (the end of the coming step); Bullet
/// derives their velocities from the move (btRigidBody::saveKinematicState).
void moveKinematic(BulletScene& scene, const World& world, std::vector<Transform>& poses, double t, Real h) {
    for (const Motion& motion : world.motions) {
        const std::size_t i = std::size_t(motion.bodyIndex);
        if (world.bodies[i].type != BodyType::Kinematic) continue;
        Transform& pose = poses[i];
        const Vec3 center = pose.apply(motion.localCenter);
        const Real turn = motion.angularVelocity.norm() * h;
        if (turn > 0) pose.rotation = (Eigen::AngleAxis<Real>(turn, motion.angularVelocity.normalized()) * pose.rotation).normalized();
        pose.position = center + motion.linearVelocity * h - pose.rotate(motion.localCenter);
        for (const KinematicPath& path : world.kinematicPaths)
            if (path.body == motion.bodyIndex)
                pose.position = path.center + path.amplitude * Real(std::sin(2 * double(kPi) * t / double(path.period) + double(path.phase)));
        scene.bodies[i]->setWorldTransform(bulletPose(pose, scene.frames[i]));
    }
}

}  // namespace

Mat3 BulletMass::inertiaInShapeAxes() const {
    const Mat3 rotation = principalRotation.toRotationMatrix();
    return rotation * principalInertia.asDiagonal() * rotation.transpose();
}

namespace {

/// The deepest penetration of a contact between a static body and another, as Bullet measures it
/// (a point's distance below zero), m; 0 when none penetrates.
double deepestStaticPenetration(btDispatcher& dispatcher) {
    double deepest = 0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
        const btPersistentManifold& manifold = *dispatcher.getManifoldByIndexInternal(m);
        if (!manifold.getBody0()->isStaticObject() && !manifold.getBody1()->isStaticObject()) continue;
        for (int p = 0; p < manifold.getNumContacts(); ++p)
            deepest = std::max(deepest, -double(manifold.getContactPoint(p).getDistance()));
    }
    return deepest;
}

/// What Bullet was given for each body, and where each body ended.
void readBack(const BulletScene& scene, const World& world, BulletRun& run) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const btRigidBody& body = *scene.bodies[i];
        run.finalPoses.push_back(shapePose(body.getWorldTransform(), scene.frames[i]));
        run.finalLinearVelocities.push_back(vec(body.getLinearVelocity()));
        run.finalAngularVelocities.push_back(vec(body.getAngularVelocity()));
        BulletMass mass;
        mass.mass = body.getInvMass() > 0 ? Real(1 / body.getInvMass()) : Real(0);
        mass.principalInertia = mass.mass > 0 ? vec(body.getLocalInertia()) : Vec3::Zero();
        if (world.motionOf(int(i))) {  // a static body's frame may be a height field's centre, not a mass's
            mass.localCenter = scene.frames[i].center;
            mass.principalRotation = Quat(scene.frames[i].axes);
        }
        run.masses.push_back(mass);
    }
}

}  // namespace

BulletRun runBullet(const World& world, long frames, const BulletOptions& options, const BulletFrameCallback& afterFrame) {
    checkSupported(world);
    const Settings& settings = world.settings;
    BulletRun run;
    run.solverIterations = options.solverIterations > 0 ? options.solverIterations : settings.solverIterations;
    run.substeps = std::max(1, options.substeps > 0 ? options.substeps : settings.substeps);
    const Real h = settings.dt / Real(run.substeps);

    const CombineRules combineRules;
    const detail::InternalEdgeCallback edgeCallback(options.internalEdges);
    BulletScene scene;
    scene.dynamics.setGravity(btVec(settings.gravity));
    btContactSolverInfo& solverInfo = scene.dynamics.getSolverInfo();
    solverInfo.m_numIterations = run.solverIterations;
    solverInfo.m_splitImpulse = options.splitImpulse ? 1 : 0;
    solverInfo.m_restitutionVelocityThreshold = btScalar(settings.restitutionThreshold);
    if (!settings.warmStarting) solverInfo.m_solverMode &= ~SOLVER_USE_WARMSTARTING;
    addBodies(scene, world, options.internalEdges);
    addJoints(scene, world, btScalar(h));

    std::vector<Transform> kinematicPoses;
    for (const Body& body : world.bodies) kinematicPoses.push_back(body.transform);
    auto poses = [&] {
        std::vector<Transform> out;
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            out.push_back(shapePose(scene.bodies[i]->getWorldTransform(), scene.frames[i]));
        return out;
    };

    // One stepSimulation call per substep, in Bullet's variable-step mode (maxSubSteps = 0):
    // exactly one internal step of h each, where the fixed-step mode's accumulator could take
    // S - 1 or S + 1 steps in a frame when dt / (dt / S) rounds.
    run.stepMs.reserve(std::size_t(std::max(0L, frames)));
    for (long frame = 0; frame < frames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        for (int s = 0; s < run.substeps; ++s) {
            const double t = world.time + double(frame) * double(settings.dt) + double(s + 1) * double(h);
            moveKinematic(scene, world, kinematicPoses, t, h);
            scene.dynamics.stepSimulation(btScalar(h), 0, btScalar(h));
        }
        const auto end = std::chrono::steady_clock::now();
        run.stepMs.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        run.staticPenetration.push_back(deepestStaticPenetration(scene.dispatcher));
        if (afterFrame) afterFrame(frame, poses());
    }
    run.frames = frames;
    readBack(scene, world, run);
    return run;
}

World worldAfterRun(const World& world, const BulletRun& run) {
    World after = world;
    for (std::size_t i = 0; i < after.bodies.size() && i < run.finalPoses.size(); ++i) {
        after.bodies[i].transform = run.finalPoses[i];
        if (Motion* motion = after.motionOf(int(i))) {
            motion->linearVelocity = run.finalLinearVelocities[i];
            motion->angularVelocity = run.finalAngularVelocities[i];
        }
    }
    after.frame = world.frame + run.frames;
    after.time = world.time + double(run.frames) * double(world.settings.dt);
    return after;
}

PeerEngine bulletPeerEngine() {
    return {bulletVersion(), [](const World& world, long frames, const BetweenPeerFrames& between) {
                const BulletRun run = runBullet(world, frames, {}, between);
                return PeerRun{run.stepMs, run.finalPoses, run.staticPenetration};
            }};
}

std::string bulletVersion() {
    const int version = btGetVersion();  // 324 for 3.24
    return "bullet " + std::to_string(version / 100) + "." + std::to_string(version % 100);
}

}  // namespace stepwise::peers
