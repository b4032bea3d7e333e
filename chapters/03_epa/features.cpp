#include "03_epa/features.h"

#include "world/contact.h"

#include <algorithm>

namespace stepwise {

int supportVertexIndex(const Shape& shape, const Vec3& localPoint) {
    switch (shape.type) {
        case ShapeType::Box:
            // Support points of a box are corners: the signs of the coordinates say which.
            return (localPoint.x() > 0 ? 1 : 0) | (localPoint.y() > 0 ? 2 : 0) | (localPoint.z() > 0 ? 4 : 0);
        case ShapeType::Capsule: return localPoint.y() > 0 ? 1 : 0;
        case ShapeType::Sphere:
        case ShapeType::Cylinder:  // a rim point: no vertex names it
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: return -1;
        case ShapeType::Convex: {
            if (!shape.hull) return -1;
            int nearest = -1;
            Real nearestDistance = kRealMax;
            const auto& vertices = shape.hull->vertices;
            for (std::size_t i = 0; i < vertices.size(); ++i) {
                const Real distance = (vertices[i] - localPoint).squaredNorm();
                if (distance < nearestDistance) {
                    nearestDistance = distance;
                    nearest = static_cast<int>(i);
                }
            }
            return nearest;
        }
    }
    return -1;
}

std::uint32_t supportFeature(const Shape& shape, const Transform& transform, const Vec3 worldPoints[3]) {
    if (shape.type == ShapeType::Sphere) return makeFeature(FeatureKind::Core, 0);
    int indices[3];
    for (int i = 0; i < 3; ++i) {
        indices[i] = supportVertexIndex(shape, transform.applyInverse(worldPoints[i]));
        if (indices[i] < 0) return makeFeature(FeatureKind::None, 0);
    }
    std::sort(indices, indices + 3);
    const int distinct = static_cast<int>(std::unique(indices, indices + 3) - indices);
    // Indices above 63 may share an id with another feature: matching then merely fails more often.
    const auto index = [&](int i) { return static_cast<std::uint32_t>(indices[i]); };
    if (distinct == 1) return makeFeature(FeatureKind::Vertex, index(0));
    if (distinct == 2) return makeFeature(FeatureKind::Edge, index(0) * 64 + index(1));
    return makeFeature(FeatureKind::Face, (index(0) * 64 + index(1)) * 64 + index(2));
}

std::uint32_t epaFeatureId(const ConvexProxy& a, const ConvexProxy& b, const SupportPoint face[3]) {
    const Vec3 onA[3] = {face[0].onA, face[1].onA, face[2].onA};
    const Vec3 onB[3] = {face[0].onB, face[1].onB, face[2].onB};
    return makeFeatureId(supportFeature(*a.shape, a.transform, onA), supportFeature(*b.shape, b.transform, onB));
}

}  // namespace stepwise
