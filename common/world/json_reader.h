#pragma once
// Strict JSON reading for the project's formats (scenes, collide queries): a JsonCursor knows
// its own path from the document root, so every rejection names its value, e.g.
// SceneError("bodies[3].shape.box.half_extents[1]", "must be > 0"). Unknown keys are errors
// (with a "did you mean" for near misses), duplicate keys are errors, overflowing numbers are
// errors. Readers go on after a rejection where they can (ErrorList), so a file reports all
// its errors at once. Shared by the scene loader and by chapters that read JSON (chapter 3's
// `collide`).

#include "world/enum_names.h"
#include "world/scene.h"
#include "world/scene_limits.h"
#include "world/shape.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace stepwise {

using Json = nlohmann::ordered_json;  // keeps the author's key order for messages and saving

/// "%g" for numbers inside messages.
std::string formatForMessage(double value);

/// Collects the rejections of one file, so a user fixes them all in one go rather than one run
/// at a time. Each independent value is read inside attempt(); past `limit` errors reading stops.
class ErrorList {
public:
    static constexpr std::size_t kDefaultLimit = 20;
    explicit ErrorList(std::size_t limit = kDefaultLimit) : limit_(limit) {}

    /// Runs `read`; records the SceneError it throws and returns false. Once the limit is
    /// reached, throws everything collected so far (the rest of the file is not read).
    template <class Read>
    bool attempt(Read&& read) {
        try {
            read();
            return true;
        } catch (const SceneError& error) {
            if (error.truncated()) throw;  // the limit, reached further down: stop reading
            add(error);
            return false;
        }
    }
    void add(const SceneError& error) {
        for (const SceneIssue& issue : error.issues()) issues_.push_back(issue);
        if (issues_.size() >= limit_) throw SceneError(issues_, true);
    }
    bool empty() const { return issues_.empty(); }
    std::size_t size() const { return issues_.size(); }
    /// Throws a SceneError holding every issue when there is any.
    void throwIfAny() const {
        if (!issues_.empty()) throw SceneError(issues_);
    }

private:
    std::size_t limit_;
    std::vector<SceneIssue> issues_;
};

/// A JSON value together with its path from the document root. Each getter checks the type
/// and range of the value and throws SceneError(path(), message) when it is wrong.
class JsonCursor {
public:
    JsonCursor(const Json& value, std::string path) : value_(value), path_(std::move(path)) {}

    const Json& json() const { return value_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& message) const { throw SceneError(path_, message); }

    /// Checks that this is an object whose keys are all among `accepted`. With `errors`, every
    /// unknown key is recorded there and reading goes on; without, the first one throws.
    void expectObject(const std::vector<const char*>& accepted, ErrorList* errors = nullptr) const {
        if (!value_.is_object()) fail("must be an object");
        for (const auto& item : value_.items()) {
            const auto known = [&](const char* key) { return item.key() == key; };
            if (std::any_of(accepted.begin(), accepted.end(), known)) continue;
            const SceneError error(path_, unknownKeyMessage(item.key(), accepted));
            if (!errors) throw error;
            errors->add(error);
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
    /// An array of at most `limit` entries (scene_limits.h).
    std::size_t arraySizeAtMost(std::size_t limit) const {
        const std::size_t size = arraySize();
        if (size > limit)
            fail("has " + std::to_string(size) + " entries; at most " + std::to_string(limit) + " are supported");
        return size;
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
    /// A number no larger than `limit` in magnitude (scene_limits.h).
    Real within(Real limit) const {
        const Real value = number();
        if (!(std::abs(value) <= limit))
            fail("must be within [" + formatForMessage(-limit) + ", " + formatForMessage(limit) + "]");
        return value;
    }
    Real positive() const { return check(number() > 0, "must be > 0"); }
    /// A number > 0 within [low, high].
    Real positiveBetween(Real low, Real high) const {
        const Real value = positive();
        if (value < low || value > high)
            fail("must be between " + formatForMessage(low) + " and " + formatForMessage(high));
        return value;
    }
    Real positiveAtMost(Real high) const {
        const Real value = number();
        if (!(value > 0 && value <= high)) fail("must be > 0 and <= " + formatForMessage(high));
        return value;
    }
    Real nonNegative() const { return check(number() >= 0, "must be >= 0"); }
    Real inRange(Real low, Real high) const {
        const Real value = number();
        if (value < low || value > high) fail("must be in [" + formatForMessage(low) + ", " + formatForMessage(high) + "]");
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
    /// [x, y, z], each no larger than `limit` in magnitude.
    Vec3 vec3Within(Real limit) const {
        vec3();
        return Vec3(element(0).within(limit), element(1).within(limit), element(2).within(limit));
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
            fail("must be a unit quaternion [x, y, z, w] (its length is " + formatForMessage(q.norm()) + ")");
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
    static std::string unknownKeyMessage(const std::string& key, const std::vector<const char*>& accepted);

    const Json& value_;
    std::string path_;
};

/// Reads a whole file of at most kMaxFileBytes. Throws SceneError(path, ...) when it is missing,
/// a directory, unreadable or too large; `what` names the kind of file in messages.
std::string readInputFile(const std::string& path, const char* what);

/// Parses JSON text. nlohmann keeps the last of two equal keys silently, so a parser callback
/// tracks the current path and rejects duplicates; the same path names a number that overflows.
/// Malformed text is rejected naming `source`, the line and the column.
Json parseStrictJson(const std::string& text, const std::string& source);

/// Reads a body object of a scene (collide queries share it): every key, checked, with the
/// rules of its type (no mass on a static body, ...). Errors go to `errors`; a shape that cannot
/// be read becomes a placeholder, so the rest of the file can still be checked.
/// `baseDirectory`: where a mesh's "obj" file is looked for (the scene file's folder).
BodyDef readBodyDef(const JsonCursor& cursor, std::size_t index, ErrorList& errors, const std::string& baseDirectory = "");

/// Reads `{ "<kind>": {...} }` for every shape kind (docs/scene-format.md, "Shapes"): box, sphere,
/// capsule, convex, cylinder, compound, mesh, heightfield. A mesh's "obj" file is named relative
/// to `baseDirectory`.
Shape readShape(const JsonCursor& cursor, const std::string& baseDirectory = "");

/// The kinds of chapter 13 (shape_reader.cpp): `params` is the object under the kind's key.
Shape readCylinder(const JsonCursor& params);
Shape readCompound(const JsonCursor& params, const std::string& baseDirectory);
Shape readMesh(const JsonCursor& params, const std::string& baseDirectory);
Shape readHeightField(const JsonCursor& params);

/// A Wavefront OBJ file's vertices ("v x y z") and faces ("f a b c ...", fanned into triangles;
/// "a/t/n" and negative indices as the format has them); everything else is skipped. Throws
/// SceneError naming the file and line of a bad vertex or face.
void readObjFile(const std::string& path, std::vector<Vec3>& vertices, std::vector<std::array<int, 3>>& triangles);

/// The shortest decimal that reads back as the same Real; whole numbers as integers.
Json tidyNumber(Real value);
Json toJson(const Vec3& v);
Json toJson(const Quat& q);

}  // namespace stepwise
