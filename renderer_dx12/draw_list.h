#pragma once
// DrawList: the renderer's DebugDraw. It only collects what a frame shows, as plain arrays
// the GPU code uploads: instances of three unit meshes (boxes, spheres, capsule cylinders),
// world-space triangles (hulls), thick lines and points, and text labels.

#include "shaders.h"
#include "world/debug_draw.h"

#include <string>
#include <vector>

namespace stepwise::render {

struct TextLabel {
    Vec3 at;
    std::string message;
    Color color;
};

class DrawList final : public DebugDraw {
public:
    /// Wireframe mode: every shape is drawn as its edges, whatever Fill it asks for.
    bool wireframe = false;

    void clear();
    void line(const Vec3& from, const Vec3& to, Color color) override;
    void point(const Vec3& at, float sizePixels, Color color) override;
    void arrow(const Vec3& from, const Vec3& to, Color color) override;
    void box(const Transform& pose, const Vec3& halfExtents, Color color, Fill fill) override;
    void sphere(const Vec3& center, Real radius, Color color, Fill fill) override;
    void capsule(const Transform& pose, Real radius, Real halfHeight, Color color, Fill fill) override;
    void hull(const Transform& pose, const ConvexHull& hull, Color color, Fill fill) override;
    void triangle(const Vec3& a, const Vec3& b, const Vec3& c, Color color) override;
    void text(const Vec3& at, const std::string& message, Color color) override;

    /// A line with its own width in pixels (the ground grid uses thin ones).
    void lineWidth(const Vec3& from, const Vec3& to, Color color, float widthPixels);

    std::vector<MeshInstance> boxes;
    std::vector<MeshInstance> spheres;
    std::vector<MeshInstance> cylinders;
    std::vector<TriangleVertex> triangles;
    std::vector<LineInstance> lines;
    std::vector<TextLabel> labels;

private:
    void circle(const Vec3& center, const Vec3& axisU, const Vec3& axisV, Real radius, Color color, Real fromAngle,
                Real toAngle);
    static MeshInstance instance(const Transform& pose, const Vec3& scale, Color color);
    bool wire(Fill fill) const { return wireframe || fill == Fill::Wire; }
};

}  // namespace stepwise::render
