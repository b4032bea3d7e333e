#include "13_worlds/triangle_prism.h"

#include <algorithm>

namespace stepwise {

namespace {

// A face of the prism from its vertex indices, ordered counter-clockwise about its outward normal
// (the one pointing away from the prism's centre).
HullFace prismFace(const ConvexHull& hull, std::vector<int> indices, const Vec3& centre) {
    const Vec3& p0 = hull.vertices[static_cast<std::size_t>(indices[0])];
    Vec3 normal = (hull.vertices[static_cast<std::size_t>(indices[1])] - p0)
                      .cross(hull.vertices[static_cast<std::size_t>(indices[2])] - p0)
                      .normalized();
    if (normal.dot(p0 - centre) < 0) {
        std::reverse(indices.begin(), indices.end());
        normal = -normal;
    }
    HullFace face;
    face.vertexIndices = std::move(indices);
    face.normal = normal;
    face.offset = normal.dot(p0);
    return face;
}

}  // namespace

// [ch13-triangle-prism]
Shape trianglePrism(const Vec3& a, const Vec3& b, const Vec3& c) {
    auto hull = std::make_shared<ConvexHull>();
    const Vec3 front = (b - a).cross(c - a).normalized();
    const Vec3 back = -kPrismDepth * front;
    hull->vertices = {a, b, c, a + back, b + back, c + back};
    Vec3 centre = Vec3::Zero();
    for (const Vec3& vertex : hull->vertices) centre += vertex / Real(6);
    hull->faces.push_back(prismFace(*hull, {0, 1, 2}, centre));
    hull->faces.push_back(prismFace(*hull, {5, 4, 3}, centre));
    for (int edge = 0; edge < 3; ++edge) {
        const int next = (edge + 1) % 3;
        hull->faces.push_back(prismFace(*hull, {edge, edge + 3, next + 3, next}, centre));
    }
    for (const Vec3& vertex : hull->vertices) hull->vertexRadius = std::max(hull->vertexRadius, vertex.norm());
    Shape shape;
    shape.type = ShapeType::Convex;
    shape.hull = std::move(hull);
    return shape;
}
// [ch13-triangle-prism]

}  // namespace stepwise
