#include "bounds_draw.h"

#include "world/shape.h"

namespace stepwise::render {

void BoundsDraw::add(const Vec3& point) {
    if (point.allFinite()) bounds_.grow(point);
}

void BoundsDraw::line(const Vec3& from, const Vec3& to, Color) {
    add(from);
    add(to);
}

void BoundsDraw::point(const Vec3& at, float, Color) { add(at); }

void BoundsDraw::arrow(const Vec3& from, const Vec3& to, Color) {
    add(from);
    add(to);
}

void BoundsDraw::box(const Transform& pose, const Vec3& halfExtents, Color, Fill) {
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 sign((corner & 1) ? 1 : -1, (corner & 2) ? 1 : -1, (corner & 4) ? 1 : -1);
        add(pose.apply(sign.cwiseProduct(halfExtents)));
    }
}

void BoundsDraw::sphere(const Vec3& center, Real radius, Color, Fill) {
    add(center - Vec3::Constant(radius));
    add(center + Vec3::Constant(radius));
}

void BoundsDraw::capsule(const Transform& pose, Real radius, Real halfHeight, Color, Fill) {
    // The capsule's axis is its local +Y (common/world/shape.h).
    for (Real end : {-halfHeight, halfHeight}) {
        const Vec3 center = pose.apply(Vec3(0, end, 0));
        add(center - Vec3::Constant(radius));
        add(center + Vec3::Constant(radius));
    }
}

void BoundsDraw::hull(const Transform& pose, const ConvexHull& hull, Color, Fill) {
    for (const Vec3& vertex : hull.vertices) add(pose.apply(vertex));
}

void BoundsDraw::triangle(const Vec3& a, const Vec3& b, const Vec3& c, Color) {
    add(a);
    add(b);
    add(c);
}

void BoundsDraw::text(const Vec3& at, const std::string& message, Color color) {
    if (!at.allFinite()) return;
    add(at);
    labels.push_back({at, message, color});
}

}  // namespace stepwise::render
