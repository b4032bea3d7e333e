// Scene files in and out (docs/scene-format.md). Loading is strict on purpose: a scene is
// written by hand, and a typo that is silently ignored ("hlaf_extents") costs an afternoon of
// wondering why the box is a point. So every value is read through a JsonCursor that knows its
// own JSON path, every object rejects keys it does not know, and every rejection is ONE
// SceneError("bodies[3].shape.box.half_extents[1]", "must be > 0").

#include "world/scene.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

namespace stepwise {
namespace {

using Json = nlohmann::ordered_json;  // keeps the author's key order for messages and saving

template <class E>
using Names = std::vector<std::pair<const char*, E>>;

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
const char* const kJointTypes[] = {"distance", "ball_socket", "hinge", "cone_twist", "fixed"};

/// "%g" for numbers inside messages.
std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

/// Levenshtein distance, to suggest "half_extents" for "hlaf_extents".
std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        }
    }
    return row[b.size()];
}

/// A JSON value together with its path from the document root. Each getter checks the type
/// and range of the value and throws SceneError(path(), message) when it is wrong.
class JsonCursor {
public:
    JsonCursor(const Json& value, std::string path) : value_(value), path_(std::move(path)) {}

    const Json& json() const { return value_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& message) const { throw SceneError(path_, message); }

    /// Checks that this is an object whose keys are all among `accepted`.
    void expectObject(const std::vector<const char*>& accepted) const {
        if (!value_.is_object()) fail("must be an object");
        for (const auto& item : value_.items()) {
            const auto known = [&](const char* key) { return item.key() == key; };
            if (std::none_of(accepted.begin(), accepted.end(), known)) fail(unknownKeyMessage(item.key(), accepted));
        }
    }
    bool has(const char* key) const { return value_.contains(key); }
    JsonCursor child(const char* key) const {
        if (!has(key)) fail(std::string("missing required key \"") + key + "\"");
        return JsonCursor(value_.at(key), path_.empty() ? key : path_ + "." + key);
    }
    std::optional<JsonCursor> optional(const char* key) const {
        return has(key) ? std::optional<JsonCursor>(child(key)) : std::nullopt;
    }
    /// Checks that this is an array and returns its size.
    std::size_t arraySize() const {
        if (!value_.is_array()) fail("must be an array");
        return value_.size();
    }
    JsonCursor element(std::size_t index) const {
        return JsonCursor(value_.at(index), path_ + "[" + std::to_string(index) + "]");
    }

    Real number() const {
        if (!value_.is_number()) fail("must be a number");
        const double value = value_.get<double>();
        if (!std::isfinite(value) || std::abs(value) > double(kRealMax)) fail("must be a finite number");
        return Real(value);
    }
    Real positive() const { return check(number() > 0, "must be > 0"); }
    Real positiveAtMost(Real high) const {
        const Real value = number();
        if (!(value > 0 && value <= high)) fail("must be > 0 and <= " + formatNumber(high));
        return value;
    }
    Real nonNegative() const { return check(number() >= 0, "must be >= 0"); }
    Real inRange(Real low, Real high) const {
        const Real value = number();
        if (value < low || value > high) fail("must be in [" + formatNumber(low) + ", " + formatNumber(high) + "]");
        return value;
    }
    int integer(int low, int high) const {
        const Real value = number();
        if (std::floor(value) != value) fail("must be an integer");
        if (value < Real(low) || value > Real(high))
            fail("must be an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
        return int(value);
    }
    bool boolean() const {
        if (!value_.is_boolean()) fail("must be true or false");
        return value_.get<bool>();
    }
    std::string string() const {
        if (!value_.is_string()) fail("must be a string");
        return value_.get<std::string>();
    }
    std::string nonEmptyString() const {
        if (string().empty()) fail("must not be empty");
        return string();
    }
    Vec3 vec3() const {
        if (!value_.is_array() || value_.size() != 3) fail("must be an array of 3 numbers [x, y, z]");
        return Vec3(element(0).number(), element(1).number(), element(2).number());
    }
    /// [lo, hi] with lo <= hi.
    std::pair<Real, Real> interval() const {
        if (!value_.is_array() || value_.size() != 2) fail("must be an array of 2 numbers [lo, hi]");
        const Real low = element(0).number();
        const Real high = element(1).number();
        if (low > high) fail("must be [lo, hi] with lo <= hi");
        return {low, high};
    }
    /// [x, y, z, w], normalised; rejected when its length is far from 1 (likely a typo).
    Quat unitQuaternion() const {
        if (!value_.is_array() || value_.size() != 4) fail("must be an array of 4 numbers [x, y, z, w]");
        const Eigen::Vector4d q(element(0).number(), element(1).number(), element(2).number(), element(3).number());
        if (std::abs(q.norm() - 1.0) > 1e-3)
            fail("must be a unit quaternion [x, y, z, w] (its length is " + formatNumber(q.norm()) + ")");
        const Eigen::Vector4d unit = q.normalized();
        return Quat(Real(unit.w()), Real(unit.x()), Real(unit.y()), Real(unit.z()));
    }
    template <class E>
    E choice(const Names<E>& names) const {
        const std::string text = string();
        for (const auto& [name, value] : names)
            if (text == name) return value;
        std::string accepted;
        for (const auto& entry : names)
            accepted += std::string(accepted.empty() ? "" : ", ") + "\"" + entry.first + "\"";
        fail("must be one of " + accepted + " (got \"" + text + "\")");
    }

private:
    Real check(bool ok, const char* message) const {
        if (!ok) fail(message);
        return Real(value_.get<double>());
    }
    static std::string unknownKeyMessage(const std::string& key, const std::vector<const char*>& accepted) {
        std::string message = "unknown key \"" + key + "\"";
        std::string list;
        const char* closest = nullptr;
        std::size_t closestDistance = 3;  // suggest only near misses
        for (const char* name : accepted) {
            list += std::string(list.empty() ? "" : ", ") + name;
            const std::size_t distance = editDistance(key, name);
            if (distance < closestDistance) closest = name, closestDistance = distance;
        }
        if (closest) message += "; did you mean \"" + std::string(closest) + "\"?";
        return message + " (accepted: " + (list.empty() ? "none" : list) + ")";
    }

    const Json& value_;
    std::string path_;
};

/// Parses JSON text. nlohmann keeps the last of two equal keys silently, so a parser callback
/// tracks the current path and rejects duplicates; the same path names a number that overflows.
Json parseJson(const std::string& text, const std::string& source) {
    struct Frame {
        bool isArray = false;
        std::size_t index = 0;
        std::string key;
        std::set<std::string> keys;
    };
    std::vector<Frame> frames;
    const auto currentPath = [&frames](bool withLastDesignator) {
        std::string path;
        for (std::size_t i = 0; i < frames.size(); ++i) {
            if (i + 1 == frames.size() && !withLastDesignator) break;
            const Frame& frame = frames[i];
            path += frame.isArray ? "[" + std::to_string(frame.index) + "]" : (path.empty() ? "" : ".") + frame.key;
        }
        return path;
    };
    const auto valueDone = [&frames] {
        if (!frames.empty() && frames.back().isArray) ++frames.back().index;
    };
    using Event = nlohmann::json::parse_event_t;
    const Json::parser_callback_t callback = [&](int, Event event, Json& parsed) {
        switch (event) {
        case Event::object_start: frames.push_back(Frame{}); break;
        case Event::array_start: frames.push_back(Frame{true, 0, {}, {}}); break;
        case Event::object_end:
        case Event::array_end: frames.pop_back(); valueDone(); break;
        case Event::value: valueDone(); break;
        case Event::key:
            frames.back().key = parsed.get<std::string>();
            if (!frames.back().keys.insert(frames.back().key).second)
                throw SceneError(currentPath(false), "duplicate key \"" + frames.back().key + "\"");
            break;
        }
        return true;
    };
    try {
        return Json::parse(text, callback);
    } catch (const nlohmann::json::parse_error& error) {
        // "[json.exception.parse_error.101] parse error at line 2, column 7: syntax error ..."
        const std::string what = error.what();
        const std::size_t line = what.find("line ");
        const std::string detail = line == std::string::npos ? what : what.substr(line);
        throw SceneError("", "malformed JSON in " + source + " at " + detail);
    } catch (const nlohmann::json::out_of_range&) {
        // Raised by the lexer for numbers such as 1e999 that overflow a double.
        throw SceneError(currentPath(true), "must be a finite number");
    }
}

Settings readSettings(const JsonCursor& cursor) {
    cursor.expectObject({"gravity", "dt", "substeps", "solver_iterations", "baumgarte", "slop", "warm_starting",
                         "broadphase", "ccd", "integrator", "gyroscopic", "solver", "restitution_threshold"});
    Settings settings;
    if (auto v = cursor.optional("gravity")) settings.gravity = v->vec3();
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

Shape readShape(const JsonCursor& cursor) {
    const std::vector<const char*> kinds = {"box", "sphere", "capsule", "convex"};
    if (!cursor.json().is_object() || cursor.json().size() != 1)
        cursor.fail("must hold exactly one of box, sphere, capsule, convex");
    const std::string kind = cursor.json().begin().key();
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
        cursor.fail("unknown shape kind \"" + kind + "\" (accepted: box, sphere, capsule, convex)");
    const JsonCursor params = cursor.child(kind.c_str());
    if (kind == "box") {
        params.expectObject({"half_extents"});
        const JsonCursor size = params.child("half_extents");
        const Vec3 halfExtents = size.vec3();
        for (int axis = 0; axis < 3; ++axis) size.element(std::size_t(axis)).positive();
        return Shape::box(halfExtents);
    }
    if (kind == "sphere") {
        params.expectObject({"radius"});
        return Shape::sphere(params.child("radius").positive());
    }
    if (kind == "capsule") {
        params.expectObject({"radius", "half_height"});
        const Real radius = params.child("radius").positive();
        return Shape::capsule(radius, params.child("half_height").positive());
    }
    params.expectObject({"vertices"});
    const JsonCursor list = params.child("vertices");
    std::vector<Vec3> points(list.arraySize());
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = list.element(i).vec3();
    if (points.size() < 4)
        list.fail("needs at least 4 points that span a volume (got " + std::to_string(points.size()) + ")");
    try {
        return Shape::convex(points);
    } catch (const HullError& error) {
        list.fail(error.message);
    }
}

BodyDef readBody(const JsonCursor& cursor, std::size_t index) {
    cursor.expectObject({"name", "type", "shape", "position", "orientation", "velocity", "angular_velocity", "mass",
                         "density", "friction", "restitution", "bullet", "integrator"});
    BodyDef def;
    def.name = "body" + std::to_string(index);
    if (auto v = cursor.optional("name")) def.name = v->nonEmptyString();
    if (auto v = cursor.optional("type")) def.type = v->choice(kBodyTypes);
    def.shape = readShape(cursor.child("shape"));
    if (auto v = cursor.optional("position")) def.transform.position = v->vec3();
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
    if (auto v = cursor.optional("velocity")) def.linearVelocity = v->vec3();
    if (auto v = cursor.optional("angular_velocity")) def.angularVelocity = v->vec3();
    if (auto v = cursor.optional("mass")) def.mass = v->positive();
    if (auto v = cursor.optional("density")) def.density = v->positive();
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
    const JsonCursor type = cursor.child("type");
    joint.type = type.string();
    std::vector<const char*> keys = {"type", "a", "b", "anchor_a", "anchor_b"};
    if (joint.type == "distance") keys.push_back("length");
    if (joint.type == "hinge") keys.insert(keys.end(), {"axis", "limits"});
    if (joint.type == "cone_twist") keys.insert(keys.end(), {"axis", "cone_angle", "twist_limits"});
    if (std::find(std::begin(kJointTypes), std::end(kJointTypes), joint.type) == std::end(kJointTypes))
        type.fail("must be one of \"distance\", \"ball_socket\", \"hinge\", \"cone_twist\", \"fixed\" (got \"" +
                  joint.type + "\")");
    cursor.expectObject(keys);
    joint.bodyA = bodyIndex(cursor.child("a"), world);
    joint.bodyB = bodyIndex(cursor.child("b"), world);
    if (joint.bodyA == joint.bodyB) cursor.child("b").fail("a joint needs two different bodies");
    if (auto v = cursor.optional("anchor_a")) joint.localAnchorA = v->vec3();
    if (auto v = cursor.optional("anchor_b")) joint.localAnchorB = v->vec3();
    if (auto v = cursor.optional("length")) joint.length = v->nonNegative();
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
    if (auto v = cursor.optional("anchor_a")) spring.localAnchorA = v->vec3();
    if (auto v = cursor.optional("anchor_b")) spring.anchorB = v->vec3();
    spring.stiffness = cursor.child("stiffness").nonNegative();
    if (auto v = cursor.optional("damping")) spring.damping = v->nonNegative();
    // Without a rest length the spring starts relaxed: the anchors' distance at load time.
    const Vec3 pointA = world.bodies[std::size_t(spring.bodyA)].transform.apply(spring.localAnchorA);
    const Vec3 pointB =
        spring.bodyB < 0 ? spring.anchorB : world.bodies[std::size_t(spring.bodyB)].transform.apply(spring.anchorB);
    spring.restLength = (pointB - pointA).norm();
    if (auto v = cursor.optional("rest_length")) spring.restLength = v->nonNegative();
    world.springs.push_back(spring);
}

World loadScene(const std::string& jsonText, const std::string& source, const std::string& defaultName) {
    const Json document = parseJson(jsonText, source);
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
        for (std::size_t i = 0; i < bodies->arraySize(); ++i) {
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
        for (std::size_t i = 0; i < joints->arraySize(); ++i)
            world.joints.push_back(readJoint(joints->element(i), world));
    if (auto forces = root.optional("forces"))
        for (std::size_t i = 0; i < forces->arraySize(); ++i) readForce(forces->element(i), world);
    return world;
}

/// The shortest decimal that reads back as the same Real: 0.1f saves as 0.1, not 0.10000000149.
/// Whole numbers print as integers ("1", not "1.0"); this also turns -0 into 0.
Json tidy(Real value) {
    if (std::floor(value) == value && std::abs(value) < Real(1e15)) return std::int64_t(value);
    if constexpr (std::is_same_v<Real, float>) {
        char text[32];
        for (int digits = 6; digits <= 9; ++digits) {
            std::snprintf(text, sizeof text, "%.*g", digits, double(value));
            const double parsed = std::strtod(text, nullptr);
            if (Real(parsed) == value) return parsed;
        }
    }
    return double(value);
}

Json toJson(const Vec3& v) { return Json::array({tidy(v.x()), tidy(v.y()), tidy(v.z())}); }
Json toJson(const Quat& q) { return Json::array({tidy(q.x()), tidy(q.y()), tidy(q.z()), tidy(q.w())}); }

Json shapeToJson(const Shape& shape) {
    switch (shape.type) {
    case ShapeType::Box: return {{"box", {{"half_extents", toJson(shape.halfExtents)}}}};
    case ShapeType::Sphere: return {{"sphere", {{"radius", tidy(shape.radius)}}}};
    case ShapeType::Capsule:
        return {{"capsule", {{"radius", tidy(shape.radius)}, {"half_height", tidy(shape.halfHeight)}}}};
    case ShapeType::Convex: break;
    }
    Json vertices = Json::array();
    if (shape.hull)
        for (const Vec3& vertex : shape.hull->vertices) vertices.push_back(toJson(vertex));
    return {{"convex", {{"vertices", vertices}}}};
}

const std::string& bodyName(const World& world, int index) {
    if (index < 0 || std::size_t(index) >= world.bodies.size())
        throw std::invalid_argument("saveSceneToString: body index " + std::to_string(index) + " out of range");
    return world.bodies[std::size_t(index)].name;
}

}  // namespace

World loadSceneFromString(const std::string& jsonText, const std::string& source) {
    return loadScene(jsonText, source, "untitled");
}

World loadSceneFile(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw SceneError(path, "no such file");
    if (std::filesystem::is_directory(path, error)) throw SceneError(path, "is a directory, not a scene file");
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    if (!file) throw SceneError(path, "cannot read the file");
    return loadScene(text.str(), path, std::filesystem::path(path).stem().string());
}

std::string saveSceneToString(const World& world) {
    const Settings& s = world.settings;
    Json scene = {{"format", "stepwise-scene"}, {"version", 1}, {"name", world.name}};
    scene["settings"] = {{"gravity", toJson(s.gravity)},
                         {"dt", tidy(s.dt)},
                         {"substeps", s.substeps},
                         {"solver_iterations", s.solverIterations},
                         {"baumgarte", tidy(s.baumgarte)},
                         {"slop", tidy(s.slop)},
                         {"warm_starting", s.warmStarting},
                         {"broadphase", toString(s.broadphase)},
                         {"ccd", toString(s.ccd)},
                         {"integrator", toString(s.integrator)},
                         {"gyroscopic", toString(s.gyroscopic)},
                         {"solver", toString(s.solver)},
                         {"restitution_threshold", tidy(s.restitutionThreshold)}};
    Json bodies = Json::array();
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        Json out = {{"name", body.name}, {"type", toString(body.type)}, {"shape", shapeToJson(body.shape)},
                    {"position", toJson(body.transform.position)}, {"orientation", toJson(body.transform.rotation)}};
        if (const Motion* motion = world.motionOf(int(i))) {
            out["velocity"] = toJson(motion->linearVelocity);
            out["angular_velocity"] = toJson(motion->angularVelocity);
            if (body.type == BodyType::Dynamic) out["mass"] = tidy(motion->mass);
            if (motion->integrator) out["integrator"] = toString(*motion->integrator);
        }
        out["friction"] = tidy(body.material.friction);
        out["restitution"] = tidy(body.material.restitution);
        if (body.bullet) out["bullet"] = true;
        bodies.push_back(out);
    }
    scene["bodies"] = bodies;
    Json joints = Json::array();
    for (const JointDesc& joint : world.joints) {
        Json out = {{"type", joint.type}, {"a", bodyName(world, joint.bodyA)}, {"b", bodyName(world, joint.bodyB)},
                    {"anchor_a", toJson(joint.localAnchorA)}, {"anchor_b", toJson(joint.localAnchorB)}};
        if (joint.type == "distance" && joint.length) out["length"] = tidy(*joint.length);
        if (joint.type == "hinge" || joint.type == "cone_twist") out["axis"] = toJson(joint.axis);
        if (joint.type == "hinge" && joint.limits)
            out["limits"] = {tidy(joint.limits->first), tidy(joint.limits->second)};
        if (joint.type == "cone_twist") out["cone_angle"] = tidy(joint.coneAngle);
        if (joint.type == "cone_twist" && joint.twistLimits)
            out["twist_limits"] = {tidy(joint.twistLimits->first), tidy(joint.twistLimits->second)};
        joints.push_back(out);
    }
    if (!joints.empty()) scene["joints"] = joints;
    Json forces = Json::array();
    for (const Spring& spring : world.springs) {
        Json out = {{"type", "spring"}, {"a", bodyName(world, spring.bodyA)}};
        if (spring.bodyB >= 0) out["b"] = bodyName(world, spring.bodyB);
        out["anchor_a"] = toJson(spring.localAnchorA);
        out["anchor_b"] = toJson(spring.anchorB);
        out["rest_length"] = tidy(spring.restLength);
        out["stiffness"] = tidy(spring.stiffness);
        out["damping"] = tidy(spring.damping);
        forces.push_back(out);
    }
    for (const Damping& damping : world.dampings) {
        Json out = {{"type", "damping"}};
        if (damping.body >= 0) out["body"] = bodyName(world, damping.body);
        out["linear"] = tidy(damping.linear);
        out["angular"] = tidy(damping.angular);
        forces.push_back(out);
    }
    if (!forces.empty()) scene["forces"] = forces;
    return scene.dump(2) + "\n";
}

}  // namespace stepwise
