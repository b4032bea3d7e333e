// Scene files in (docs/scene-format.md); scene_save.cpp writes them. Loading is strict on purpose: a scene is
// written by hand, and a typo that is silently ignored ("hlaf_extents") costs an afternoon of
// wondering why the box is a point. So every value is read through a JsonCursor that knows its
// own JSON path, every object rejects keys it does not know, and every rejection names its
// value: "bodies[3].shape.box.half_extents[1]: must be > 0". Reading goes on after a rejection
// (ErrorList), so a file reports all its errors at once, up to a limit.

#include "world/json_reader.h"
#include "world/scene.h"

#include <filesystem>
#include <map>
#include <ostream>

namespace stepwise {
namespace {

const Names<bool> kContactPoints = {{"manifold", true}, {"one_point", false}};

Settings readSettings(const JsonCursor& cursor, ErrorList& errors) {
    cursor.expectObject({"gravity", "dt", "substeps", "solver_iterations", "baumgarte", "slop", "warm_starting",
                         "broadphase", "ccd", "integrator", "gyroscopic", "solver", "restitution_threshold", "stabilisation", "contact_points",
                         "sleeping", "sleep_speed", "time_to_sleep", "contact_hertz", "contact_damping_ratio",
                         "joint_hertz", "joint_damping_ratio", "max_push_out_speed", "bounds_margin",
                         "active_edges", "plan_iterations"},
                        &errors);
    Settings settings;
    // Each key on its own: one bad value does not hide the next.
    const auto read = [&](const char* key, auto assign) {
        if (auto v = cursor.optional(key)) errors.attempt([&] { assign(*v); });
    };
    read("gravity", [&](const JsonCursor& v) { settings.gravity = v.vec3Within(kMaxGravity); });
    read("dt", [&](const JsonCursor& v) { settings.dt = v.positiveAtMost(1); });
    read("substeps", [&](const JsonCursor& v) { settings.substeps = v.integer(1, 64); });
    read("solver_iterations", [&](const JsonCursor& v) {
        if (v.json().is_string() && v.json().get<std::string>() == "auto") return;  // the default
        if (v.json().is_string()) v.fail("must be \"auto\" or an integer");
        settings.solverIterations = v.integer(0, 1000);
        // The core format's default written out is the default: a scene that states every
        // default (as the format's own example does) runs as one that states none. Any other
        // number is the count as it stands; plan_iterations says otherwise for either.
        settings.planIterations = settings.solverIterations == Settings{}.solverIterations;
    });
    read("plan_iterations", [&](const JsonCursor& v) { settings.planIterations = v.boolean(); });
    read("baumgarte", [&](const JsonCursor& v) { settings.baumgarte = v.inRange(0, 1); });
    read("slop", [&](const JsonCursor& v) { settings.slop = v.nonNegative(); });
    read("restitution_threshold", [&](const JsonCursor& v) { settings.restitutionThreshold = v.nonNegative(); });
    read("warm_starting", [&](const JsonCursor& v) { settings.warmStarting = v.boolean(); });
    read("broadphase", [&](const JsonCursor& v) { settings.broadphase = v.choice(kBroadphaseNames); });
    read("ccd", [&](const JsonCursor& v) { settings.ccd = v.choice(kCcdNames); });
    read("integrator", [&](const JsonCursor& v) { settings.integrator = v.choice(kIntegratorNames); });
    read("gyroscopic", [&](const JsonCursor& v) { settings.gyroscopic = v.choice(kGyroscopicNames); });
    read("solver", [&](const JsonCursor& v) { settings.solver = v.choice(kSolverNames); });
    read("stabilisation", [&](const JsonCursor& v) { settings.stabilisation = v.choice(kStabilisationNames); });
    read("contact_points", [&](const JsonCursor& v) { settings.manifoldContacts = v.choice(kContactPoints); });
    read("sleeping", [&](const JsonCursor& v) { settings.sleeping = v.boolean(); });
    read("sleep_speed", [&](const JsonCursor& v) { settings.sleepSpeed = v.positive(); });
    read("time_to_sleep", [&](const JsonCursor& v) { settings.timeToSleep = v.positive(); });
    read("contact_hertz", [&](const JsonCursor& v) { settings.contactHertz = v.positive(); });
    read("contact_damping_ratio", [&](const JsonCursor& v) { settings.contactDampingRatio = v.nonNegative(); });
    read("joint_hertz", [&](const JsonCursor& v) { settings.jointHertz = v.positive(); });
    read("joint_damping_ratio", [&](const JsonCursor& v) { settings.jointDampingRatio = v.nonNegative(); });
    read("max_push_out_speed", [&](const JsonCursor& v) { settings.maxPushOutSpeed = v.positive(); });
    read("bounds_margin", [&](const JsonCursor& v) { settings.boundsMargin = v.nonNegative(); });
    read("active_edges", [&](const JsonCursor& v) { settings.activeEdges = v.boolean(); });
    return settings;
}

/// Resolves a body name that a joint or force refers to.
int bodyIndex(const JsonCursor& cursor, const World& world) {
    const std::string name = cursor.string();
    const int index = world.findBody(name);
    if (index >= 0) return index;
    std::string known;
    for (std::size_t i = 0; i < world.bodies.size() && i < 8; ++i) known += (i ? ", " : "") + world.bodies[i].name;
    if (world.bodies.size() > 8) known += ", ...";
    cursor.fail("unknown body \"" + name + "\" (bodies: " + (known.empty() ? "none" : known) + ")");
}

// [ch08-joint-keys]
/// The keys each joint type accepts beyond type, a, b, anchors and collide_connected.
std::vector<const char*> jointKeys(JointType type) {
    switch (type) {
        case JointType::Distance: return {"length", "spring_hertz", "spring_damping_ratio"};
        case JointType::BallSocket: return {};
        case JointType::Hinge: return {"axis", "limits", "motor", "friction_torque", "reference_rotation"};
        case JointType::ConeTwist: return {"axis", "cone_angle", "twist_limits", "friction_torque", "reference_rotation"};
        case JointType::Slider: return {"axis", "limits", "motor", "reference_rotation"};
        case JointType::Fixed: return {"reference_rotation"};
    }
    return {};
}
// [ch08-joint-keys]

/// An angle interval [lo, hi] within [-pi, pi] (hinge limits, twist limits).
std::pair<Real, Real> angleInterval(const JsonCursor& cursor) {
    const std::pair<Real, Real> interval = cursor.interval();
    if (interval.first < -kPi || interval.second > kPi) cursor.fail("must lie within [-pi, pi] radians");
    return interval;
}

JointMotor readMotor(const JsonCursor& cursor, JointType type) {
    const char* forceKey = type == JointType::Hinge ? "max_torque" : "max_force";
    cursor.expectObject({"speed", forceKey});
    JointMotor motor;
    motor.speed = cursor.child("speed").within(kMaxSpeed);
    motor.maxForce = cursor.child(forceKey).inRange(0, kMaxForce);
    return motor;
}

// Whatever the file leaves out that the bodies' poses at load decide: the rest orientation and a
// distance joint's length.
void completeJointFromPoses(JointDesc& joint, const World& world, bool hasReference) {
    const Transform& poseA = world.bodies[static_cast<std::size_t>(joint.bodyA)].transform;
    const Transform& poseB = world.bodies[static_cast<std::size_t>(joint.bodyB)].transform;
    if (!hasReference) joint.referenceRotation = poseA.rotation.conjugate() * poseB.rotation;
    if (joint.type == JointType::Distance && !joint.length)
        joint.length = (poseB.apply(joint.localAnchorB) - poseA.apply(joint.localAnchorA)).norm();
}

JointDesc readJoint(const JsonCursor& cursor, const World& world, ErrorList& errors) {
    if (!cursor.json().is_object()) cursor.fail("must be an object");
    JointDesc joint;
    joint.type = cursor.child("type").choice(kJointTypeNames);
    std::vector<const char*> keys = {"type", "a", "b", "anchor_a", "anchor_b", "collide_connected"};
    for (const char* key : jointKeys(joint.type)) keys.push_back(key);
    cursor.expectObject(keys, &errors);
    const bool foundA = errors.attempt([&] { joint.bodyA = bodyIndex(cursor.child("a"), world); });
    const bool foundB = errors.attempt([&] { joint.bodyB = bodyIndex(cursor.child("b"), world); });
    if (foundA && foundB && joint.bodyA == joint.bodyB)
        errors.attempt([&] { cursor.child("b").fail("a joint needs two different bodies"); });
    const auto read = [&](const char* key, auto assign) {
        if (auto v = cursor.optional(key)) errors.attempt([&] { assign(*v); });
    };
    read("anchor_a", [&](const JsonCursor& v) { joint.localAnchorA = v.vec3Within(kMaxCoordinate); });
    read("anchor_b", [&](const JsonCursor& v) { joint.localAnchorB = v.vec3Within(kMaxCoordinate); });
    read("collide_connected", [&](const JsonCursor& v) { joint.collideConnected = v.boolean(); });
    read("length", [&](const JsonCursor& v) { joint.length = v.inRange(0, kMaxCoordinate); });
    read("spring_hertz", [&](const JsonCursor& v) { joint.springHertz = v.inRange(0, kMaxJointHertz); });
    read("spring_damping_ratio", [&](const JsonCursor& v) { joint.springDampingRatio = v.inRange(0, kMaxDampingRatio); });
    read("axis", [&](const JsonCursor& v) {
        const Vec3 axis = v.vec3Within(kMaxCoordinate);
        if (axis.norm() < Real(1e-6)) v.fail("must not be zero");
        joint.axis = axis.normalized();
    });
    read("limits", [&](const JsonCursor& v) {
        joint.limits = joint.type == JointType::Hinge ? angleInterval(v) : v.interval();
        if (joint.type == JointType::Slider && (std::abs(joint.limits->first) > kMaxCoordinate ||
                                                std::abs(joint.limits->second) > kMaxCoordinate))
            v.fail("must lie within [-" + std::to_string(int(kMaxCoordinate)) + ", " + std::to_string(int(kMaxCoordinate)) + "] m");
    });
    read("motor", [&](const JsonCursor& v) { joint.motor = readMotor(v, joint.type); });
    read("cone_angle", [&](const JsonCursor& v) { joint.coneAngle = v.inRange(0, kPi); });
    read("twist_limits", [&](const JsonCursor& v) { joint.twistLimits = angleInterval(v); });
    read("friction_torque", [&](const JsonCursor& v) { joint.frictionTorque = v.inRange(0, kMaxForce); });
    bool hasReference = false;
    read("reference_rotation", [&](const JsonCursor& v) {
        // Kept as written when it is unit to float precision: normalising again may move the last
        // bit, and a saved scene would not load back to itself.
        const Quat unit = v.unitQuaternion();
        const Quat written(v.element(3).number(), v.element(0).number(), v.element(1).number(), v.element(2).number());
        joint.referenceRotation = std::abs(written.norm() - 1) < Real(1e-6) ? written : unit;
        hasReference = true;
    });
    if (foundA && foundB && joint.bodyA != joint.bodyB) completeJointFromPoses(joint, world, hasReference);
    return joint;
}

void readForce(const JsonCursor& cursor, World& world) {
    if (!cursor.json().is_object()) cursor.fail("must be an object");
    const JsonCursor type = cursor.child("type");
    const std::string kind = type.string();
    if (kind == "damping") {
        cursor.expectObject({"type", "body", "linear", "angular"});
        Damping damping;
        if (auto v = cursor.optional("body")) damping.body = bodyIndex(*v, world);
        if (auto v = cursor.optional("linear")) damping.linear = v->nonNegative();
        if (auto v = cursor.optional("angular")) damping.angular = v->nonNegative();
        world.dampings.push_back(damping);
        return;
    }
    if (kind != "spring") type.fail("must be one of \"spring\", \"damping\" (got \"" + kind + "\")");
    cursor.expectObject({"type", "a", "b", "anchor_a", "anchor_b", "rest_length", "stiffness", "damping"});
    Spring spring;
    spring.bodyA = bodyIndex(cursor.child("a"), world);
    if (auto v = cursor.optional("b")) spring.bodyB = bodyIndex(*v, world);
    if (spring.bodyA == spring.bodyB) cursor.child("b").fail("a spring needs two different bodies");
    if (auto v = cursor.optional("anchor_a")) spring.localAnchorA = v->vec3Within(kMaxCoordinate);
    if (auto v = cursor.optional("anchor_b")) spring.anchorB = v->vec3Within(kMaxCoordinate);
    spring.stiffness = cursor.child("stiffness").nonNegative();
    if (auto v = cursor.optional("damping")) spring.damping = v->nonNegative();
    // Without a rest length the spring starts relaxed: the anchors' distance at load time.
    const Vec3 pointA = world.bodies[std::size_t(spring.bodyA)].transform.apply(spring.localAnchorA);
    const Vec3 pointB =
        spring.bodyB < 0 ? spring.anchorB : world.bodies[std::size_t(spring.bodyB)].transform.apply(spring.anchorB);
    spring.restLength = (pointB - pointA).norm();
    if (auto v = cursor.optional("rest_length")) spring.restLength = v->inRange(0, kMaxCoordinate);
    world.springs.push_back(spring);
}

// The bodies, each key checked on its own (readBodyDef); names must be unique.
void readBodies(const JsonCursor& bodies, World& world, ErrorList& errors, const std::string& baseDirectory) {
    std::map<std::string, std::size_t> firstUse;
    for (std::size_t i = 0; i < bodies.arraySizeAtMost(kMaxBodies); ++i) {
        const JsonCursor cursor = bodies.element(i);
        if (!cursor.json().is_object()) {
            errors.attempt([&] { cursor.fail("must be an object"); });
            continue;
        }
        const std::size_t errorsBefore = errors.size();
        const BodyDef def = readBodyDef(cursor, i, errors, baseDirectory);
        if (auto [it, fresh] = firstUse.emplace(def.name, i); !fresh) {
            const std::string other = "bodies[" + std::to_string(it->second) + "]";
            errors.attempt([&] {
                if (cursor.has("name")) cursor.child("name").fail("duplicate name \"" + def.name + "\" (also " + other + ")");
                cursor.fail("its default name \"" + def.name + "\" is taken by " + other + "; give it a name");
            });
        }
        const bool added = errors.attempt([&] {
            try {
                addBody(world, def);
            } catch (const std::invalid_argument& error) {
                cursor.fail(error.what());
            }
        });
        // Sizes that are each fine can still overflow a volume or an inertia (r^5 m).
        const Motion* motion = added ? world.motionOf(int(world.bodies.size()) - 1) : nullptr;
        if (errors.size() == errorsBefore && motion &&
            !(std::isfinite(motion->mass) && std::isfinite(motion->inverseMass) && motion->inertiaLocal.allFinite() &&
              motion->inverseInertiaLocal.allFinite()))
            errors.attempt([&] {
                cursor.fail("its mass or inertia is not a finite number (sizes, mass or density too large or too small)");
            });
    }
}

/// "generator": { "<name>": { parameters } }: exactly one generator the program knows.
void runGenerator(const JsonCursor& cursor, const SceneGenerators& generators, World& world) {
    if (!cursor.json().is_object() || cursor.json().size() != 1)
        cursor.fail("must be an object with one key, the generator's name: { \"stress\": { ... } }");
    const std::string name = cursor.json().begin().key();
    const auto generator = generators.find(name);
    if (generator == generators.end()) {
        std::string known;
        for (const auto& entry : generators) known += std::string(known.empty() ? "" : ", ") + "\"" + entry.first + "\"";
        cursor.fail("unknown generator \"" + name + "\" (" + (known.empty() ? "this program knows none" : "known: " + known) + ")");
    }
    generator->second(world, cursor.child(name.c_str()));
}

World loadScene(const std::string& jsonText, const std::string& source, const std::string& defaultName,
                const SceneGenerators& generators) {
    const Json document = parseStrictJson(jsonText, source);
    const JsonCursor root(document, "");
    if (!document.is_object()) root.fail("a scene must be a JSON object { ... }");
    ErrorList errors;
    root.expectObject({"format", "version", "name", "description", "settings", "bodies", "generator", "joints", "forces"},
                      &errors);
    errors.attempt([&] {
        if (auto v = root.optional("format"); v && v->string() != "stepwise-scene") v->fail("must be \"stepwise-scene\"");
    });
    errors.attempt([&] {
        if (auto v = root.optional("version"); v && v->integer(0, 1 << 30) != 1)
            v->fail("unsupported version " + v->json().dump() + " (this engine reads version 1)");
    });
    errors.attempt([&] {
        if (auto v = root.optional("description")) v->string();
    });

    World world;
    world.name = defaultName;
    errors.attempt([&] {
        if (auto v = root.optional("name")) world.name = v->string();
    });
    errors.attempt([&] {
        if (auto v = root.optional("settings")) world.settings = readSettings(*v, errors);
    });
    // Joints and forces name bodies: without the body list they could only add false alarms.
    const bool bodiesRead = errors.attempt([&] {
        // A mesh's "obj" file is named relative to the scene file's folder.
        const std::string baseDirectory = std::filesystem::path(source).parent_path().string();
        if (auto bodies = root.optional("bodies")) readBodies(*bodies, world, errors, baseDirectory);
    });
    if (bodiesRead) {
        // Generated bodies come after the listed ones, so joints and forces can name either.
        errors.attempt([&] {
            if (auto generator = root.optional("generator")) runGenerator(*generator, generators, world);
        });
        errors.attempt([&] {
            if (auto joints = root.optional("joints"))
                for (std::size_t i = 0; i < joints->arraySizeAtMost(kMaxJoints); ++i)
                    errors.attempt([&] { world.joints.push_back(readJoint(joints->element(i), world, errors)); });
        });
        errors.attempt([&] {
            if (auto forces = root.optional("forces"))
                for (std::size_t i = 0; i < forces->arraySizeAtMost(kMaxForces); ++i)
                    errors.attempt([&] { readForce(forces->element(i), world); });
        });
    }
    errors.throwIfAny();
    return world;
}

}  // namespace

void printSceneError(std::ostream& out, const SceneError& error) {
    for (const SceneIssue& issue : error.issues()) out << "error: " << issue.text() << "\n";
    if (error.truncated()) out << "error: stopped after " << error.issues().size() << " errors\n";
}

World loadSceneFromString(const std::string& jsonText, const std::string& source, const SceneGenerators& generators) {
    return loadScene(jsonText, source, "untitled", generators);
}

World loadSceneFile(const std::string& path, const SceneGenerators& generators) {
    return loadScene(readInputFile(path, "a scene file"), path, std::filesystem::path(path).stem().string(), generators);
}

}  // namespace stepwise
