// Face and edge-edge contacts of polytopes, and the guards of an edge-edge contact.
#include "06_manifolds/polytope_manifold.h"

#include "02_gjk/segments.h"
#include "06_manifolds/clipping.h"
#include "06_manifolds/polytope_faces.h"
#include "world/contact.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

/// A face in world coordinates.
struct WorldFace {
    FacePolygon local;
    Vec3 normal = Vec3::Zero();
    Real offset = 0;
    std::vector<Vec3> corners;
};

/// Vertices of a clipped patch closer than this fraction of its size to a neighbour or to the
/// line through their neighbours are dropped (removeRedundantVertices): far above the round-off of
/// the clip (10^-7 of the size in float), far below anything the solver would notice.
constexpr Real kPatchTolerance = Real(1e-5);

/// The patch's size: its largest distance from its first vertex.
Real patchSize(const std::vector<ClipVertex>& polygon) {
    Real size = 0;
    for (const ClipVertex& vertex : polygon) size = std::max(size, (vertex.position - polygon.front().position).norm());
    return size;
}

void placeFace(const Shape& shape, const Transform& transform, int face, WorldFace& placed) {
    polytopeFace(shape, face, placed.local);
    placed.normal = transform.rotate(placed.local.normal);
    placed.corners.clear();
    for (const Vec3& corner : placed.local.corners) placed.corners.push_back(transform.apply(corner));
    placed.offset = placed.local.offset + placed.normal.dot(transform.position);
}

/// faceContact's working memory, one per thread, kept from call to call: a face contact allocates
/// nothing once the largest faces have been seen (they were a third of a rebuilt box pair's cost).
/// Nothing in it outlives a call.
struct FaceContactScratch {
    WorldFace reference, incident;
    std::vector<ClipVertex> polygon, working;
    std::vector<ClipPlane> planes;
};

FaceContactScratch& faceContactScratch() {
    thread_local FaceContactScratch scratch;
    return scratch;
}

// [ch06-face-contact]
/// Clips the incident face against the reference face's side planes and keeps what lies at most
/// keepDistance above the reference face. `referenceIsA` says which body owns the reference face.
bool faceContact(const Shape& reference, const Transform& referenceTransform, int referenceFace,
                 const Shape& incident, const Transform& incidentTransform, bool referenceIsA, Real keepDistance,
                 ManifoldCandidates& out) {
    FaceContactScratch& scratch = faceContactScratch();
    const WorldFace& ref = scratch.reference;
    placeFace(reference, referenceTransform, referenceFace, scratch.reference);
    Real alignment = 0;
    const int incidentFace = mostAlignedFace(incident, incidentTransform, -ref.normal, alignment);
    if (incidentFace < 0 || ref.corners.size() < 3) return false;
    const WorldFace& inc = scratch.incident;
    placeFace(incident, incidentTransform, incidentFace, scratch.incident);
    const std::size_t incidentCount = inc.corners.size();
    if (incidentCount < 3) return false;

    // The incident face as a polygon whose vertices and edges know their features.
    std::vector<ClipVertex>& polygon = scratch.polygon;
    polygon.assign(incidentCount, ClipVertex{});
    for (std::size_t k = 0; k < incidentCount; ++k) {
        polygon[k].position = inc.corners[k];
        polygon[k].referenceFeature = makeFeature(FeatureKind::Face, static_cast<std::uint32_t>(referenceFace));
        polygon[k].incidentFeature = makeFeature(FeatureKind::Vertex, static_cast<std::uint32_t>(inc.local.vertexIndices[k]));
        // Vertices and edges by their indices in the shape, not in the face: when two faces tie
        // for incident (an edge resting on a face), either gives the same ids.
        polygon[k].edgeFeature = makeFeature(
            FeatureKind::Edge, edgeIndexOf(inc.local.vertexIndices[k], inc.local.vertexIndices[(k + 1) % incidentCount]));
    }
    // Side planes: through each reference edge, perpendicular to the face, facing out. The corners
    // run counter-clockwise seen from outside, so edge x normal points away from the face.
    std::vector<ClipPlane>& planes = scratch.planes;
    planes.clear();
    const std::size_t referenceCount = ref.corners.size();
    for (std::size_t k = 0; k < referenceCount; ++k) {
        const Vec3& start = ref.corners[k];
        const Vec3& end = ref.corners[(k + 1) % referenceCount];
        const Vec3 outward = (end - start).cross(ref.normal);
        const Real length = outward.norm();
        if (!(length > kEpsilon)) continue;  // a degenerate edge bounds nothing
        ClipPlane plane;
        plane.normal = outward / length;
        plane.offset = plane.normal.dot(start);
        plane.sideStart = ref.local.vertexIndices[k];
        plane.sideEnd = ref.local.vertexIndices[(k + 1) % referenceCount];
        plane.sideFeature = makeFeature(FeatureKind::Edge, edgeIndexOf(plane.sideStart, plane.sideEnd));
        planes.push_back(plane);
    }
    CrossingFeatures crossing;
    crossing.incidentFaceFeature = makeFeature(FeatureKind::Face, static_cast<std::uint32_t>(incidentFace));
    clipPolygon(polygon, planes, crossing, scratch.working);
    const std::vector<ClipVertex>& clipped = polygon;
    removeRedundantVertices(polygon, kPatchTolerance * patchSize(polygon));

    out.normal = referenceIsA ? ref.normal : Vec3(-ref.normal);
    out.kind = referenceIsA ? "face_a" : "face_b";
    out.referenceSide = referenceIsA ? 1 : 2;
    out.points.clear();
    for (const ClipVertex& vertex : clipped) {
        const Real separation = ref.normal.dot(vertex.position) - ref.offset;
        if (!(separation <= keepDistance)) continue;
        // The incident point, and its projection on the reference face.
        const Vec3 onReference = vertex.position - separation * ref.normal;
        ManifoldPoint point;
        point.depth = -separation;
        point.pointA = referenceIsA ? onReference : vertex.position;
        point.pointB = referenceIsA ? vertex.position : onReference;
        point.featureId = referenceIsA ? makeFeatureId(vertex.referenceFeature, vertex.incidentFeature)
                                       : makeFeatureId(vertex.incidentFeature, vertex.referenceFeature);
        out.points.push_back(point);
    }
    return !out.points.empty();
}
// [ch06-face-contact]

/// The edges of a shape lying (within `tolerance`) in its supporting plane along `direction`.
std::vector<PolytopeEdge> supportingEdges(const Shape& shape, const Transform& transform, const Vec3& direction,
                                          Real tolerance) {
    const Vec3 local = transform.rotateInverse(direction);
    const Real height = polytopeSupport(shape, local).dot(local);
    std::vector<PolytopeEdge> found;
    for (const PolytopeEdge& edge : polytopeEdges(shape)) {
        if (edge.start.dot(local) >= height - tolerance && edge.end.dot(local) >= height - tolerance) {
            found.push_back(PolytopeEdge{transform.apply(edge.start), transform.apply(edge.end), edge.id});
        }
    }
    return found;
}

// [ch06-edge-contact]
/// One point where an edge of A crosses an edge of B: of the edges that support each shape along
/// the normal, the pairs whose cross product is (within round-off) most parallel to it, and of
/// those the pair passing nearest chapter 3's witness points (a box has four parallel edges per
/// direction, and more than one may lie within the tolerance of the supporting plane); the point
/// is their closest points.
bool edgeContact(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, const ContactQuery& query,
                 Real keepDistance, ManifoldCandidates& out) {
    const Vec3 normal = query.normal;
    const Real tolerance = Real(0.01) * std::max({boundingRadius(a), boundingRadius(b), Real(1e-3)});
    const std::vector<PolytopeEdge> edgesA = supportingEdges(a, ta, normal, tolerance);
    const std::vector<PolytopeEdge> edgesB = supportingEdges(b, tb, -normal, tolerance);
    const auto alignmentOf = [&](const PolytopeEdge& edgeA, const PolytopeEdge& edgeB) {
        const Vec3 axis = (edgeA.end - edgeA.start).cross(edgeB.end - edgeB.start);
        const Real length = axis.norm();
        return length > kEpsilon ? std::abs(axis.dot(normal)) / length : Real(-1);
    };
    Real bestAlignment = -1;
    for (const PolytopeEdge& edgeA : edgesA)
        for (const PolytopeEdge& edgeB : edgesB) bestAlignment = std::max(bestAlignment, alignmentOf(edgeA, edgeB));
    if (!(bestAlignment > 0)) return false;
    const PolytopeEdge* bestA = nullptr;
    const PolytopeEdge* bestB = nullptr;
    Vec3 onA = Vec3::Zero(), onB = Vec3::Zero();
    Real bestDistance = kRealMax;
    for (const PolytopeEdge& edgeA : edgesA) {
        for (const PolytopeEdge& edgeB : edgesB) {
            if (alignmentOf(edgeA, edgeB) < bestAlignment - Real(1e-3)) continue;
            Vec3 witnessOnA, witnessOnB, unused;
            closestPointsOfSegments<Real>(query.pointA, query.pointA, edgeA.start, edgeA.end, unused, witnessOnA);
            closestPointsOfSegments<Real>(query.pointB, query.pointB, edgeB.start, edgeB.end, unused, witnessOnB);
            const Real distance = (witnessOnA - query.pointA).norm() + (witnessOnB - query.pointB).norm();
            if (distance < bestDistance) {
                bestDistance = distance;
                bestA = &edgeA;
                bestB = &edgeB;
            }
        }
    }
    if (!bestA) return false;
    closestPointsOfSegments<Real>(bestA->start, bestA->end, bestB->start, bestB->end, onA, onB);
    Vec3 axis = (bestA->end - bestA->start).cross(bestB->end - bestB->start).normalized();
    if (axis.dot(normal) < 0) axis = -axis;
    ManifoldPoint point;
    point.pointA = onA;
    point.pointB = onB;
    point.depth = axis.dot(onA - onB);
    if (!(-point.depth <= keepDistance)) return false;
    point.featureId = makeFeatureId(makeFeature(FeatureKind::Edge, bestA->id), makeFeature(FeatureKind::Edge, bestB->id));
    out.normal = axis;
    out.kind = "edge_edge";
    out.points.assign(1, point);
    return true;
}
// [ch06-edge-contact]

// [ch06-edge-guards]
/// Speculative points beside an edge-edge point. One point cannot stop a body turning about it:
/// a box rolling over another's edge at 3 rad/s brings its next face down a centimetre and a half
/// within a frame, and nothing in the manifold sees it coming. So the faces that will meet next
/// (those most aligned with the normal, as Bullet's and Jolt's clipping choose them) are clipped
/// as a face contact would be, and each clipped point within keepDistance joins the edge point
/// as a guard. Its depth is read along the edge normal from its pair of points, which is never
/// more than along the face's own normal: a guard may act a little early, never late. Guards are
/// gaps only: a clipped point already below the face would push along the edge normal, not the
/// face's, and shove the bodies sideways (limbs of a ragdoll pile wedged between boxes would
/// creep); the edge point, whose depth is the shapes' overlap, stays the deepest.
void addFaceGuards(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, Real keepDistance,
                   ManifoldCandidates& out) {
    const Vec3 normal = out.normal;
    const ManifoldPoint edgePoint = out.points.front();
    Real alignmentA = 0, alignmentB = 0;
    const int faceA = mostAlignedFace(a, ta, normal, alignmentA);
    const int faceB = mostAlignedFace(b, tb, -normal, alignmentB);
    const bool referenceIsA = alignmentA >= alignmentB;
    thread_local ManifoldCandidates faces;
    const bool clipped = referenceIsA ? faceA >= 0 && faceContact(a, ta, faceA, b, tb, true, keepDistance, faces)
                                      : faceB >= 0 && faceContact(b, tb, faceB, a, ta, false, keepDistance, faces);
    if (!clipped) return;
    for (const ManifoldPoint& face : faces.points) {
        ManifoldPoint guard = face;
        guard.depth = normal.dot(face.pointA - face.pointB);
        // Within kFaceTolerance of the edge point's depth a guard lies at the pivot, which the edge
        // point already holds (where the clip crosses the same two edges, it is that point).
        if (!(guard.depth < std::min(Real(0), edgePoint.depth - kFaceTolerance)) || !(-guard.depth <= keepDistance))
            continue;
        out.points.push_back(guard);
    }
}
// [ch06-edge-guards]

}  // namespace

// [ch06-polytope-manifold]
namespace {

/// SAT's face query: the face of `shape` that separates `other` the most (least negative).
int bestSeparatingFace(const Shape& shape, const Transform& transform, const Shape& other,
                       const Transform& otherTransform, Real& separation) {
    int best = -1;
    separation = -kRealMax;
    const int count = polytopeFaceCount(shape);
    for (int face = 0; face < count; ++face) {
        const Real faceSeparationValue = faceSeparation(shape, transform, face, other, otherTransform);
        // Ties go to the lower index, so the same pose always picks the same face.
        if (faceSeparationValue > separation) {
            separation = faceSeparationValue;
            best = face;
        }
    }
    return best;
}

/// The depth of the deepest candidate point (-kRealMax when there is none).
Real deepestCandidate(const ManifoldCandidates& candidates) {
    Real deepest = -kRealMax;
    for (const ManifoldPoint& point : candidates.points) deepest = std::max(deepest, point.depth);
    return deepest;
}

// [ch06-reads-overlap]
/// Whether the candidates read the shapes' overlap: their deepest point within kFaceTolerance of
/// it, either way. Clipping keeps only what lies over the reference face; where the incident
/// body's deepest corner lies beyond the face's edge, every kept point reads shallower than the
/// shapes overlap (centimetres, for a hull that turned onto an edge), and the solve would let the
/// bodies sink by the difference. The other way, a held face reads along its own normal (up to
/// the hysteresis deeper), and two edges within round-off of parallel give an edge axis that is
/// anything at all (a hull a hair above the ground read 4.7 cm deep along one): the solve would
/// push the bodies apart by the difference.
bool readsOverlap(const ManifoldCandidates& candidates, Real overlap) {
    const Real deepest = deepestCandidate(candidates);
    return deepest >= overlap - kFaceTolerance && deepest <= overlap + kFaceTolerance;
}
// [ch06-reads-overlap]

}  // namespace

bool polytopeManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                      const ContactQuery& query, Real keepDistance, ManifoldCandidates& out,
                      ReferenceSide preferred) {
    // SAT's three candidates (Gregorius, GDC 2013): the best face of A, the best face of B, and
    // for edge pairs the axis chapter 3 found, whose separation is minus its depth. The faces are
    // searched in full rather than taken from chapter 3's normal: for shapes that just touch, EPA's
    // depth is zero along any of many normals and its normal says nothing about the faces.
    Real separationA = 0, separationB = 0;
    const int faceA = bestSeparatingFace(a, ta, b, tb, separationA);
    const int faceB = bestSeparatingFace(b, tb, a, ta, separationB);
    if (faceA < 0 || faceB < 0) return false;
    const Real axisSeparation = -query.depth;
    const auto build = [&](Real edgeTolerance, bool referenceIsA) {
        if (std::max(separationA, separationB) + edgeTolerance < axisSeparation) {
            if (!edgeContact(a, ta, b, tb, query, keepDistance, out)) return false;
            addFaceGuards(a, ta, b, tb, keepDistance, out);
            return true;
        }
        return referenceIsA ? faceContact(a, ta, faceA, b, tb, true, keepDistance, out)
                            : faceContact(b, tb, faceB, a, ta, false, keepDistance, out);
    };
    // The best axis bounds the overlap (EPA's depth never exceeds the shapes' own).
    const Real overlap = -std::max({separationA, separationB, axisSeparation});
    if (preferred != ReferenceSide::None) {
        // A pair that touched face to face last step stays a face contact, on the same reference
        // body, within the larger hysteresis...
        const bool heldA = preferred == ReferenceSide::A ? separationB <= separationA + kReferenceHysteresis
                                                          : separationA > separationB + kReferenceHysteresis;
        if (!build(kReferenceHysteresis, heldA)) return false;
        // ...while its points read no deeper than the shapes overlap. A held face reads depth along
        // its own normal, up to the hysteresis more than the best axis: a hull that turned, or a box
        // that fell onto another at an angle since last step, would read a centimetre the shapes do
        // not have, and the solve would push them apart by it.
        if (readsOverlap(out, overlap)) return true;
        out.points.clear();
        out.referenceSide = 0;
    }
    // A's face is the reference unless B's is clearly better: the bias keeps the choice steady
    // when both faces rest flat on each other (Box2D's b2CollidePolygons does the same).
    if (!build(kFaceTolerance, separationB <= separationA + kFaceTolerance)) return false;
    if (readsOverlap(out, overlap)) return true;
    out.points.clear();
    out.referenceSide = 0;
    return false;  // chapter 3's single point stands for the pair
}
// [ch06-polytope-manifold]

}  // namespace stepwise
