#include "world/debug_draw.h"

#include "world/world.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

// A cylinder as a prism of kCylinderSides sides: triangles for the surface, lines for the rims.
constexpr int kCylinderSides = 24;

void drawCylinder(DebugDraw& draw, const Transform& pose, Real radius, Real halfHeight, Color color, Fill fill) {
    Vec3 previousTop, previousBottom;
    for (int i = 0; i <= kCylinderSides; ++i) {
        const Real angle = Real(2) * kPi * Real(i) / Real(kCylinderSides);
        const Vec3 rim(radius * math::cos(angle), 0, radius * math::sin(angle));
        const Vec3 top = pose.apply(rim + Vec3(0, halfHeight, 0)), bottom = pose.apply(rim - Vec3(0, halfHeight, 0));
        if (i > 0) {
            draw.line(previousTop, top, color);
            draw.line(previousBottom, bottom, color);
            if (fill == Fill::Solid) {
                draw.triangle(previousBottom, bottom, top, color);
                draw.triangle(previousBottom, top, previousTop, color);
                draw.triangle(pose.apply(Vec3(0, halfHeight, 0)), top, previousTop, color);
                draw.triangle(pose.apply(Vec3(0, -halfHeight, 0)), previousBottom, bottom, color);
            }
        }
        if (i % (kCylinderSides / 4) == 0) draw.line(bottom, top, color);
        previousTop = top;
        previousBottom = bottom;
    }
}

void drawMesh(DebugDraw& draw, const Transform& pose, const TriangleMesh& mesh, Color color) {
    for (const auto& corners : mesh.triangles)
        draw.triangle(pose.apply(mesh.vertices[static_cast<std::size_t>(corners[0])]),
                      pose.apply(mesh.vertices[static_cast<std::size_t>(corners[1])]),
                      pose.apply(mesh.vertices[static_cast<std::size_t>(corners[2])]), color);
}

void drawHeightField(DebugDraw& draw, const Transform& pose, const HeightField& field, Color color) {
    const auto at = [&](int row, int column) {
        const Real height = field.heights[static_cast<std::size_t>(row) * static_cast<std::size_t>(field.columns) +
                                          static_cast<std::size_t>(column)];
        return Vec3(Real(column) * field.cellSize, height, Real(row) * field.cellSize);
    };
    for (int row = 0; row + 1 < field.rows; ++row)
        for (int column = 0; column + 1 < field.columns; ++column) {
            const Vec3 a = at(row, column), b = at(row, column + 1), c = at(row + 1, column), d = at(row + 1, column + 1);
            if (std::isnan(a.y()) || std::isnan(b.y()) || std::isnan(c.y()) || std::isnan(d.y())) continue;  // a hole
            draw.triangle(pose.apply(a), pose.apply(d), pose.apply(b), color);
            draw.triangle(pose.apply(a), pose.apply(c), pose.apply(d), color);
        }
}

}  // namespace

void drawShape(DebugDraw& draw, const Shape& shape, const Transform& pose, Color color, Fill fill) {
    switch (shape.type) {
        case ShapeType::Box: draw.box(pose, shape.halfExtents, color, fill); break;
        case ShapeType::Sphere: draw.sphere(pose.position, shape.radius, color, fill); break;
        case ShapeType::Capsule: draw.capsule(pose, shape.radius, shape.halfHeight, color, fill); break;
        case ShapeType::Convex: draw.hull(pose, *shape.hull, color, fill); break;
        case ShapeType::Cylinder: drawCylinder(draw, pose, shape.radius, shape.halfHeight, color, fill); break;
        case ShapeType::Compound:
            for (const CompoundChild& child : shape.compound->children)
                drawShape(draw, child.shape, compose(pose, child.transform), color, fill);
            break;
        case ShapeType::Mesh: drawMesh(draw, pose, *shape.mesh, color); break;
        case ShapeType::HeightField: drawHeightField(draw, pose, *shape.heightField, color); break;
    }
}

void drawBody(DebugDraw& draw, const Body& body, Color color, Fill fill) { drawShape(draw, body.shape, body.transform, color, fill); }

Color bodyColor(int bodyIndex) {
    // Golden-ratio hue steps keep neighbouring indices apart; fixed saturation and value
    // keep every colour readable on the grey ground.
    const float hue = std::fmod(0.12f + 0.618034f * static_cast<float>(bodyIndex), 1.0f) * 6.0f;
    const float chroma = 0.65f, value = 0.92f, low = value - chroma;
    const float x = chroma * (1 - std::abs(std::fmod(hue, 2.0f) - 1));
    const int sector = static_cast<int>(hue);
    float r = low, g = low, b = low;
    switch (sector) {
        case 0: r += chroma, g += x; break;
        case 1: r += x, g += chroma; break;
        case 2: g += chroma, b += x; break;
        case 3: g += x, b += chroma; break;
        case 4: r += x, b += chroma; break;
        default: r += chroma, b += x; break;
    }
    return Color{r, g, b, 1};
}

Color bodyTypeColor(const World& world, int bodyIndex) {
    const BodyType type = world.bodies[static_cast<size_t>(bodyIndex)].type;
    return type == BodyType::Static ? colors::kGrey : type == BodyType::Kinematic ? colors::kBlue : bodyColor(bodyIndex);
}

void drawWorld(DebugDraw& draw, const World& world) {
    for (size_t i = 0; i < world.bodies.size(); ++i)
        drawBody(draw, world.bodies[i], bodyTypeColor(world, static_cast<int>(i)));
}

void RecordingDraw::grow(const Vec3& point) {
    if (point.allFinite()) bounds_.grow(point);
}

void RecordingDraw::line(const Vec3& from, const Vec3& to, Color color) {
    commands_.push_back({Kind::Line, from, to, color, {}});
    grow(from);
    grow(to);
}
void RecordingDraw::point(const Vec3& at, float, Color color) {
    commands_.push_back({Kind::Point, at, at, color, {}});
    grow(at);
}
void RecordingDraw::arrow(const Vec3& from, const Vec3& to, Color color) {
    commands_.push_back({Kind::Arrow, from, to, color, {}});
    grow(from);
    grow(to);
}
void RecordingDraw::box(const Transform& pose, const Vec3& halfExtents, Color color, Fill fill) {
    commands_.push_back({Kind::Box, pose.position, halfExtents, color, {}, fill});
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
        grow(pose.apply(sign.cwiseProduct(halfExtents)));
    }
}
void RecordingDraw::sphere(const Vec3& center, Real radius, Color color, Fill fill) {
    commands_.push_back({Kind::Sphere, center, Vec3::Constant(radius), color, {}, fill});
    grow(center - Vec3::Constant(radius));
    grow(center + Vec3::Constant(radius));
}
void RecordingDraw::capsule(const Transform& pose, Real radius, Real halfHeight, Color color, Fill fill) {
    commands_.push_back({Kind::Capsule, pose.position, Vec3(radius, halfHeight, 0), color, {}, fill});
    // The capsule's axis is its local +Y (world/shape.h): the balls at both ends.
    for (Real end : {-halfHeight, halfHeight}) {
        const Vec3 center = pose.apply(Vec3(0, end, 0));
        grow(center - Vec3::Constant(radius));
        grow(center + Vec3::Constant(radius));
    }
}
void RecordingDraw::hull(const Transform& pose, const ConvexHull& hull, Color color, Fill fill) {
    commands_.push_back({Kind::Hull, pose.position, pose.position, color, {}, fill});
    for (const Vec3& vertex : hull.vertices) grow(pose.apply(vertex));
}
void RecordingDraw::triangle(const Vec3& a, const Vec3& b, const Vec3& c, Color color) {
    commands_.push_back({Kind::Triangle, a, b, color, {}});
    grow(a);
    grow(b);
    grow(c);
}
void RecordingDraw::text(const Vec3& at, const std::string& message, Color color) {
    commands_.push_back({Kind::Text, at, at, color, message});
    grow(at);
}

int RecordingDraw::count(Kind kind) const {
    return static_cast<int>(std::count_if(commands_.begin(), commands_.end(), [&](const Command& c) { return c.kind == kind; }));
}

}  // namespace stepwise
