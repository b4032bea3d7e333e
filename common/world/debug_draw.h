#pragma once
// The only way physics code shows anything. Chapters describe what to draw; a renderer
// (renderer_dx12) or a recorder (tests, headless runs) decides what that means.

#include "math/math.h"

#include <string>
#include <vector>

namespace stepwise {

struct ConvexHull;
struct Shape;
struct Body;
struct World;

struct Color {
    float r = 1, g = 1, b = 1, a = 1;
};

namespace colors {
constexpr Color kRed{0.90f, 0.20f, 0.20f, 1};
constexpr Color kGreen{0.30f, 0.80f, 0.35f, 1};
constexpr Color kBlue{0.25f, 0.45f, 0.95f, 1};
constexpr Color kYellow{0.95f, 0.85f, 0.20f, 1};
constexpr Color kWhite{1, 1, 1, 1};
constexpr Color kGrey{0.55f, 0.55f, 0.58f, 1};
constexpr Color kOrange{0.95f, 0.55f, 0.15f, 1};
constexpr Color kCyan{0.20f, 0.85f, 0.90f, 1};
constexpr Color kMagenta{0.85f, 0.30f, 0.85f, 1};
}  // namespace colors

enum class Fill { Solid, Wire };

class DebugDraw {
public:
    virtual ~DebugDraw() = default;
    virtual void line(const Vec3& from, const Vec3& to, Color color) = 0;
    virtual void point(const Vec3& at, float sizePixels, Color color) = 0;
    virtual void arrow(const Vec3& from, const Vec3& to, Color color) = 0;
    virtual void box(const Transform& pose, const Vec3& halfExtents, Color color, Fill fill) = 0;
    virtual void sphere(const Vec3& center, Real radius, Color color, Fill fill) = 0;
    virtual void capsule(const Transform& pose, Real radius, Real halfHeight, Color color, Fill fill) = 0;
    virtual void hull(const Transform& pose, const ConvexHull& hull, Color color, Fill fill) = 0;
    virtual void triangle(const Vec3& a, const Vec3& b, const Vec3& c, Color color) = 0;
    virtual void text(const Vec3& at, const std::string& message, Color color) = 0;
};

/// Draws one body's shape at its pose.
/// A shape at a pose (a compound draws its children; meshes and height fields as triangles).
void drawShape(DebugDraw& draw, const Shape& shape, const Transform& pose, Color color, Fill fill = Fill::Solid);
void drawBody(DebugDraw& draw, const Body& body, Color color, Fill fill = Fill::Solid);

/// Draws every body: statics grey, kinematics blue, dynamics in a colour picked by index.
void drawWorld(DebugDraw& draw, const World& world);

/// A colour per body index that neighbours can tell apart.
Color bodyColor(int bodyIndex);

/// How every demo colours a body: statics grey, kinematics blue, dynamics bodyColor(index).
Color bodyTypeColor(const World& world, int bodyIndex);

/// Keeps every call as a record: the drawer for tests and headless runs. It also measures: the box
/// around everything drawn is how the demo frames a scene from what its draw hook puts around the
/// bodies (chapter 2 draws the Minkowski difference metres above them), so the hook is run once
/// into a recorder.
class RecordingDraw final : public DebugDraw {
public:
    enum class Kind { Line, Point, Arrow, Box, Sphere, Capsule, Hull, Triangle, Text };
    struct Command {
        Kind kind;
        Vec3 a = Vec3::Zero();
        Vec3 b = Vec3::Zero();
        Color color;
        std::string message;
        Fill fill = Fill::Solid;   // shapes: solid or wireframe
    };

    void line(const Vec3& from, const Vec3& to, Color color) override;
    void point(const Vec3& at, float sizePixels, Color color) override;
    void arrow(const Vec3& from, const Vec3& to, Color color) override;
    void box(const Transform& pose, const Vec3& halfExtents, Color color, Fill fill) override;
    void sphere(const Vec3& center, Real radius, Color color, Fill fill) override;
    void capsule(const Transform& pose, Real radius, Real halfHeight, Color color, Fill fill) override;
    void hull(const Transform& pose, const ConvexHull& hull, Color color, Fill fill) override;
    void triangle(const Vec3& a, const Vec3& b, const Vec3& c, Color color) override;
    void text(const Vec3& at, const std::string& message, Color color) override;

    int count(Kind kind) const;
    const std::vector<Command>& commands() const { return commands_; }
    void clear() {
        commands_.clear();
        bounds_ = Aabb{};
    }

    /// Every point drawn so far: the ends of lines, the corners of boxes, the vertices of hulls, the
    /// balls of spheres and capsules, the anchors of labels (their width is only known on screen).
    /// Non-finite points (a scene drawing a NaN) are left out instead of poisoning the box; empty
    /// (min > max) when nothing finite was drawn.
    const Aabb& bounds() const { return bounds_; }
    bool empty() const { return (bounds_.min.array() > bounds_.max.array()).any(); }

private:
    void grow(const Vec3& point);
    std::vector<Command> commands_;
    Aabb bounds_;
};

}  // namespace stepwise
