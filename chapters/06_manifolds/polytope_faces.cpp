// Faces and edges of boxes and hulls, for clipping.
#include "06_manifolds/polytope_faces.h"

#include <cmath>

namespace stepwise {

bool isPolytope(const Shape& shape) {
    return shape.type == ShapeType::Box || (shape.type == ShapeType::Convex && shape.hull != nullptr);
}

int polytopeFaceCount(const Shape& shape) {
    if (shape.type == ShapeType::Box) return 6;
    if (shape.type == ShapeType::Convex && shape.hull) return static_cast<int>(shape.hull->faces.size());
    return 0;
}

namespace {

// Box faces 0..5 are -x, +x, -y, +y, -z, +z: face 2*axis + (positive ? 1 : 0).
int boxCornerIndex(int axis, bool positive, int u, int v, bool uPositive, bool vPositive) {
    int index = 0;
    if (positive) index |= 1 << axis;
    if (uPositive) index |= 1 << u;
    if (vPositive) index |= 1 << v;
    return index;
}

Vec3 boxCorner(const Vec3& halfExtents, int index) {
    return Vec3(index & 1 ? halfExtents.x() : -halfExtents.x(), index & 2 ? halfExtents.y() : -halfExtents.y(),
                index & 4 ? halfExtents.z() : -halfExtents.z());
}

}  // namespace

Vec3 polytopeFaceNormal(const Shape& shape, int face) {
    if (face < 0 || face >= polytopeFaceCount(shape)) return Vec3::Zero();
    if (shape.type == ShapeType::Box) {
        Vec3 normal = Vec3::Zero();
        normal[face / 2] = face % 2 ? Real(1) : Real(-1);
        return normal;
    }
    return shape.hull->faces[static_cast<std::size_t>(face)].normal;
}

FacePolygon polytopeFace(const Shape& shape, int face) {
    FacePolygon polygon;
    polytopeFace(shape, face, polygon);
    return polygon;
}

void polytopeFace(const Shape& shape, int face, FacePolygon& polygon) {
    polygon.index = -1;
    polygon.normal = Vec3::Zero();
    polygon.offset = 0;
    polygon.corners.clear();
    polygon.vertexIndices.clear();
    if (face < 0 || face >= polytopeFaceCount(shape)) return;
    polygon.index = face;
    polygon.normal = polytopeFaceNormal(shape, face);
    if (shape.type == ShapeType::Box) {
        const int axis = face / 2;
        const bool positive = face % 2 == 1;
        // u x v = axis, so (-,-), (+,-), (+,+), (-,+) in (u, v) runs counter-clockwise seen
        // from +axis; the negative face takes them in reverse.
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const bool uSigns[4] = {false, true, true, false};
        const bool vSigns[4] = {false, false, true, true};
        for (int k = 0; k < 4; ++k) {
            const int corner = positive ? k : 3 - k;
            const int index = boxCornerIndex(axis, positive, u, v, uSigns[corner], vSigns[corner]);
            polygon.vertexIndices.push_back(index);
            polygon.corners.push_back(boxCorner(shape.halfExtents, index));
        }
        polygon.offset = shape.halfExtents[axis];
        return;
    }
    const HullFace& hullFace = shape.hull->faces[static_cast<std::size_t>(face)];
    polygon.offset = hullFace.offset;
    for (int index : hullFace.vertexIndices) {
        if (index < 0 || index >= static_cast<int>(shape.hull->vertices.size())) continue;
        polygon.vertexIndices.push_back(index);
        polygon.corners.push_back(shape.hull->vertices[static_cast<std::size_t>(index)]);
    }
}

int mostAlignedFace(const Shape& shape, const Transform& transform, const Vec3& worldDirection, Real& alignment) {
    const Vec3 local = transform.rotateInverse(worldDirection);
    int best = -1;
    alignment = -kRealMax;
    const int count = polytopeFaceCount(shape);
    for (int face = 0; face < count; ++face) {
        // Ties go to the lower index, so the same pose always picks the same face.
        const Real dot = polytopeFaceNormal(shape, face).dot(local);
        if (dot > alignment) {
            alignment = dot;
            best = face;
        }
    }
    return best;
}

Vec3 polytopeSupport(const Shape& shape, const Vec3& localDirection) {
    if (shape.type == ShapeType::Box) {
        return Vec3(localDirection.x() >= 0 ? shape.halfExtents.x() : -shape.halfExtents.x(),
                    localDirection.y() >= 0 ? shape.halfExtents.y() : -shape.halfExtents.y(),
                    localDirection.z() >= 0 ? shape.halfExtents.z() : -shape.halfExtents.z());
    }
    if (shape.type != ShapeType::Convex || !shape.hull || shape.hull->vertices.empty()) return Vec3::Zero();
    const Vec3* best = &shape.hull->vertices.front();
    Real bestDot = best->dot(localDirection);
    for (const Vec3& vertex : shape.hull->vertices) {
        const Real dot = vertex.dot(localDirection);
        if (dot > bestDot) {
            bestDot = dot;
            best = &vertex;
        }
    }
    return *best;
}

Real faceSeparation(const Shape& shape, const Transform& transform, int face, const Shape& other,
                    const Transform& otherTransform) {
    const Vec3 normal = transform.rotate(polytopeFaceNormal(shape, face));
    if (face < 0 || face >= polytopeFaceCount(shape)) return -kRealMax;
    const Real offset = shape.type == ShapeType::Box ? shape.halfExtents[face / 2]
                                                     : shape.hull->faces[static_cast<std::size_t>(face)].offset;
    // Plane in world: n . x = offset + n . position.
    const Vec3 deepest = otherTransform.apply(polytopeSupport(other, otherTransform.rotateInverse(-normal)));
    return normal.dot(deepest - transform.position) - offset;
}

std::vector<PolytopeEdge> polytopeEdges(const Shape& shape) {
    std::vector<PolytopeEdge> edges;
    const int count = polytopeFaceCount(shape);
    FacePolygon polygon;
    for (int face = 0; face < count; ++face) {
        polytopeFace(shape, face, polygon);
        const int corners = static_cast<int>(polygon.corners.size());
        for (int k = 0; k < corners; ++k) {
            const int next = (k + 1) % corners;
            // Each edge is listed by two faces, once in each direction: keep one.
            if (polygon.vertexIndices[static_cast<std::size_t>(k)] >= polygon.vertexIndices[static_cast<std::size_t>(next)])
                continue;
            edges.push_back(PolytopeEdge{polygon.corners[static_cast<std::size_t>(k)],
                                         polygon.corners[static_cast<std::size_t>(next)],
                                         edgeIndexOf(polygon.vertexIndices[static_cast<std::size_t>(k)],
                                                     polygon.vertexIndices[static_cast<std::size_t>(next)])});
        }
    }
    return edges;
}

}  // namespace stepwise
