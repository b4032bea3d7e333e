// Scene files in (docs/scene-format.md); scene_save.cpp writes them. Loading is strict on purpose: a scene is
// written by hand, and a typo that is silently ignored ("hlaf_extents") costs an afternoon of
// wondering why the box is a point. So every value is read through a JsonCursor that knows its
// own JSON path, every object rejects keys it does not know, and every rejection is ONE
// SceneError("bodies[3].shape.box.half_extents[1]", "must be > 0").

#include "world/json_reader.h"
#include "world/scene.h"

#include <filesystem>
#include <map>

namespace stepwise {
namespace {

const Names<BodyType> kBodyTypes = {
    {"static", BodyType::Static}, {"kinematic", BodyType::Kinematic}, {"dynamic", BodyType::Dynamic}};
const Names<IntegratorKind> kIntegrators = {{"semi_implicit_euler", IntegratorKind::SemiImplicitEuler},
                                            {"rk4", IntegratorKind::Rk4},
                                            {"verlet", IntegratorKind::Verlet}};
const Names<GyroscopicMode> kGyroscopic = {
    {"off", GyroscopicMode::Off}, {"explicit", GyroscopicMode::Explicit}, {"implicit", GyroscopicMode::Implicit}};
const Names<BroadphaseMode> kBroadphase = {
    {"auto", BroadphaseMode::Auto}, {"sap", BroadphaseMode::Sap}, {"brute", BroadphaseMode::Brute}};
const Names<CcdMode> kCcd = {{"auto", CcdMode::Auto}, {"on", CcdMode::On}, {"off", CcdMode::Off}};
const Names<SolverKind> kSolvers = {{"gauss_seidel", SolverKind::GaussSeidel}, {"jacobi", SolverKind::Jacobi}};
const Names<JointType> kJointTypes = {{"distance", JointType::Distance},
                                      {"ball_socket", JointType::BallSocket},
                                      {"hinge", JointType::Hinge},
                                      {"cone_twist", JointType::ConeTwist},
                                      {"fixed", JointType::Fixed}};

Settings readSettings(const JsonCursor& cursor) {
    cursor.expectObject({"gravity", "dt", "substeps", "solver_iterations", "baumgarte", "slop", "warm_starting",
                         "broadphase", "ccd", "integrator", "gyroscopic", "solver", "restitution_threshold"});
    Settings settings;
    if (auto v = cursor.optional("gravity")) settings.gravity = v->vec3Within(kMaxGravity);
    if (auto v = cursor.optional("dt")) settings.dt = v->positiveAtMost(1);
    if (auto v = cursor.optional("substeps")) settings.substeps = v->integer(1, 64);
    if (auto v = cursor.optional("solver_iterations")) settings.solverIterations = v->integer(0, 1000);
    if (auto v = cursor.optional("baumgarte")) settings.baumgarte = v->inRange(0, 1);
    if (auto v = cursor.optional("slop")) settings.slop = v->nonNegative();
    if (auto v = cursor.optional("restitution_threshold")) settings.restitutionThreshold = v->nonNegative();
    if (auto v = cursor.optional("warm_starting")) settings.warmStarting = v->boolean();
    if (auto v = cursor.optional("broadphase")) settings.broadphase = v->choice(kBroadphase);
    if (auto v = cursor.optional("ccd")) settings.ccd = v->choice(kCcd);
    if (auto v = cursor.optional("integrator")) settings.integrator = v->choice(kIntegrators);
    if (auto v = cursor.optional("gyroscopic")) settings.gyroscopic = v->choice(kGyroscopic);
    if (auto v = cursor.optional("solver")) settings.solver = v->choice(kSolvers);
    return settings;
}

BodyDef readBody(const JsonCursor& cursor, std::size_t index) {
    cursor.expectObject({"name", "type", "shape", "position", "orientation", "velocity", "angular_velocity", "mass",
                         "density", "friction", "restitution", "bullet", "integrator"});
    BodyDef def;
    def.name = "body" + std::to_string(index);
    if (auto v = cursor.optional("name")) def.name = v->nonEmptyString();
    if (auto v = cursor.optional("type")) def.type = v->choice(kBodyTypes);
    def.shape = readShape(cursor.child("shape"));
    if (auto v = cursor.optional("position")) def.transform.position = v->vec3Within(kMaxCoordinate);
    if (auto v = cursor.optional("orientation")) def.transform.rotation = v->unitQuaternion();
    if (def.type == BodyType::Static)
        for (const char* key : {"velocity", "angular_velocity", "integrator"})
            if (cursor.has(key)) cursor.child(key).fail("not allowed on a static body (it never moves)");
    if (def.type != BodyType::Dynamic)
        for (const char* key : {"mass", "density"})
            if (cursor.has(key))
                cursor.child(key).fail(std::string("only dynamic bodies have mass (this body is ") +
                                       toString(def.type) + ")");
    if (cursor.has("mass") && cursor.has("density")) cursor.child("density").fail("give mass or density, not both");
    if (auto v = cursor.optional("velocity")) def.linearVelocity = v->vec3Within(kMaxSpeed);
    if (auto v = cursor.optional("angular_velocity")) def.angularVelocity = v->vec3Within(kMaxAngularSpeed);
    if (auto v = cursor.optional("mass")) def.mass = v->positiveBetween(kMinMass, kMaxMass);
    if (auto v = cursor.optional("density")) def.density = v->positiveBetween(kMinDensity, kMaxDensity);
    if (auto v = cursor.optional("friction")) def.material.friction = v->nonNegative();
    if (auto v = cursor.optional("restitution")) def.material.restitution = v->inRange(0, 1);
    if (auto v = cursor.optional("bullet")) def.bullet = v->boolean();
    if (auto v = cursor.optional("integrator")) def.integrator = v->choice(kIntegrators);
    return def;
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

JointDesc readJoint(const JsonCursor& cursor, const World& world) {
    if (!cursor.json().is_object()) cursor.fail("must be an object");
    JointDesc joint;
    joint.type = cursor.child("type").choice(kJointTypes);
    std::vector<const char*> keys = {"type", "a", "b", "anchor_a", "anchor_b"};
    if (joint.type == JointType::Distance) keys.push_back("length");
    if (joint.type == JointType::Hinge) keys.insert(keys.end(), {"axis", "limits"});
    if (joint.type == JointType::ConeTwist) keys.insert(keys.end(), {"axis", "cone_angle", "twist_limits"});
    cursor.expectObject(keys);
    joint.bodyA = bodyIndex(cursor.child("a"), world);
    joint.bodyB = bodyIndex(cursor.child("b"), world);
    if (joint.bodyA == joint.bodyB) cursor.child("b").fail("a joint needs two different bodies");
    if (auto v = cursor.optional("anchor_a")) joint.localAnchorA = v->vec3Within(kMaxCoordinate);
    if (auto v = cursor.optional("anchor_b")) joint.localAnchorB = v->vec3Within(kMaxCoordinate);
    if (auto v = cursor.optional("length")) joint.length = v->inRange(0, kMaxCoordinate);
    if (auto v = cursor.optional("axis")) {
        const Vec3 axis = v->vec3();
        if (axis.norm() < Real(1e-6)) v->fail("must not be zero");
        joint.axis = axis.normalized();
    }
    if (auto v = cursor.optional("limits")) joint.limits = v->interval();
    if (auto v = cursor.optional("cone_angle")) joint.coneAngle = v->inRange(0, kPi);
    if (auto v = cursor.optional("twist_limits")) joint.twistLimits = v->interval();
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

World loadScene(const std::string& jsonText, const std::string& source, const std::string& defaultName) {
    const Json document = parseStrictJson(jsonText, source);
    const JsonCursor root(document, "");
    if (!document.is_object()) root.fail("a scene must be a JSON object { ... }");
    root.expectObject({"format", "version", "name", "description", "settings", "bodies", "joints", "forces"});
    if (auto v = root.optional("format"); v && v->string() != "stepwise-scene") v->fail("must be \"stepwise-scene\"");
    if (auto v = root.optional("version"); v && v->integer(0, 1 << 30) != 1)
        v->fail("unsupported version " + v->json().dump() + " (this engine reads version 1)");
    if (auto v = root.optional("description")) v->string();

    World world;
    world.name = defaultName;
    if (auto v = root.optional("name")) world.name = v->string();
    if (auto v = root.optional("settings")) world.settings = readSettings(*v);
    if (auto bodies = root.optional("bodies")) {
        std::map<std::string, std::size_t> firstUse;
        for (std::size_t i = 0; i < bodies->arraySizeAtMost(kMaxBodies); ++i) {
            const JsonCursor cursor = bodies->element(i);
            const BodyDef def = readBody(cursor, i);
            if (auto [it, fresh] = firstUse.emplace(def.name, i); !fresh) {
                const std::string other = "bodies[" + std::to_string(it->second) + "]";
                if (cursor.has("name"))
                    cursor.child("name").fail("duplicate name \"" + def.name + "\" (also " + other + ")");
                cursor.fail("its default name \"" + def.name + "\" is taken by " + other + "; give it a name");
            }
            try {
                addBody(world, def);
            } catch (const std::invalid_argument& error) {
                cursor.fail(error.what());
            }
            // Sizes that are each fine can still overflow a volume or an inertia (r^5 m).
            const Motion* motion = world.motionOf(int(i));
            if (motion && !(std::isfinite(motion->mass) && std::isfinite(motion->inverseMass) &&
                            motion->inertiaLocal.allFinite() && motion->inverseInertiaLocal.allFinite()))
                cursor.fail("its mass or inertia is not a finite number (sizes, mass or density too large or too small)");
        }
    }
    if (auto joints = root.optional("joints"))
        for (std::size_t i = 0; i < joints->arraySizeAtMost(kMaxJoints); ++i)
            world.joints.push_back(readJoint(joints->element(i), world));
    if (auto forces = root.optional("forces"))
        for (std::size_t i = 0; i < forces->arraySizeAtMost(kMaxForces); ++i) readForce(forces->element(i), world);
    return world;
}

}  // namespace

World loadSceneFromString(const std::string& jsonText, const std::string& source) {
    return loadScene(jsonText, source, "untitled");
}

World loadSceneFile(const std::string& path) {
    return loadScene(readInputFile(path, "a scene file"), path, std::filesystem::path(path).stem().string());
}

}  // namespace stepwise
