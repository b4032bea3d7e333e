#include "draw_list.h"

#include "world/shape.h"

#include <algorithm>
#include <cmath>

namespace stepwise::render {

namespace {
constexpr int kCircleSegments = 32;

void store(float out[3], const Vec3& v) {
    out[0] = static_cast<float>(v.x());
    out[1] = static_cast<float>(v.y());
    out[2] = static_cast<float>(v.z());
}
void store(float out[4], Color color) {
    out[0] = color.r;
    out[1] = color.g;
    out[2] = color.b;
    out[3] = color.a;
}
bool finite(const Vec3& v) { return v.allFinite(); }
}  // namespace

void DrawList::clear() {
    boxes.clear();
    spheres.clear();
    cylinders.clear();
    triangles.clear();
    lines.clear();
    labels.clear();
}

MeshInstance DrawList::instance(const Transform& pose, const Vec3& scale, Color color) {
    MeshInstance out = {};
    const Mat3 rotation = pose.rotation.normalized().toRotationMatrix();
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) out.rows[row][col] = static_cast<float>(rotation(row, col));
        out.rows[row][3] = static_cast<float>(pose.position[row]);
    }
    store(out.scale, scale);
    out.scale[3] = 1;
    store(out.color, color);
    return out;
}

void DrawList::lineWidth(const Vec3& from, const Vec3& to, Color color, float widthPixels) {
    if (!finite(from) || !finite(to)) return;  // a NaN body must not take the frame down
    LineInstance line = {};
    store(line.from, from);
    store(line.to, to);
    store(line.color, color);
    line.widthPixels = widthPixels;
    lines.push_back(line);
}

void DrawList::line(const Vec3& from, const Vec3& to, Color color) { lineWidth(from, to, color, 0); }

void DrawList::point(const Vec3& at, float sizePixels, Color color) {
    lineWidth(at, at, color, std::max(sizePixels, 1.0f));
}

void DrawList::arrow(const Vec3& from, const Vec3& to, Color color) {
    line(from, to, color);
    const Vec3 shaft = to - from;
    const Real length = shaft.norm();
    if (!(length > Real(1e-6))) return;
    const Vec3 direction = shaft / length;
    const Real head = std::min(Real(0.25) * length, Real(0.2));
    const Vec3 u = anyPerpendicular(direction);
    const Vec3 v = direction.cross(u);
    const Vec3 base = to - head * direction;
    for (const Vec3& side : {u, Vec3(-u), v, Vec3(-v)}) line(to, base + Real(0.4) * head * side, color);
}

void DrawList::box(const Transform& pose, const Vec3& halfExtents, Color color, Fill fill) {
    if (!finite(pose.position) || !finite(halfExtents)) return;
    if (!wire(fill)) {
        boxes.push_back(instance(pose, halfExtents, color));
        return;
    }
    Vec3 corners[8];
    for (int i = 0; i < 8; ++i) {
        const Vec3 sign((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
        corners[i] = pose.apply(sign.cwiseProduct(halfExtents));
    }
    // Corners differing in exactly one bit share an edge.
    for (int i = 0; i < 8; ++i) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(i & bit)) line(corners[i], corners[i | bit], color);
        }
    }
}

void DrawList::circle(const Vec3& center, const Vec3& axisU, const Vec3& axisV, Real radius, Color color,
                      Real fromAngle, Real toAngle) {
    const int segments = std::max(2, static_cast<int>(kCircleSegments * (toAngle - fromAngle) / (2 * kPi)));
    Vec3 previous = center + radius * (std::cos(fromAngle) * axisU + std::sin(fromAngle) * axisV);
    for (int i = 1; i <= segments; ++i) {
        const Real angle = fromAngle + (toAngle - fromAngle) * Real(i) / Real(segments);
        const Vec3 next = center + radius * (std::cos(angle) * axisU + std::sin(angle) * axisV);
        line(previous, next, color);
        previous = next;
    }
}

void DrawList::sphere(const Vec3& center, Real radius, Color color, Fill fill) {
    if (!finite(center) || !(radius > 0)) return;
    if (!wire(fill)) {
        Transform pose;
        pose.position = center;
        spheres.push_back(instance(pose, Vec3::Constant(radius), color));
        return;
    }
    const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
    circle(center, x, y, radius, color, 0, 2 * kPi);
    circle(center, y, z, radius, color, 0, 2 * kPi);
    circle(center, z, x, radius, color, 0, 2 * kPi);
}

void DrawList::capsule(const Transform& pose, Real radius, Real halfHeight, Color color, Fill fill) {
    if (!finite(pose.position) || !(radius > 0) || !(halfHeight >= 0)) return;
    const Vec3 axis = pose.rotate(Vec3::UnitY());
    const Vec3 top = pose.position + halfHeight * axis;
    const Vec3 bottom = pose.position - halfHeight * axis;
    if (!wire(fill)) {
        // One cylinder plus two spheres: all three come from the instanced unit meshes.
        cylinders.push_back(instance(pose, Vec3(radius, halfHeight, radius), color));
        Transform cap = pose;
        cap.position = top;
        spheres.push_back(instance(cap, Vec3::Constant(radius), color));
        cap.position = bottom;
        spheres.push_back(instance(cap, Vec3::Constant(radius), color));
        return;
    }
    const Vec3 u = pose.rotate(Vec3::UnitX());
    const Vec3 w = pose.rotate(Vec3::UnitZ());
    circle(top, u, w, radius, color, 0, 2 * kPi);
    circle(bottom, u, w, radius, color, 0, 2 * kPi);
    for (const Vec3& side : {u, Vec3(-u), w, Vec3(-w)}) line(top + radius * side, bottom + radius * side, color);
    circle(top, u, axis, radius, color, 0, kPi);
    circle(top, w, axis, radius, color, 0, kPi);
    circle(bottom, u, axis, radius, color, kPi, 2 * kPi);
    circle(bottom, w, axis, radius, color, kPi, 2 * kPi);
}

void DrawList::hull(const Transform& pose, const ConvexHull& shape, Color color, Fill fill) {
    if (!finite(pose.position)) return;
    const int vertexCount = static_cast<int>(shape.vertices.size());
    for (const HullFace& face : shape.faces) {
        const auto& ids = face.vertexIndices;
        const bool valid = ids.size() >= 3 && std::all_of(ids.begin(), ids.end(), [&](int id) {
                               return id >= 0 && id < vertexCount;
                           });
        if (!valid) continue;
        if (wire(fill)) {
            for (size_t i = 0; i < ids.size(); ++i) {
                line(pose.apply(shape.vertices[ids[i]]), pose.apply(shape.vertices[ids[(i + 1) % ids.size()]]), color);
            }
            continue;
        }
        // Faces are convex polygons: a fan from the first vertex covers each one.
        const Vec3 normal = pose.rotate(face.normal);
        const Vec3 first = pose.apply(shape.vertices[ids[0]]);
        for (size_t i = 1; i + 1 < ids.size(); ++i) {
            const Vec3 corners[3] = {first, pose.apply(shape.vertices[ids[i]]), pose.apply(shape.vertices[ids[i + 1]])};
            for (const Vec3& corner : corners) {
                TriangleVertex vertex = {};
                store(vertex.position, corner);
                store(vertex.normal, normal);
                store(vertex.color, color);
                triangles.push_back(vertex);
            }
        }
    }
}

void DrawList::triangle(const Vec3& a, const Vec3& b, const Vec3& c, Color color) {
    if (!finite(a) || !finite(b) || !finite(c)) return;
    if (wireframe) {
        line(a, b, color);
        line(b, c, color);
        line(c, a, color);
        return;
    }
    Vec3 normal = (b - a).cross(c - a);
    normal = normal.norm() > Real(1e-12) ? Vec3(normal.normalized()) : Vec3(Vec3::UnitY());
    for (const Vec3* corner : {&a, &b, &c}) {
        TriangleVertex vertex = {};
        store(vertex.position, *corner);
        store(vertex.normal, normal);
        store(vertex.color, color);
        triangles.push_back(vertex);
    }
}

void DrawList::text(const Vec3& at, const std::string& message, Color color) {
    if (finite(at)) labels.push_back({at, message, color});
}

}  // namespace stepwise::render
