#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stepwise {

const Names<BodyType> kBodyTypeNames = {
    {"static", BodyType::Static}, {"kinematic", BodyType::Kinematic}, {"dynamic", BodyType::Dynamic}};

const char* toString(BodyType type) { return nameOf(kBodyTypeNames, type); }

const Contact* findContact(const std::vector<Contact>& contacts, const BodyPair& pair) {
    const auto at = std::lower_bound(contacts.begin(), contacts.end(), pair,
                                     [](const Contact& contact, const BodyPair& key) { return contact.pair() < key; });
    return at != contacts.end() && at->pair() == pair ? &*at : nullptr;
}

World emptyWorld(const std::string& name, const Vec3& gravity) {
    World world;
    world.name = name;
    world.settings.gravity = gravity;
    return world;
}

int World::findBody(const std::string& bodyName) const {
    for (size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].name == bodyName) return static_cast<int>(i);
    return -1;
}

int World::dynamicBodyCount() const {
    int count = 0;
    for (const Body& body : bodies) count += body.type == BodyType::Dynamic;
    return count;
}

int addStaticBox(World& world, const std::string& name, const Vec3& position, const Vec3& halfExtents,
                 const Quat& rotation, const Material& material) {
    BodyDef def;
    def.name = name;
    def.type = BodyType::Static;
    def.shape = Shape::box(halfExtents);
    def.transform.position = position;
    def.transform.rotation = rotation;
    def.material = material;
    return addBody(world, def);
}

// [foundation-add-body]
int addBody(World& world, const BodyDef& def) {
    Body body;
    body.name = def.name.empty() ? "body" + std::to_string(world.bodies.size()) : def.name;
    body.type = def.type;
    body.shape = def.shape;
    body.transform = def.transform;
    body.transform.rotation.normalize();
    body.material = def.material;
    body.bullet = def.bullet;
    const int bodyIndex = static_cast<int>(world.bodies.size());

    if (def.type != BodyType::Static) {
        Motion motion;
        motion.bodyIndex = bodyIndex;
        motion.linearVelocity = def.linearVelocity;
        motion.angularVelocity = def.angularVelocity;
        motion.integrator = def.integrator;
        if (def.type == BodyType::Dynamic) {
            const Real volume = shapeVolume(def.shape);
            if (!(volume > 0)) throw std::invalid_argument("body '" + body.name + "': shape has no volume");
            const Real density = def.mass ? *def.mass / volume : def.density;
            if (!(density > 0) || !std::isfinite(density))
                throw std::invalid_argument("body '" + body.name + "': mass and density must be > 0");
            const MassProperties props = computeMassProperties(def.shape, density);
            motion.mass = props.mass;
            motion.inverseMass = 1 / props.mass;
            motion.localCenter = props.localCenter;
            motion.inertiaLocal = props.inertia;
            motion.inverseInertiaLocal = props.inertia.inverse();
        }
        body.motionIndex = static_cast<int>(world.motions.size());
        world.motions.push_back(motion);
    }
    if (def.path && def.type == BodyType::Kinematic) {
        KinematicPath path = *def.path;
        path.body = bodyIndex;
        path.center = def.transform.position - path.amplitude * math::sin(path.phase);
        world.kinematicPaths.push_back(path);
    }
    world.bodies.push_back(std::move(body));
    return bodyIndex;
}
// [foundation-add-body]

// A flood fill from the body through the sleeping bodies it touches or is tied to. Each woken
// body scans the contacts, joints and springs once: O(island x links), fine for one edit; the
// step's own wake-up (chapter 10, sleep.cpp) does the whole world at once with union-find.
void wakeBody(World& world, int bodyIndex) {
    const auto valid = [&](int index) { return index >= 0 && std::size_t(index) < world.bodies.size(); };
    if (!valid(bodyIndex)) return;
    Motion* motion = world.motionOf(bodyIndex);
    if (!motion) return;
    motion->sleepTime = 0;
    if (!motion->asleep) return;
    motion->asleep = false;
    std::vector<int> stack{bodyIndex};
    const auto wake = [&](int other) {
        if (!valid(other)) return;
        Motion* otherMotion = world.motionOf(other);
        if (!otherMotion || !otherMotion->asleep) return;
        otherMotion->asleep = false;
        otherMotion->sleepTime = 0;
        stack.push_back(other);
    };
    const auto visitLink = [&](int body, int a, int b) {
        if (a == body) wake(b);
        else if (b == body) wake(a);
    };
    while (!stack.empty()) {
        const int body = stack.back();
        stack.pop_back();
        for (const Contact& contact : world.contacts)
            if (contact.pointCount > 0) visitLink(body, contact.bodyA, contact.bodyB);
        for (const JointDesc& joint : world.joints) visitLink(body, joint.bodyA, joint.bodyB);
        for (const Spring& spring : world.springs)
            if (spring.bodyB >= 0) visitLink(body, spring.bodyA, spring.bodyB);
    }
}

Vec3 worldCenterOfMass(const World& world, int bodyIndex) {
    const Body& body = world.bodies[bodyIndex];
    const Motion* motion = world.motionOf(bodyIndex);
    return motion ? body.transform.apply(motion->localCenter) : body.transform.position;
}

Mat3 worldInverseInertia(const Body& body, const Motion& motion) {
    const Mat3 rotation = body.transform.rotation.toRotationMatrix();
    return rotation * motion.inverseInertiaLocal * rotation.transpose();
}

const Names<JointType> kJointTypeNames = {{"distance", JointType::Distance},   {"ball_socket", JointType::BallSocket},
                                          {"hinge", JointType::Hinge},         {"cone_twist", JointType::ConeTwist},
                                          {"slider", JointType::Slider},       {"fixed", JointType::Fixed}};

const char* toString(JointType type) { return nameOf(kJointTypeNames, type); }

Energy computeEnergy(const World& world, const std::function<bool(int bodyIndex)>& countsBody) {
    const auto counts = [&](int bodyIndex) { return !countsBody || countsBody(bodyIndex); };
    Energy energy;
    for (const Motion& motion : world.motions) {
        const Body& body = world.bodies[motion.bodyIndex];
        if (body.type != BodyType::Dynamic || !counts(motion.bodyIndex)) continue;
        const Mat3 rotation = body.transform.rotation.toRotationMatrix();
        const Vec3 angularLocal = rotation.transpose() * motion.angularVelocity;
        energy.kinetic += 0.5 * motion.mass * motion.linearVelocity.squaredNorm() +
                          0.5 * angularLocal.dot(motion.inertiaLocal * angularLocal);
        energy.gravity -= motion.mass * world.settings.gravity.dot(body.transform.apply(motion.localCenter));
    }
    for (const Spring& spring : world.springs) {
        if (!counts(spring.bodyA)) continue;
        const Vec3 endA = world.bodies[spring.bodyA].transform.apply(spring.localAnchorA);
        const Vec3 endB = spring.bodyB < 0 ? spring.anchorB : world.bodies[spring.bodyB].transform.apply(spring.anchorB);
        const double stretch = (endB - endA).norm() - spring.restLength;
        energy.springs += 0.5 * spring.stiffness * stretch * stretch;
    }
    return energy;
}

}  // namespace stepwise
