// Closed-form manifolds of spheres and capsules.
#include "06_manifolds/round_manifolds.h"

#include "02_gjk/segments.h"
#include "06_manifolds/polytope_faces.h"
#include "world/contact.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

ManifoldPoint singlePoint(const ContactQuery& query) {
    ManifoldPoint point;
    point.pointA = query.pointA;
    point.pointB = query.pointB;
    point.depth = query.depth;
    point.featureId = query.featureId;
    return point;
}

namespace {

struct Segment {
    Vec3 start = Vec3::Zero();  // the capsule's bottom cap centre (vertex 0)
    Vec3 end = Vec3::Zero();    // its top (vertex 1)
};

Segment capsuleSegment(const Shape& capsule, const Transform& transform) {
    return Segment{transform.apply(Vec3(0, -capsule.halfHeight, 0)), transform.apply(Vec3(0, capsule.halfHeight, 0))};
}

/// A point of two round cores: surface points along `normal` (A towards B), pointA - pointB = depth * normal.
ManifoldPoint roundPoint(const Vec3& coreA, Real radiusA, const Vec3& coreB, Real radiusB, const Vec3& normal,
                         std::uint32_t featureId) {
    ManifoldPoint point;
    point.depth = radiusA + radiusB - normal.dot(coreB - coreA);
    point.pointA = coreA + radiusA * normal;
    point.pointB = point.pointA - point.depth * normal;
    point.featureId = featureId;
    return point;
}

// [ch06-round-ends]
/// Whether a capsule's ends stand for the contact: the deepest reads the shapes' overlap (chapter
/// 3's depth) within kRoundEndsTolerance. Where the capsule's deepest part lies beyond the face's
/// edge, or two capsules cross, the ends read shallower than the shapes overlap.
bool reachesQueryDepth(const ManifoldCandidates& out, const ContactQuery& query) {
    Real deepest = -kRealMax;
    for (const ManifoldPoint& point : out.points) deepest = std::max(deepest, point.depth);
    return deepest >= query.depth - kRoundEndsTolerance;
}
// [ch06-round-ends]

// [ch06-capsule-capsule]
/// Nearly parallel capsules: the two ends of the stretch where their segments overlap, seen along
/// A's axis. Each end is a cap of A or of B; its feature is that cap against the other's segment.
bool parallelCapsules(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, const ContactQuery& query,
                      Real keepDistance, ManifoldCandidates& out) {
    const Vec3& normal = query.normal;
    const Segment segmentA = capsuleSegment(a, ta), segmentB = capsuleSegment(b, tb);
    const Vec3 axisA = segmentA.end - segmentA.start, axisB = segmentB.end - segmentB.start;
    const Real lengthA = axisA.norm(), lengthB = axisB.norm();
    if (!(lengthA > kEpsilon) || !(lengthB > kEpsilon)) return false;
    if (std::abs(axisA.dot(axisB)) < kParallelCapsules * lengthA * lengthB) return false;
    const Vec3 direction = axisA / lengthA;
    // B's caps along A's axis, in A's parameter (0 at A's bottom cap, lengthA at its top).
    Real b0 = direction.dot(segmentB.start - segmentA.start), b1 = direction.dot(segmentB.end - segmentA.start);
    int capLow = 0, capHigh = 1;
    if (b0 > b1) {
        std::swap(b0, b1);
        std::swap(capLow, capHigh);
    }
    const Real low = std::max(Real(0), b0), high = std::min(lengthA, b1);
    if (!(high - low > Real(1e-3) * lengthA)) return false;  // the stretch is a point: one contact
    const std::uint32_t segmentFeature = makeFeature(FeatureKind::Edge, 0);
    const Real ends[2] = {low, high};
    const std::uint32_t features[2] = {
        low == b0 ? makeFeatureId(segmentFeature, makeFeature(FeatureKind::Vertex, static_cast<std::uint32_t>(capLow)))
                  : makeFeatureId(makeFeature(FeatureKind::Vertex, 0), segmentFeature),
        high == b1 ? makeFeatureId(segmentFeature, makeFeature(FeatureKind::Vertex, static_cast<std::uint32_t>(capHigh)))
                   : makeFeatureId(makeFeature(FeatureKind::Vertex, 1), segmentFeature)};
    out.points.clear();
    out.normal = normal;
    out.kind = "round";
    for (int k = 0; k < 2; ++k) {
        const Vec3 onA = segmentA.start + ends[k] * direction;
        Vec3 closestOnB, unused;
        closestPointsOfSegments<Real>(onA, onA, segmentB.start, segmentB.end, unused, closestOnB);
        const ManifoldPoint point = roundPoint(onA, a.radius, closestOnB, b.radius, normal, features[k]);
        if (-point.depth <= keepDistance) out.points.push_back(point);
    }
    return !out.points.empty() && reachesQueryDepth(out, query);
}
// [ch06-capsule-capsule]

// [ch06-capsule-face]
/// A capsule (`capsule`) on a face of a polytope: its segment clipped against the face's side
/// planes, each surviving end a point. `polytopeIsA` says which body is the polytope.
bool capsuleOnFace(const Shape& polytope, const Transform& polytopeTransform, const Shape& capsule,
                   const Transform& capsuleTransform, bool polytopeIsA, const ContactQuery& query,
                   Real keepDistance, ManifoldCandidates& out) {
    const Vec3 towardsCapsule = polytopeIsA ? query.normal : Vec3(-query.normal);
    Real alignment = 0;
    const int face = mostAlignedFace(polytope, polytopeTransform, towardsCapsule, alignment);
    if (face < 0) return false;
    thread_local FacePolygon local;  // keeps its room from call to call
    polytopeFace(polytope, face, local);
    const std::size_t count = local.corners.size();
    if (count < 3) return false;
    const Vec3 faceNormal = polytopeTransform.rotate(local.normal);
    const Real faceOffset = local.offset + faceNormal.dot(polytopeTransform.position);
    const Segment segment = capsuleSegment(capsule, capsuleTransform);
    const Real separation0 = faceNormal.dot(segment.start) - faceOffset - capsule.radius;
    const Real separation1 = faceNormal.dot(segment.end) - faceOffset - capsule.radius;
    // Only a face contact: the face must separate the shapes as well as chapter 3's axis does.
    if (std::min(separation0, separation1) + Real(0.0005) < -query.depth) return false;

    // Clip the segment: its parameters [low, high] inside every side plane.
    Real low = 0, high = 1;
    std::uint32_t lowFeature = makeFeature(FeatureKind::Vertex, 0), highFeature = makeFeature(FeatureKind::Vertex, 1);
    std::uint32_t lowOther = makeFeature(FeatureKind::Face, static_cast<std::uint32_t>(face)), highOther = lowOther;
    const Vec3 delta = segment.end - segment.start;
    for (std::size_t k = 0; k < count && low <= high; ++k) {
        const Vec3 start = polytopeTransform.apply(local.corners[k]);
        const Vec3 end = polytopeTransform.apply(local.corners[(k + 1) % count]);
        const Vec3 outward = (end - start).cross(faceNormal);
        const Real distanceStart = outward.dot(segment.start - start), rate = outward.dot(delta);
        const std::uint32_t side = makeFeature(FeatureKind::Edge, edgeIndexOf(local.vertexIndices[k], local.vertexIndices[(k + 1) % count]));
        if (std::abs(rate) <= kEpsilon * outward.norm() * delta.norm()) {
            if (distanceStart > 0) return false;  // parallel to the side and outside it
            continue;
        }
        const Real t = -distanceStart / rate;
        if (rate > 0 && t < high) {  // leaving through this side
            high = t;
            highFeature = makeFeature(FeatureKind::Edge, 0);
            highOther = side;
        } else if (rate < 0 && t > low) {  // entering through it
            low = t;
            lowFeature = makeFeature(FeatureKind::Edge, 0);
            lowOther = side;
        }
    }
    if (!(low <= high)) return false;
    out.points.clear();
    out.normal = polytopeIsA ? faceNormal : Vec3(-faceNormal);
    out.kind = "round";
    const Real parameters[2] = {low, high};
    const std::uint32_t capsuleFeatures[2] = {lowFeature, highFeature};
    const std::uint32_t polytopeFeatures[2] = {lowOther, highOther};
    const int ends = high - low > Real(1e-6) ? 2 : 1;
    for (int k = 0; k < ends; ++k) {
        const Vec3 core = segment.start + parameters[k] * delta;
        const Real coreSeparation = faceNormal.dot(core) - faceOffset;
        const Vec3 onCapsule = core - capsule.radius * faceNormal;
        const Vec3 onFace = core - coreSeparation * faceNormal;
        ManifoldPoint point;
        point.depth = capsule.radius - coreSeparation;
        if (!(-point.depth <= keepDistance)) continue;
        point.pointA = polytopeIsA ? onFace : onCapsule;
        point.pointB = polytopeIsA ? onCapsule : onFace;
        point.featureId = polytopeIsA ? makeFeatureId(polytopeFeatures[k], capsuleFeatures[k])
                                      : makeFeatureId(capsuleFeatures[k], polytopeFeatures[k]);
        out.points.push_back(point);
    }
    return !out.points.empty() && reachesQueryDepth(out, query);
}
// [ch06-capsule-face]

}  // namespace

bool roundManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                   const ContactQuery& query, Real keepDistance, ManifoldCandidates& out) {
    if (a.type == ShapeType::Capsule && b.type == ShapeType::Capsule &&
        parallelCapsules(a, ta, b, tb, query, keepDistance, out))
        return true;
    if (a.type == ShapeType::Capsule && isPolytope(b) && capsuleOnFace(b, tb, a, ta, false, query, keepDistance, out))
        return true;
    if (b.type == ShapeType::Capsule && isPolytope(a) && capsuleOnFace(a, ta, b, tb, true, query, keepDistance, out))
        return true;
    // Spheres, and capsules touching at one point: chapter 3's answer.
    if (!(-query.depth <= keepDistance)) return false;
    out.normal = query.normal;
    out.kind = "single";
    out.points.assign(1, singlePoint(query));
    return true;
}

}  // namespace stepwise
