// The World as Bullet's (bullet_scene.h): the checks before a run, the bodies with the engine's
// masses, inertias, materials and damping, the joints as Bullet's constraints, and the poses
// between the two frames.

#include "peers/bullet_scene.h"

#include <cmath>
#include <memory>
#include <string>

namespace stepwise::peers::detail {

/// Shape pose -> Bullet body pose: T_body = T_shape * (center, axes).
btTransform bulletPose(const Transform& pose, const PrincipalFrame& frame) {
    const Mat3 rotation = pose.rotation.normalized().toRotationMatrix();
    return btPose(rotation * frame.axes, pose.position + rotation * frame.center);
}

/// Bullet body pose -> shape pose (the inverse of bulletPose).
Transform shapePose(const btTransform& body, const PrincipalFrame& frame) {
    Transform pose;
    pose.rotation = Quat(mat(body.getBasis()) * frame.axes.transpose()).normalized();
    pose.position = vec(body.getOrigin()) - pose.rotation * frame.center;
    return pose;
}

namespace {

std::string bodyLabel(const World& world, int index) {
    return "bodies[" + std::to_string(index) + "] (\"" + world.bodies[std::size_t(index)].name + "\")";
}

std::string jointLabel(const World& world, std::size_t index) {
    const JointDesc& joint = world.joints[index];
    return "joints[" + std::to_string(index) + "] (" + toString(joint.type) + ", \"" +
           world.bodies[std::size_t(joint.bodyA)].name + "\" - \"" + world.bodies[std::size_t(joint.bodyB)].name + "\")";
}

}  // namespace

/// Refuses, before anything is built, what Bullet cannot do as the engine does.
void checkSupported(const World& world) {
    const Settings& settings = world.settings;
    if (settings.integrator != IntegratorKind::SemiImplicitEuler)
        throw BulletUnsupported(std::string("settings.integrator (") + toString(settings.integrator) +
                                "): unsupported: Bullet integrates with semi-implicit Euler only");
    if (settings.solver != SolverKind::GaussSeidel)
        throw BulletUnsupported(std::string("settings.solver (") + toString(settings.solver) +
                                "): unsupported: Bullet's btSequentialImpulseConstraintSolver is Gauss-Seidel only");
    for (const Motion& motion : world.motions)
        if (motion.integrator && *motion.integrator != IntegratorKind::SemiImplicitEuler)
            throw BulletUnsupported(bodyLabel(world, motion.bodyIndex) + ".integrator (" + toString(*motion.integrator) +
                                    "): unsupported: Bullet integrates with semi-implicit Euler only");
    if (!world.springs.empty())
        throw BulletUnsupported("springs[0] (\"" + world.bodies[std::size_t(world.springs[0].bodyA)].name +
                                "\"): unsupported: Bullet has no damped spring between two anchors");
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        if (!canMove(body.shape) && body.type != BodyType::Static)
            throw BulletUnsupported(bodyLabel(world, static_cast<int>(i)) + ".shape (" + toString(body.shape.type) +
                                    "): unsupported: Bullet's triangle meshes and height fields are static only");
    }
    for (std::size_t i = 0; i < world.joints.size(); ++i) {
        const JointDesc& joint = world.joints[i];
        if (joint.type == JointType::Distance)
            throw BulletUnsupported(jointLabel(world, i) +
                                    ": unsupported: Bullet has no distance constraint (a rod or spring between two anchors)");
        if (joint.type == JointType::ConeTwist && joint.frictionTorque > 0)
            throw BulletUnsupported(jointLabel(world, i) +
                                    ".friction_torque: unsupported: btConeTwistConstraint has no joint friction");
    }
}

namespace {

/// A unit joint axis as one column of a right-handed frame: column `column` is the axis.
Mat3 axisFrame(const Vec3& axis, int column) {
    const Vec3 u = axis.normalized();
    const Vec3 v = anyPerpendicular(u);
    const Vec3 w = u.cross(v);
    Mat3 frame;
    if (column == 0) frame << u, v, w;   // x = axis: slider, cone-twist
    else frame << v, w, u;               // z = axis: hinge
    return frame;
}

/// Velocity-proportional drag (World::dampings, dv/dt = -rate v) as Bullet's per-step factor
/// v *= (1 - d)^dt: d = 1 - exp(-rate) gives exactly v *= exp(-rate dt).
btScalar bulletDamping(Real rate) { return btScalar(1 - std::exp(-double(rate))); }

/// The Bullet body of World body `index`, its shape made in Bullet's body frame.
std::unique_ptr<btRigidBody> makeBody(BulletScene& scene, const World& world, int index, bool internalEdges) {
    const Body& body = world.bodies[std::size_t(index)];
    const Motion* motion = world.motionOf(index);
    PrincipalFrame frame = detail::principalFrame(motion);
    const detail::BulletShape shape = detail::makeBodyShape(scene.store, body.shape, frame, internalEdges, bodyLabel(world, index));
    scene.frames.push_back(frame);
    const bool dynamic = body.type == BodyType::Dynamic;
    const btScalar mass = dynamic ? btScalar(motion->mass) : btScalar(0);
    btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.shape, dynamic ? btVec(frame.inertia) : btVector3(0, 0, 0));
    info.m_startWorldTransform = bulletPose(body.transform, frame);
    info.m_friction = btScalar(body.material.friction);
    info.m_restitution = btScalar(body.material.restitution);
    info.m_rollingFriction = info.m_spinningFriction = btScalar(body.material.rollingResistance * roundRadius(body.shape));
    Real linearRate = 0, angularRate = 0;
    for (const Damping& damping : world.dampings)
        if (dynamic && (damping.body == index || damping.body < 0)) linearRate += damping.linear, angularRate += damping.angular;
    info.m_linearDamping = bulletDamping(linearRate);
    info.m_angularDamping = bulletDamping(angularRate);
    auto rigid = std::make_unique<btRigidBody>(info);
    if (motion) {
        rigid->setLinearVelocity(btVec(motion->linearVelocity));
        rigid->setAngularVelocity(btVec(motion->angularVelocity));
    }
    if (shape.internalEdges)  // Bullet calls the contact-added callback for this body's contacts
        rigid->setCollisionFlags(rigid->getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
    if (body.type == BodyType::Kinematic)
        rigid->setCollisionFlags(rigid->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    if (body.type != BodyType::Static) rigid->setActivationState(DISABLE_DEACTIVATION);
    return rigid;
}

/// A dynamic body's gyroscopic term and continuous collision, as the world's settings ask.
void setDynamics(btRigidBody& rigid, const Body& body, const Settings& settings) {
    const int gyroscopic[] = {0, BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT, BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY};
    rigid.setFlags(gyroscopic[int(settings.gyroscopic)]);
    if (settings.ccd == CcdMode::Off) return;
    // Bullet's continuous collision: a swept sphere for bodies moving more than half their
    // smallest extent in a step (the engine's auto rule, chapter 7).
    const Aabb box = computeAabb(body.shape, Transform{});
    const Real smallestHalf = box.extents().minCoeff();
    rigid.setCcdMotionThreshold(btScalar(smallestHalf));
    rigid.setCcdSweptSphereRadius(btScalar(Real(0.8) * smallestHalf));
}

}  // namespace

void addBodies(BulletScene& scene, const World& world, bool internalEdges) {
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        std::unique_ptr<btRigidBody> rigid = makeBody(scene, world, int(i), internalEdges);
        if (world.bodies[i].type == BodyType::Dynamic) setDynamics(*rigid, world.bodies[i], world.settings);
        scene.dynamics.addRigidBody(rigid.get());
        scene.bodies.push_back(std::move(rigid));
    }
}

void addJoints(BulletScene& scene, const World& world, btScalar subDt) {
    for (const JointDesc& joint : world.joints) {
        btRigidBody& a = *scene.bodies[std::size_t(joint.bodyA)];
        btRigidBody& b = *scene.bodies[std::size_t(joint.bodyB)];
        // At rest B's orientation in A is referenceRotation, so a frame with axes F in A has
        // axes referenceRotation^-1 F in B.
        const Mat3 toB = joint.referenceRotation.normalized().conjugate().toRotationMatrix();
        auto frames = [&](const Mat3& basisA) {
            return std::make_pair(scene.jointFrame(joint.bodyA, joint.localAnchorA, basisA),
                                  scene.jointFrame(joint.bodyB, joint.localAnchorB, toB * basisA));
        };
        std::unique_ptr<btTypedConstraint> made;
        switch (joint.type) {
            case JointType::Distance: break;  // refused by checkSupported
            case JointType::BallSocket: {
                const auto [inA, inB] = frames(Mat3::Identity());
                made = std::make_unique<btPoint2PointConstraint>(a, b, inA.getOrigin(), inB.getOrigin());
                break;
            }
            case JointType::Hinge: {
                const auto [inA, inB] = frames(axisFrame(joint.axis, 2));
                auto hinge = std::make_unique<btHingeConstraint>(a, b, inA, inB, false);
                // Bullet's hinge angle (and motor speed) count A turning against B: the engine's
                // with the sign flipped.
                if (joint.limits) hinge->setLimit(btScalar(-joint.limits->second), btScalar(-joint.limits->first));
                if (joint.motor)
                    hinge->enableAngularMotor(true, btScalar(-joint.motor->speed), btScalar(joint.motor->maxForce) * subDt);
                else if (joint.frictionTorque > 0)  // joint friction: a motor of speed zero, as the engine does
                    hinge->enableAngularMotor(true, 0, btScalar(joint.frictionTorque) * subDt);
                made = std::move(hinge);
                break;
            }
            case JointType::ConeTwist: {
                // Bullet's twist limit is symmetric: turn A's frame to the middle of [lo, hi].
                const Real lo = joint.twistLimits ? joint.twistLimits->first : -kPi;
                const Real hi = joint.twistLimits ? joint.twistLimits->second : kPi;
                const Mat3 basis = axisFrame(joint.axis, 0);
                const Mat3 middle = basis * Eigen::AngleAxis<Real>(Real(0.5) * (lo + hi), Vec3::UnitX()).toRotationMatrix();
                const btTransform inA = scene.jointFrame(joint.bodyA, joint.localAnchorA, middle);
                const btTransform inB = scene.jointFrame(joint.bodyB, joint.localAnchorB, toB * basis);
                auto cone = std::make_unique<btConeTwistConstraint>(a, b, inA, inB);
                cone->setLimit(btScalar(joint.coneAngle), btScalar(joint.coneAngle), btScalar(Real(0.5) * (hi - lo)));
                made = std::move(cone);
                break;
            }
            case JointType::Slider: {
                const auto [inA, inB] = frames(axisFrame(joint.axis, 0));
                auto slider = std::make_unique<btSliderConstraint>(a, b, inA, inB, true);
                if (joint.limits) {
                    slider->setLowerLinLimit(btScalar(joint.limits->first));
                    slider->setUpperLinLimit(btScalar(joint.limits->second));
                } else {  // lower above upper: free (Bullet's convention)
                    slider->setLowerLinLimit(1);
                    slider->setUpperLinLimit(-1);
                }
                if (joint.motor) {
                    slider->setPoweredLinMotor(true);
                    slider->setTargetLinMotorVelocity(btScalar(joint.motor->speed));
                    slider->setMaxLinMotorForce(btScalar(joint.motor->maxForce));
                }
                made = std::move(slider);
                break;
            }
            case JointType::Fixed: {
                const auto [inA, inB] = frames(Mat3::Identity());
                made = std::make_unique<btFixedConstraint>(a, b, inA, inB);
                break;
            }
        }
        scene.dynamics.addConstraint(made.get(), !joint.collideConnected);
        scene.joints.push_back(std::move(made));
    }
}

}  // namespace stepwise::peers::detail
