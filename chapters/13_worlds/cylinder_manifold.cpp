#include "13_worlds/cylinder_manifold.h"

#include "06_manifolds/polytope_faces.h"
#include "world/contact.h"

#include <cmath>
#include <vector>

namespace stepwise {

namespace {

/// A face of one shape in world space: outward unit normal, plane offset, corners in order.
struct WorldFace {
    Vec3 normal = Vec3::UnitY();
    Real offset = 0;
    std::vector<Vec3> corners;
    int index = 0;
};

/// A point of the incident feature and the corner (or clipped edge) it came from.
struct Tagged {
    Vec3 position;
    std::uint32_t feature;
};

// The cap of a cylinder on the side `sign` of its axis, corners in order around the rim.
void capCorners(const Shape& cylinder, const Transform& pose, Real sign, std::vector<Vec3>& corners) {
    corners.clear();
    for (int i = 0; i < kCapCorners; ++i) {
        const Real angle = sign * Real(2) * kPi * Real(i) / Real(kCapCorners);
        const Vec3 local(cylinder.radius * math::cos(angle), sign * cylinder.halfHeight, -cylinder.radius * math::sin(angle));
        corners.push_back(pose.apply(local));
    }
}

/// The face of `shape` whose outward normal is within kCapAngle of `outward`: a polytope's face, or
/// a cylinder's cap. False when no face is that close (an edge or a rim faces that way).
bool faceToward(const Shape& shape, const Transform& pose, const Vec3& outward, WorldFace& face) {
    if (isPolytope(shape)) {
        Real alignment = 0;
        const int index = mostAlignedFace(shape, pose, outward, alignment);
        if (index < 0 || alignment < math::cos(kCapAngle)) return false;
        const FacePolygon polygon = polytopeFace(shape, index);
        face.normal = pose.rotate(polygon.normal);
        face.corners.clear();
        for (const Vec3& corner : polygon.corners) face.corners.push_back(pose.apply(corner));
        face.offset = face.normal.dot(face.corners.front());
        face.index = index;
        return true;
    }
    if (shape.type != ShapeType::Cylinder) return false;
    const Vec3 axis = pose.rotate(Vec3::UnitY());
    const Real along = axis.dot(outward);
    if (std::abs(along) < math::cos(kCapAngle)) return false;
    const Real sign = along > 0 ? Real(1) : Real(-1);
    face.normal = sign * axis;
    capCorners(shape, pose, sign, face.corners);
    face.offset = face.normal.dot(pose.apply(Vec3(0, sign * shape.halfHeight, 0)));
    face.index = along > 0 ? 0 : 1;
    return true;
}

/// The cylinder's feature facing `toward` (world): its cap's corners, or its side's support
/// segment. False when a rim point faces that way.
bool incidentFeature(const Shape& cylinder, const Transform& pose, const Vec3& toward, std::vector<Tagged>& feature) {
    feature.clear();
    const Vec3 axis = pose.rotate(Vec3::UnitY());
    const Real along = axis.dot(toward);
    if (std::abs(along) >= math::cos(kCapAngle)) {
        std::vector<Vec3> corners;
        const Real sign = along > 0 ? Real(1) : Real(-1);
        capCorners(cylinder, pose, sign, corners);
        for (std::size_t i = 0; i < corners.size(); ++i)
            feature.push_back({corners[i], makeFeature(FeatureKind::Vertex, static_cast<std::uint32_t>(i + (sign > 0 ? 0 : 16)))});
        return true;
    }
    if (std::abs(along) > math::sin(kSideAngle)) return false;
    const Vec3 radial = (toward - along * axis).normalized();
    const Vec3 rim = pose.position + cylinder.radius * radial;
    feature.push_back({rim + cylinder.halfHeight * axis, makeFeature(FeatureKind::Edge, 32)});
    feature.push_back({rim - cylinder.halfHeight * axis, makeFeature(FeatureKind::Edge, 33)});
    return true;
}

/// Keeps the part of a convex polygon (or a segment: two points) inside the half space
/// normal . x <= offset; a crossing takes the feature of the side it crosses.
void clipBy(std::vector<Tagged>& polygon, const Vec3& normal, Real offset, std::uint32_t sideFeature) {
    if (polygon.empty()) return;
    std::vector<Tagged> kept;
    const std::size_t count = polygon.size();
    const std::size_t edges = count == 2 ? 1 : count;  // a segment has one edge, not a closed loop
    if (count == 1) {
        if (normal.dot(polygon[0].position) > offset) polygon.clear();
        return;
    }
    for (std::size_t i = 0; i < edges; ++i) {
        const Tagged& from = polygon[i];
        const Tagged& to = polygon[(i + 1) % count];
        const Real d0 = normal.dot(from.position) - offset, d1 = normal.dot(to.position) - offset;
        if (d0 <= 0) kept.push_back(from);
        if ((d0 < 0 && d1 > 0) || (d0 > 0 && d1 < 0))
            kept.push_back({from.position + (d0 / (d0 - d1)) * (to.position - from.position), sideFeature});
        if (count == 2 && d1 <= 0) kept.push_back(to);
    }
    polygon = kept;
}

}  // namespace

// [ch13-cylinder-manifold]
bool cylinderManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                      const ContactQuery& query, Real keepDistance, ManifoldCandidates& out) {
    const Vec3 n = query.normal;  // from A towards B
    // The reference face: B's facing A with A's cylinder incident, or A's facing B with B's.
    WorldFace faceB, faceA;
    const bool onB = a.type == ShapeType::Cylinder && faceToward(b, tb, -n, faceB);
    const bool onA = b.type == ShapeType::Cylinder && faceToward(a, ta, n, faceA);
    if (!onB && !onA) return false;
    const bool referenceB = onB && (!onA || faceB.normal.dot(-n) >= faceA.normal.dot(n));
    const WorldFace& face = referenceB ? faceB : faceA;
    std::vector<Tagged> incident;
    if (!incidentFeature(referenceB ? a : b, referenceB ? ta : tb, -face.normal, incident)) return false;
    // Clip to the reference face's sides: for an edge from c0 to c1, (c1 - c0) x m lies in the
    // face's plane across the edge, turned away from the face's centre.
    const std::size_t sides = face.corners.size();
    Vec3 centre = Vec3::Zero();
    for (const Vec3& corner : face.corners) centre += corner / Real(sides);
    for (std::size_t i = 0; i < sides && !incident.empty(); ++i) {
        const Vec3& c0 = face.corners[i];
        const Vec3& c1 = face.corners[(i + 1) % sides];
        Vec3 outward = (c1 - c0).cross(face.normal).normalized();
        if (outward.dot(centre - c0) > 0) outward = -outward;
        clipBy(incident, outward, outward.dot(c0), makeFeature(FeatureKind::Edge, static_cast<std::uint32_t>(40 + i)));
    }
    out.points.clear();
    out.normal = referenceB ? Vec3(-face.normal) : face.normal;
    out.kind = "cylinder";
    out.referenceSide = referenceB ? 2 : 1;
    const std::uint32_t referenceFeature = makeFeature(FeatureKind::Face, static_cast<std::uint32_t>(face.index));
    for (const Tagged& point : incident) {
        const Real separation = face.normal.dot(point.position) - face.offset;  // < 0: inside the reference shape
        if (separation > keepDistance) continue;
        const Vec3 onFace = point.position - separation * face.normal;
        ManifoldPoint candidate;
        candidate.depth = -separation;
        candidate.pointA = referenceB ? point.position : onFace;
        candidate.pointB = referenceB ? onFace : point.position;
        candidate.featureId = referenceB ? makeFeatureId(point.feature, referenceFeature)
                                         : makeFeatureId(referenceFeature, point.feature);
        out.points.push_back(candidate);
    }
    return !out.points.empty();
}
// [ch13-cylinder-manifold]

}  // namespace stepwise
