#pragma once
// Sutherland-Hodgman clipping of a polygon against planes (Sutherland and Hodgman, "Reentrant
// Polygon Clipping", CACM 1974; Ericson, Real-Time Collision Detection, 8.3.4): the incident face
// of a contact, clipped against the side planes of the reference face, is the patch where the two
// faces overlap. Every vertex remembers which features made it, so the contact points it becomes
// can be recognised next step (feature ids, world/contact.h).

#include "math/math.h"

#include <cstdint>
#include <vector>

namespace stepwise {

/// A vertex of the polygon being clipped, with the features that made it: one of the reference
/// shape (its face, a side edge, a corner) and one of the incident shape (a vertex, an edge, the
/// face). `edgeFeature` names the edge from this vertex to the next: an edge of the incident face
/// (`edgeOnReference` false) or a stretch along the reference side plane that cut it (true).
struct ClipVertex {
    Vec3 position = Vec3::Zero();
    std::uint32_t referenceFeature = 0;
    std::uint32_t incidentFeature = 0;
    std::uint32_t edgeFeature = 0;
    bool edgeOnReference = false;
    int sideStart = -1;  // for an edge along a side plane: the reference vertices of that side
    int sideEnd = -1;
};

/// A clipping plane: points with dot(normal, x) <= offset are kept. It stands on the side edge of
/// the reference face from vertex `sideStart` to `sideEnd` (vertex indices of the reference shape);
/// `sideFeature` is that edge's feature.
struct ClipPlane {
    Vec3 normal = Vec3::UnitX();
    Real offset = 0;
    int sideStart = -1;
    int sideEnd = -1;
    std::uint32_t sideFeature = 0;
};

/// What a crossing needs beyond the edge and the plane: where an edge that already runs along an
/// earlier side plane crosses a later one, the point is the reference face's corner between the two
/// sides (named by its vertex) over the incident face, named by `incidentFaceFeature`.
struct CrossingFeatures {
    std::uint32_t incidentFaceFeature = 0;
};

/// Clips `polygon` (a convex polygon, any winding) against one plane, into `clipped`. A vertex on
/// the plane counts as inside. Crossings get their features from the edge and the plane.
void clipAgainstPlane(const std::vector<ClipVertex>& polygon, const ClipPlane& plane,
                      const CrossingFeatures& crossing, std::vector<ClipVertex>& clipped);

/// Drops the vertices of a clipped polygon that add nothing to its shape: those within
/// `tolerance` of the previous kept vertex, and those within `tolerance` of the line through their
/// neighbours. Two faces that coincide to round-off clip into such vertices: an incident edge lying
/// within 10^-9 m of a side plane crosses it anywhere along its length, and the crossing sits part
/// way along the patch's edge, where it could be taken for a corner.
void removeRedundantVertices(std::vector<ClipVertex>& polygon, Real tolerance);

/// Clips against every plane in turn. Returns the clipped polygon (empty when nothing is left).
std::vector<ClipVertex> clipPolygon(std::vector<ClipVertex> polygon, const std::vector<ClipPlane>& planes,
                                    const CrossingFeatures& crossing);
/// The same in place: `polygon` becomes the clipped polygon, `working` holds each plane's result
/// (both keep their room from call to call).
void clipPolygon(std::vector<ClipVertex>& polygon, const std::vector<ClipPlane>& planes, const CrossingFeatures& crossing,
                 std::vector<ClipVertex>& working);

}  // namespace stepwise
