#pragma once
// BoundsDraw: a DebugDraw that draws nothing and only measures. The camera frames a scene from
// its bodies AND from what the scene's draw hook puts around them (chapter 2 draws the
// Minkowski difference metres above its bodies), so the hook is run once into this recorder.

#include "draw_list.h"
#include "world/debug_draw.h"

#include <vector>

namespace stepwise::render {

class BoundsDraw final : public DebugDraw {
public:
    void line(const Vec3& from, const Vec3& to, Color color) override;
    void point(const Vec3& at, float sizePixels, Color color) override;
    void arrow(const Vec3& from, const Vec3& to, Color color) override;
    void box(const Transform& pose, const Vec3& halfExtents, Color color, Fill fill) override;
    void sphere(const Vec3& center, Real radius, Color color, Fill fill) override;
    void capsule(const Transform& pose, Real radius, Real halfHeight, Color color, Fill fill) override;
    void hull(const Transform& pose, const ConvexHull& hull, Color color, Fill fill) override;
    void triangle(const Vec3& a, const Vec3& b, const Vec3& c, Color color) override;
    /// The anchor counts; the label is kept too, since its on-screen width is only known to
    /// the shell (ui_shell.cpp, frameScene).
    void text(const Vec3& at, const std::string& message, Color color) override;

    /// Everything drawn so far; empty (min > max) when nothing finite was drawn.
    const Aabb& bounds() const { return bounds_; }
    bool empty() const { return (bounds_.min.array() > bounds_.max.array()).any(); }
    std::vector<TextLabel> labels;

private:
    /// Non-finite points (a scene drawing a NaN) are skipped instead of poisoning the box.
    void add(const Vec3& point);
    Aabb bounds_;
};

}  // namespace stepwise::render
