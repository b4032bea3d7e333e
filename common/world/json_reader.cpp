#include "world/json_reader.h"

#include <cstdint>
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


Json parseStrictJson(const std::string& text, const std::string& source) {
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

const Names<IntegratorKind>& integratorNames() {
    static const Names<IntegratorKind> names = {{"semi_implicit_euler", IntegratorKind::SemiImplicitEuler},
                                                {"rk4", IntegratorKind::Rk4},
                                                {"verlet", IntegratorKind::Verlet}};
    return names;
}

BodyDef readBodyDef(const JsonCursor& cursor, std::size_t index, ErrorList& errors) {
    static const Names<BodyType> kBodyTypes = {
        {"static", BodyType::Static}, {"kinematic", BodyType::Kinematic}, {"dynamic", BodyType::Dynamic}};
    cursor.expectObject({"name", "type", "shape", "position", "orientation", "velocity", "angular_velocity", "mass",
                         "density", "friction", "restitution", "bullet", "integrator"},
                        &errors);
    BodyDef def;
    def.name = "body" + std::to_string(index);
    errors.attempt([&] {
        if (auto v = cursor.optional("name")) def.name = v->nonEmptyString();
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("type")) def.type = v->choice(kBodyTypes);
    });
    // A placeholder keeps the body, so joints and forces that name it can still be checked.
    if (!errors.attempt([&] { def.shape = readShape(cursor.child("shape")); })) def.shape = Shape::sphere(1);
    errors.attempt([&] {
        if (auto v = cursor.optional("position")) def.transform.position = v->vec3();
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("orientation")) def.transform.rotation = v->unitQuaternion();
    });
    // What a body's type rules out: motion on a static body, mass on one that is not dynamic.
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
    if (def.type != BodyType::Static) {
        errors.attempt([&] {
            if (auto v = cursor.optional("velocity")) def.linearVelocity = v->vec3();
        });
        errors.attempt([&] {
            if (auto v = cursor.optional("angular_velocity")) def.angularVelocity = v->vec3();
        });
    }
    if (def.type == BodyType::Dynamic) {
        errors.attempt([&] {
            if (auto v = cursor.optional("mass")) def.mass = v->positive();
        });
        errors.attempt([&] {
            if (auto v = cursor.optional("density")) def.density = v->positive();
        });
    }
    errors.attempt([&] {
        if (auto v = cursor.optional("friction")) def.material.friction = v->nonNegative();
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("restitution")) def.material.restitution = v->inRange(0, 1);
    });
    errors.attempt([&] {
        if (auto v = cursor.optional("bullet")) def.bullet = v->boolean();
    });
    if (def.type != BodyType::Static)
        errors.attempt([&] {
            if (auto v = cursor.optional("integrator")) def.integrator = v->choice(integratorNames());
        });
    return def;
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
