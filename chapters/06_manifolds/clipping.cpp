// Sutherland-Hodgman clipping with feature bookkeeping.
#include "06_manifolds/clipping.h"

#include "06_manifolds/polytope_faces.h"
#include "world/contact.h"

#include <algorithm>

namespace stepwise {

namespace {

// [ch06-crossing-features]
/// The point where the edge leaving `from` crosses the plane. Its features: the side edge of the
/// reference face against the incident edge it cuts; or, when the edge itself already lies on an
/// earlier side plane, the reference face's corner between the two side planes against the
/// incident face (the corner of the reference face stands over the incident face).
ClipVertex crossingVertex(const ClipVertex& from, const ClipVertex& to, Real distanceFrom, Real distanceTo,
                          const ClipPlane& plane, const CrossingFeatures& crossing) {
    ClipVertex vertex;
    const Real t = distanceFrom / (distanceFrom - distanceTo);
    vertex.position = from.position + t * (to.position - from.position);
    if (from.edgeOnReference) {
        // Two sides of a convex face meet at their shared vertex; sides that share none meet
        // outside the face, where a later plane clips the point away, so any id will do.
        const int corner = from.sideEnd == plane.sideStart ? plane.sideStart
                           : from.sideStart == plane.sideEnd ? from.sideStart : plane.sideStart;
        vertex.referenceFeature = makeFeature(FeatureKind::Vertex, static_cast<std::uint32_t>(std::max(corner, 0)));
        vertex.incidentFeature = crossing.incidentFaceFeature;
    } else {
        vertex.referenceFeature = plane.sideFeature;
        vertex.incidentFeature = from.edgeFeature;
    }
    return vertex;
}
// [ch06-crossing-features]

}  // namespace

// [ch06-clip-plane]
void clipAgainstPlane(const std::vector<ClipVertex>& polygon, const ClipPlane& plane,
                      const CrossingFeatures& crossing, std::vector<ClipVertex>& clipped) {
    clipped.clear();
    const std::size_t count = polygon.size();
    if (count == 0) return;
    for (std::size_t i = 0; i < count; ++i) {
        const ClipVertex& from = polygon[i];
        const ClipVertex& to = polygon[(i + 1) % count];
        const Real distanceFrom = plane.normal.dot(from.position) - plane.offset;
        const Real distanceTo = plane.normal.dot(to.position) - plane.offset;
        const bool fromInside = distanceFrom <= 0, toInside = distanceTo <= 0;
        if (fromInside) clipped.push_back(from);
        if (fromInside == toInside) continue;
        // The edge crosses: a new vertex on the plane. Leaving the inside, the edge from the new
        // vertex runs along the plane to where the polygon comes back in.
        ClipVertex vertex = crossingVertex(from, to, distanceFrom, distanceTo, plane, crossing);
        if (fromInside) {
            vertex.edgeOnReference = true;
            vertex.sideStart = plane.sideStart;
            vertex.sideEnd = plane.sideEnd;
            vertex.edgeFeature = plane.sideFeature;
        } else {
            vertex.edgeOnReference = from.edgeOnReference;
            vertex.sideStart = from.sideStart;
            vertex.sideEnd = from.sideEnd;
            vertex.edgeFeature = from.edgeFeature;
        }
        clipped.push_back(vertex);
    }
}
// [ch06-clip-plane]

// [ch06-redundant-vertices]
void removeRedundantVertices(std::vector<ClipVertex>& polygon, Real tolerance) {
    const Real squaredTolerance = tolerance * tolerance;
    bool removed = true;
    while (removed && polygon.size() > 2) {
        removed = false;
        const std::size_t count = polygon.size();
        for (std::size_t i = 0; i < count; ++i) {
            const Vec3& before = polygon[(i + count - 1) % count].position;
            const Vec3& vertex = polygon[i].position;
            const Vec3& after = polygon[(i + 1) % count].position;
            const Vec3 chord = after - before;
            const Real chordLength2 = chord.squaredNorm();
            const bool duplicate = (vertex - before).squaredNorm() <= squaredTolerance;
            // Distance from the chord's line: |chord x (vertex - before)| / |chord|.
            const bool onChord = chordLength2 > squaredTolerance &&
                                 chord.cross(vertex - before).squaredNorm() <= squaredTolerance * chordLength2 &&
                                 (vertex - before).dot(chord) > 0 && (vertex - after).dot(chord) < 0;
            if (duplicate || onChord) {
                polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(i));
                removed = true;
                break;
            }
        }
    }
}
// [ch06-redundant-vertices]

std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> polygon, const std::vector<ClipPlane>& planes,
                                    const CrossingFeatures& crossing) {
    std::vector<ClipVertex> working;
    clipPolygon(polygon, planes, crossing, working);
    return polygon;
}

void clipPolygon(std::vector<ClipVertex>& polygon, const std::vector<ClipPlane>& planes, const CrossingFeatures& crossing,
                 std::vector<ClipVertex>& working) {
    for (const ClipPlane& plane : planes) {
        clipAgainstPlane(polygon, plane, crossing, working);
        polygon.swap(working);
        if (polygon.empty()) break;
    }
}

}  // namespace stepwise
