#include "world/json_reader.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <type_traits>

namespace stepwise {

namespace {

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

}  // namespace

/// "%g" for numbers inside messages.
std::string formatForMessage(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string JsonCursor::unknownKeyMessage(const std::string& key, const std::vector<const char*>& accepted) {
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


std::string readInputFile(const std::string& path, const char* what) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) throw SceneError(path, "no such file");
    if (std::filesystem::is_directory(path, error)) throw SceneError(path, std::string("is a directory, not ") + what);
    const auto bytes = std::filesystem::file_size(path, error);
    if (!error && bytes > kMaxFileBytes)
        throw SceneError(path, "is " + std::to_string(bytes >> 20) + " MiB; at most " +
                                   std::to_string(kMaxFileBytes >> 20) + " MiB are read");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw SceneError(path, "cannot open the file for reading");
    std::ostringstream text;
    text << file.rdbuf();
    if (!file) throw SceneError(path, "cannot read the file");
    return text.str();
}

namespace {

/// A first pass over the text that builds nothing: it tracks the path of the current value and
/// rejects duplicate keys, numbers that overflow and documents of more than kMaxJsonValues
/// values, before the DOM parse allocates anything. (nlohmann's callback parser does the same
/// checks, but scans the enclosing array after every object, quadratic in the array's length:
/// 100,000 bodies took seconds and a million query pairs minutes.)
class StrictJsonChecker {
public:
    using Number = nlohmann::json::number_float_t;
    explicit StrictJsonChecker(const std::string& source) : source_(source) {}

    bool null() { return value(); }
    bool boolean(bool) { return value(); }
    bool number_integer(nlohmann::json::number_integer_t) { return value(); }
    bool number_unsigned(nlohmann::json::number_unsigned_t) { return value(); }
    bool number_float(Number, const std::string&) { return value(); }
    bool string(std::string&) { return value(); }
    bool binary(nlohmann::json::binary_t&) { return value(); }
    bool start_object(std::size_t) {
        count();
        frames_.push_back(Frame{});
        return true;
    }
    bool start_array(std::size_t) {
        count();
        frames_.push_back(Frame{true, 0, {}, {}});
        return true;
    }
    bool end_object() { return end(); }
    bool end_array() { return end(); }
    bool key(std::string& name) {
        Frame& frame = frames_.back();
        frame.key = name;
        if (!frame.keys.insert(name).second) throw SceneError(path(false), "duplicate key \"" + name + "\"");
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) {
        // 406: the lexer read a number such as 1e999 that overflows a double.
        if (error.id == 406) throw SceneError(path(true), "must be a finite number");
        // "[json.exception.parse_error.101] parse error at line 2, column 7: syntax error ..."
        const std::string what = error.what();
        const std::size_t line = what.find("line ");
        const std::string detail = line == std::string::npos ? what : what.substr(line);
        throw SceneError("", "malformed JSON in " + source_ + " at " + detail);
    }

private:
    struct Frame {
        bool isArray = false;
        std::size_t index = 0;
        std::string key;
        std::set<std::string> keys;
    };

    /// The path of the current value; without its last designator, the path of its container.
    std::string path(bool withLastDesignator) const {
        std::string text;
        for (std::size_t i = 0; i < frames_.size(); ++i) {
            if (i + 1 == frames_.size() && !withLastDesignator) break;
            const Frame& frame = frames_[i];
            text += frame.isArray ? "[" + std::to_string(frame.index) + "]" : (text.empty() ? "" : ".") + frame.key;
        }
        return text;
    }
    void count() {
        if (++values_ > kMaxJsonValues)
            throw SceneError(path(true), "the document has more than " + std::to_string(kMaxJsonValues) +
                                             " values; larger ones are not read");
    }
    bool value() {
        count();
        valueDone();
        return true;
    }
    void valueDone() {
        if (!frames_.empty() && frames_.back().isArray) ++frames_.back().index;
    }
    bool end() {
        frames_.pop_back();
        valueDone();
        return true;
    }

    const std::string& source_;
    std::vector<Frame> frames_;
    std::size_t values_ = 0;
};

}  // namespace

Json parseStrictJson(const std::string& text, const std::string& source) {
    StrictJsonChecker checker(source);
    nlohmann::json::sax_parse(text, &checker);
    return Json::parse(text);  // well-formed, no duplicate keys, bounded: the checker saw to it
}

namespace {

/// What a body's type rules out: motion on a static body, mass on one that is not dynamic.
void checkTypeRules(const JsonCursor& cursor, const BodyDef& def, ErrorList& errors) {
    if (def.type == BodyType::Static)
        for (const char* key : {"velocity", "angular_velocity", "integrator"})
            if (cursor.has(key))
                errors.attempt([&] { cursor.child(key).fail("not allowed on a static body (it never moves)"); });
    if (def.type != BodyType::Dynamic)
        for (const char* key : {"mass", "density"})
            if (cursor.has(key))
                errors.attempt([&] {
                    cursor.child(key).fail(std::string("only dynamic bodies have mass (this body is ") +
                                           toString(def.type) + ")");
                });
    if (cursor.has("mass") && cursor.has("density"))
        errors.attempt([&] { cursor.child("density").fail("give mass or density, not both"); });
}

/// The velocities of a body that moves, and the mass or density of a dynamic one.
void readMotion(const JsonCursor& cursor, BodyDef& def, ErrorList& errors) {
    if (def.type != BodyType::Static) {
        errors.attempt([&] {
            if (auto v = cursor.optional("velocity")) def.linearVelocity = v->vec3Within(kMaxSpeed);
        });
        errors.attempt([&] {
            if (auto v = cursor.optional("angular_velocity")) def.angularVelocity = v->vec3Within(kMaxAngularSpeed);
        });
    }
    if (def.type == BodyType::Dynamic) {
        errors.attempt([&] {
            if (auto v = cursor.optional("mass")) def.mass = v->positiveBetween(kMinMass, kMaxMass);
        });
        errors.attempt([&] {
            if (auto v = cursor.optional("density")) def.density = v->positiveBetween(kMinDensity, kMaxDensity);
        });
    }
}

/// The surface, the bullet flag, the integrator and a kinematic body's path.
void readMaterialAndPath(const JsonCursor& cursor, BodyDef& def, ErrorList& errors) {
    errors.attempt([&] {
        if (auto v = cursor.optional("friction")) def.material.friction = v->nonNegative();
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("restitution")) def.material.restitution = v->inRange(0, 1);
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("rolling_resistance")) def.material.rollingResistance = v->inRange(0, 1);
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("bullet")) def.bullet = v->boolean();
    });
    if (def.type != BodyType::Static)
        errors.attempt([&] {
            if (auto v = cursor.optional("integrator")) def.integrator = v->choice(kIntegratorNames);
        });
    errors.attempt([&] {
        if (auto v = cursor.optional("path")) {
            if (def.type != BodyType::Kinematic) v->fail("only kinematic bodies follow a path");
            v->expectObject({"amplitude", "period", "phase"});
            KinematicPath path;
            path.amplitude = v->child("amplitude").vec3Within(kMaxCoordinate);
            path.period = v->child("period").positiveBetween(Real(1e-3), Real(1e6));
            if (auto phase = v->optional("phase")) path.phase = phase->within(Real(1e6));
            def.path = path;
        }
    });
}

}  // namespace

BodyDef readBodyDef(const JsonCursor& cursor, std::size_t index, ErrorList& errors, const std::string& baseDirectory) {
    cursor.expectObject({"name", "type", "shape", "position", "orientation", "velocity", "angular_velocity", "mass",
                         "density", "friction", "restitution", "rolling_resistance", "bullet", "integrator", "path"},
                        &errors);
    BodyDef def;
    def.name = "body" + std::to_string(index);
    errors.attempt([&] {
        if (auto v = cursor.optional("name")) def.name = v->nonEmptyString();
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("type")) def.type = v->choice(kBodyTypeNames);
    });
    // A placeholder keeps the body, so joints and forces that name it can still be checked.
    if (!errors.attempt([&] { def.shape = readShape(cursor.child("shape"), baseDirectory); })) def.shape = Shape::sphere(1);
    // The ground of chapter 13 never moves: a mesh or a height field is static.
    if (!canMove(def.shape) && def.type != BodyType::Static)
        errors.attempt([&] {
            cursor.child("shape").fail(std::string("a ") + toString(def.shape.type) +
                                       " is static only: give its body \"type\": \"static\"");
        });
    errors.attempt([&] {
        if (auto v = cursor.optional("position")) def.transform.position = v->vec3Within(kMaxCoordinate);
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("orientation")) def.transform.rotation = v->unitQuaternion();
    });
    checkTypeRules(cursor, def, errors);
    readMotion(cursor, def, errors);
    readMaterialAndPath(cursor, def, errors);
    return def;
}

Shape readShape(const JsonCursor& cursor, const std::string& baseDirectory) {
    const std::vector<const char*> kinds = {"box", "sphere", "capsule", "convex", "cylinder", "compound", "mesh", "heightfield"};
    const char* accepted = "box, sphere, capsule, convex, cylinder, compound, mesh, heightfield";
    if (!cursor.json().is_object() || cursor.json().size() != 1)
        cursor.fail(std::string("must hold exactly one of ") + accepted);
    const std::string kind = cursor.json().begin().key();
    if (std::find(kinds.begin(), kinds.end(), kind) == kinds.end())
        cursor.fail("unknown shape kind \"" + kind + "\" (accepted: " + accepted + ")");
    const JsonCursor params = cursor.child(kind.c_str());
    if (kind == "box") {
        params.expectObject({"half_extents"});
        const JsonCursor size = params.child("half_extents");
        const Vec3 halfExtents = size.vec3();
        for (int axis = 0; axis < 3; ++axis) size.element(std::size_t(axis)).positiveBetween(kMinShapeSize, kMaxShapeSize);
        return Shape::box(halfExtents);
    }
    if (kind == "sphere") {
        params.expectObject({"radius"});
        return Shape::sphere(params.child("radius").positiveBetween(kMinShapeSize, kMaxShapeSize));
    }
    if (kind == "capsule") {
        params.expectObject({"radius", "half_height"});
        const Real radius = params.child("radius").positiveBetween(kMinShapeSize, kMaxShapeSize);
        return Shape::capsule(radius, params.child("half_height").positiveBetween(kMinShapeSize, kMaxShapeSize));
    }
    if (kind == "cylinder") return readCylinder(params);
    if (kind == "compound") return readCompound(params, baseDirectory);
    if (kind == "mesh") return readMesh(params, baseDirectory);
    if (kind == "heightfield") return readHeightField(params);
    params.expectObject({"vertices"});
    const JsonCursor list = params.child("vertices");
    std::vector<Vec3> points(list.arraySizeAtMost(std::size_t(kMaxHullPoints)));
    for (std::size_t i = 0; i < points.size(); ++i) points[i] = list.element(i).vec3Within(kMaxShapeSize);
    if (points.size() < 4)
        list.fail("needs at least 4 points that span a volume (got " + std::to_string(points.size()) + ")");
    try {
        return Shape::convex(points);
    } catch (const HullError& error) {
        list.fail(error.message);
    }
}

Json tidyNumber(Real value) {
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

Json toJson(const Vec3& v) { return Json::array({tidyNumber(v.x()), tidyNumber(v.y()), tidyNumber(v.z())}); }
Json toJson(const Quat& q) { return Json::array({tidyNumber(q.x()), tidyNumber(q.y()), tidyNumber(q.z()), tidyNumber(q.w())}); }

}  // namespace stepwise
