#pragma once
// An independent reference for chapter 6's polytope manifolds, written apart from the chapter's
// code so that the two can disagree: the separating axis test over every face normal and every
// edge-edge cross product (Ericson, Real-Time Collision Detection, 5.2.1; Gregorius, "The
// Separating Axis Test between Convex Polyhedra", GDC 2013), then the incident face clipped
// against the reference face's side planes (Sutherland-Hodgman), all in double. It shares no code
// with chapters/06_manifolds: boxes are spelled out from their half extents here, hulls read from
// ConvexHull's faces, and the clipper and the segment distance are its own.

#include "world/shape.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace stepwise::reference {

using V3 = Eigen::Vector3d;

/// A polytope in world coordinates: vertices, faces (vertex loops, counter-clockwise from
/// outside, with outward normals) and edges (vertex index pairs).
struct WorldPolytope {
    std::vector<V3> vertices;
    std::vector<std::vector<int>> faces;
    std::vector<V3> normals;
    std::vector<std::pair<int, int>> edges;
    V3 centre = V3::Zero();
};

inline V3 toWorld(const Transform& transform, const Vec3& local) {
    const Eigen::Quaterniond rotation = transform.rotation.cast<double>().normalized();
    return rotation * local.cast<double>() + transform.position.cast<double>();
}

inline void addEdgesFromFaces(WorldPolytope& polytope) {
    for (const auto& face : polytope.faces) {
        for (std::size_t k = 0; k < face.size(); ++k) {
            const int i = face[k], j = face[(k + 1) % face.size()];
            if (i < j) polytope.edges.emplace_back(i, j);
        }
    }
}

inline WorldPolytope placePolytope(const Shape& shape, const Transform& transform) {
    WorldPolytope polytope;
    if (shape.type == ShapeType::Box) {
        const Vec3& h = shape.halfExtents;
        // Corner (sx, sy, sz) for sx, sy, sz in {-1, +1}, index = x + 2y + 4z bits.
        for (int index = 0; index < 8; ++index) {
            const Vec3 corner((index & 1) ? h.x() : -h.x(), (index & 2) ? h.y() : -h.y(), (index & 4) ? h.z() : -h.z());
            polytope.vertices.push_back(toWorld(transform, corner));
        }
        // Faces written out by hand, counter-clockwise seen from outside.
        polytope.faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    } else if (shape.type == ShapeType::Convex && shape.hull) {
        for (const Vec3& vertex : shape.hull->vertices) polytope.vertices.push_back(toWorld(transform, vertex));
        for (const HullFace& face : shape.hull->faces) polytope.faces.push_back(face.vertexIndices);
    }
    for (const V3& v : polytope.vertices) polytope.centre += v / static_cast<double>(polytope.vertices.size());
    for (auto& face : polytope.faces) {
        // Newell's normal of the loop (robust for any planar polygon), turned outward: the loop is
        // reversed if it ran the other way, so side planes built from it face out.
        V3 normal = V3::Zero(), centroid = V3::Zero();
        for (std::size_t k = 0; k < face.size(); ++k) {
            const V3& p = polytope.vertices[static_cast<std::size_t>(face[k])];
            const V3& q = polytope.vertices[static_cast<std::size_t>(face[(k + 1) % face.size()])];
            normal += p.cross(q);
            centroid += p / static_cast<double>(face.size());
        }
        normal.normalize();
        if (normal.dot(centroid - polytope.centre) < 0) {
            std::reverse(face.begin(), face.end());
            normal = -normal;
        }
        polytope.normals.push_back(normal);
    }
    addEdgesFromFaces(polytope);
    return polytope;
}

struct ReferencePoint {
    V3 pointA = V3::Zero();
    V3 pointB = V3::Zero();
    double depth = 0;
};

struct ReferenceManifold {
    enum Kind { None, FaceA, FaceB, EdgeEdge } kind = None;
    V3 normal = V3::UnitY();  // A towards B
    std::vector<ReferencePoint> points;
    double bestFace = 0, bestEdge = 0;  // separations, for telling clear cases from ties
};

inline double faceSeparationOf(const WorldPolytope& owner, std::size_t face, const WorldPolytope& other) {
    const V3& n = owner.normals[face];
    const double offset = n.dot(owner.vertices[static_cast<std::size_t>(owner.faces[face][0])]);
    double lowest = std::numeric_limits<double>::max();
    for (const V3& v : other.vertices) lowest = std::min(lowest, n.dot(v) - offset);
    return lowest;
}

/// Closest points of two segments by the textbook case split (Ericson 5.1.9), in double.
inline void segmentClosest(const V3& p1, const V3& q1, const V3& p2, const V3& q2, V3& c1, V3& c2) {
    const V3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2);
    const double denom = a * e - b * b;
    double s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
    double t = (b * s + f) / e;
    if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
    }
    c1 = p1 + s * d1;
    c2 = p2 + t * d2;
}

/// The points of a face contact: `inc`'s face most opposed to the reference face, clipped against
/// the reference face's side planes, kept up to keepDistance above it.
inline std::vector<ReferencePoint> clipFacePoints(const WorldPolytope& a, const WorldPolytope& b, bool referenceIsA,
                                                  std::size_t refFace, double keepDistance) {
    const WorldPolytope& ref = referenceIsA ? a : b;
    const WorldPolytope& inc = referenceIsA ? b : a;
    const V3 refNormal = ref.normals[refFace];
    std::size_t incFace = 0;
    double lowest = 1e300;
    for (std::size_t f = 0; f < inc.faces.size(); ++f) {
        const double d = inc.normals[f].dot(refNormal);
        if (d < lowest) { lowest = d; incFace = f; }
    }
    std::vector<V3> polygon;
    for (int index : inc.faces[incFace]) polygon.push_back(inc.vertices[static_cast<std::size_t>(index)]);
    const auto& loop = ref.faces[refFace];
    for (std::size_t k = 0; k < loop.size() && !polygon.empty(); ++k) {
        const V3& p = ref.vertices[static_cast<std::size_t>(loop[k])];
        const V3& q = ref.vertices[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
        const V3 side = (q - p).cross(refNormal).normalized();
        std::vector<V3> next;
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const V3& s = polygon[i];
            const V3& e = polygon[(i + 1) % polygon.size()];
            const double ds = side.dot(s - p), de = side.dot(e - p);
            if (ds <= 0) next.push_back(s);
            if ((ds <= 0) != (de <= 0)) next.push_back(s + (ds / (ds - de)) * (e - s));
        }
        polygon.swap(next);
    }
    const double refOffset = refNormal.dot(ref.vertices[static_cast<std::size_t>(loop[0])]);
    std::vector<ReferencePoint> points;
    for (const V3& p : polygon) {
        const double separation = refNormal.dot(p) - refOffset;
        if (separation > keepDistance) continue;
        const V3 projected = p - separation * refNormal;
        points.push_back(referenceIsA ? ReferencePoint{projected, p, -separation} : ReferencePoint{p, projected, -separation});
    }
    return points;
}

/// The face of `polytope` whose outward normal is most aligned with `direction`.
inline std::size_t mostAlignedFaceOf(const WorldPolytope& polytope, const V3& direction, double& alignment) {
    std::size_t best = 0;
    alignment = -1e300;
    for (std::size_t f = 0; f < polytope.faces.size(); ++f) {
        if (polytope.normals[f].dot(direction) > alignment) { alignment = polytope.normals[f].dot(direction); best = f; }
    }
    return best;
}

/// SAT and clipping. `faceTolerance`: faces are preferred to edges and A's face to B's within it
/// (the engine's convention, Box2D's). Points more than keepDistance above the reference face are
/// dropped. An edge-edge answer also holds the guards: the clipped points of the faces most aligned
/// with its normal, read along it, apart (depth < 0) and more than `faceTolerance` shallower than
/// the edge point.
inline ReferenceManifold satManifold(const Shape& shapeA, const Transform& ta, const Shape& shapeB, const Transform& tb,
                                     double keepDistance, double faceTolerance) {
    ReferenceManifold result;
    const WorldPolytope a = placePolytope(shapeA, ta), b = placePolytope(shapeB, tb);
    if (a.faces.empty() || b.faces.empty()) return result;
    double bestA = -1e300, bestB = -1e300, bestEdge = -1e300;
    std::size_t faceA = 0, faceB = 0;
    for (std::size_t f = 0; f < a.faces.size(); ++f) {
        const double s = faceSeparationOf(a, f, b);
        if (s > bestA) { bestA = s; faceA = f; }
    }
    for (std::size_t f = 0; f < b.faces.size(); ++f) {
        const double s = faceSeparationOf(b, f, a);
        if (s > bestB) { bestB = s; faceB = f; }
    }
    std::pair<int, int> edgeA{0, 0}, edgeB{0, 0};
    V3 edgeAxis = V3::UnitY();
    for (const auto& ea : a.edges) {
        for (const auto& eb : b.edges) {
            const V3 da = a.vertices[static_cast<std::size_t>(ea.second)] - a.vertices[static_cast<std::size_t>(ea.first)];
            const V3 db = b.vertices[static_cast<std::size_t>(eb.second)] - b.vertices[static_cast<std::size_t>(eb.first)];
            V3 axis = da.cross(db);
            if (axis.norm() < 1e-9 * da.norm() * db.norm()) continue;
            axis.normalize();
            // Orient from A's edge outward: A's centre lies behind its edge.
            if (axis.dot(a.vertices[static_cast<std::size_t>(ea.first)] - a.centre) < 0) axis = -axis;
            double maxA = -1e300, minB = 1e300;
            for (const V3& v : a.vertices) maxA = std::max(maxA, axis.dot(v));
            for (const V3& v : b.vertices) minB = std::min(minB, axis.dot(v));
            // The axis must support both edges (Minkowski face test, done by brute force).
            const double edgeHeightA = axis.dot(a.vertices[static_cast<std::size_t>(ea.first)]);
            const double edgeHeightB = axis.dot(b.vertices[static_cast<std::size_t>(eb.first)]);
            if (edgeHeightA < maxA - 1e-9 || edgeHeightB > minB + 1e-9) continue;
            const double s = minB - maxA;
            if (s > bestEdge) { bestEdge = s; edgeA = ea; edgeB = eb; edgeAxis = axis; }
        }
    }
    result.bestFace = std::max(bestA, bestB);
    result.bestEdge = bestEdge;
    if (bestEdge > result.bestFace + faceTolerance) {
        V3 onA, onB;
        segmentClosest(a.vertices[static_cast<std::size_t>(edgeA.first)], a.vertices[static_cast<std::size_t>(edgeA.second)],
                       b.vertices[static_cast<std::size_t>(edgeB.first)], b.vertices[static_cast<std::size_t>(edgeB.second)], onA, onB);
        result.kind = ReferenceManifold::EdgeEdge;
        result.normal = edgeAxis;
        const double depth = edgeAxis.dot(onA - onB);
        if (!(-depth <= keepDistance)) return result;
        result.points.push_back({onA, onB, depth});
        // Guards: the faces most aligned with the edge normal, clipped, read along that normal.
        double alignA = 0, alignB = 0;
        const std::size_t guardA = mostAlignedFaceOf(a, edgeAxis, alignA);
        const std::size_t guardB = mostAlignedFaceOf(b, -edgeAxis, alignB);
        const bool guardOnA = alignA >= alignB;
        for (const ReferencePoint& face : clipFacePoints(a, b, guardOnA, guardOnA ? guardA : guardB, keepDistance)) {
            const double guardDepth = edgeAxis.dot(face.pointA - face.pointB);
            if (guardDepth < std::min(0.0, depth - faceTolerance) && -guardDepth <= keepDistance)
                result.points.push_back({face.pointA, face.pointB, guardDepth});
        }
        return result;
    }
    const bool referenceIsA = bestB <= bestA + faceTolerance;
    result.kind = referenceIsA ? ReferenceManifold::FaceA : ReferenceManifold::FaceB;
    result.normal = referenceIsA ? a.normals[faceA] : V3(-b.normals[faceB]);
    result.points = clipFacePoints(a, b, referenceIsA, referenceIsA ? faceA : faceB, keepDistance);
    return result;
}

}  // namespace stepwise::reference
