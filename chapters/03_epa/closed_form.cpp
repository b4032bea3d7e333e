// Closed-form contacts: closest points of the shapes' cores, inflated by their radii.
#include "03_epa/closed_form.h"

#include "02_gjk/segments.h"
#include "02_gjk/tolerances.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

// [ch03-inflate]
/// Contact of two "fat points": cores coreA and coreB with radii. The normal runs from core to
/// core; when the cores coincide every direction gives the same depth, so `fallback` decides.
/// Coincide means closer than the cores' own round-off: two capsule axes that cross are computed
/// a few rounding errors apart, and the direction of that rounding noise is no normal (found by
/// fuzz_narrowphase: it left the contact point inside the capsule by a third of its radius).
/// The round-off is that of the numbers the cores were computed from, `coreSpan` (the largest
/// coordinate among centres and segment ends): the closest point of a 47 m capsule's axis to a
/// crossing axis at its centre is off by millionths of 47 m, not of its small coordinates.
ContactQuery inflateCores(const Vec3& coreA, Real radiusA, const Vec3& coreB, Real radiusB, Real coreSpan,
                          const Vec3& fallbackNormal, const char* routine) {
    ContactQuery query;
    query.routine = routine;
    const Vec3 between = coreB - coreA;
    const Real distance = between.norm();
    const Real roundOff = tolerance::kTouching * (coreSpan + radiusA + radiusB);
    query.normal = distance > roundOff ? Vec3(between / distance) : fallbackNormal;
    if (!isFinite(query.normal)) query.normal = fallbackNormal;
    query.depth = radiusA + radiusB - distance;
    query.intersect = query.depth >= 0;
    query.pointA = coreA + radiusA * query.normal;
    query.pointB = coreB - radiusB * query.normal;
    return query;
}
// [ch03-inflate]

/// A unit direction perpendicular to `axis`, leaning towards `towards` when it can.
Vec3 perpendicularTowards(const Vec3& axis, const Vec3& towards) {
    const Vec3 unitAxis = axis.normalized();
    const Vec3 side = towards - unitAxis * unitAxis.dot(towards);
    const Real length = side.norm();
    return length > 0 && isFinite(length) ? Vec3(side / length) : anyPerpendicular(unitAxis);
}

// [ch03-closed-form-features]
constexpr std::uint32_t kSphereCore = makeFeature(FeatureKind::Core, 0);

/// A capsule's feature at a point of its core segment: an end cap (vertex 0 bottom, 1 top) or
/// the side (edge 0), so a capsule rolling along its side keeps one id.
std::uint32_t segmentFeature(const Vec3& onSegment, const Vec3& bottom, const Vec3& top) {
    const Real endTolerance = kEpsilon * kEpsilon * std::max((top - bottom).squaredNorm(), Real(1e-30)) * 16;
    if ((onSegment - bottom).squaredNorm() <= endTolerance) return makeFeature(FeatureKind::Vertex, 0);
    if ((onSegment - top).squaredNorm() <= endTolerance) return makeFeature(FeatureKind::Vertex, 1);
    return makeFeature(FeatureKind::Edge, 0);
}

/// The box feature closest to a sphere centre, from which coordinates the clamp changed: one
/// axis clamped is a face (2 per axis), two an edge (4 per free axis), three a corner (sign bits).
std::uint32_t boxRegionFeature(const Vec3& local, const Vec3& clamped) {
    int clampedAxes = 0;
    std::uint32_t signBits = 0;
    int freeAxis = 0, faceAxis = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (local[axis] > 0) signBits |= 1u << axis;
        if (clamped[axis] != local[axis]) {
            ++clampedAxes;
            faceAxis = axis;
        } else {
            freeAxis = axis;
        }
    }
    if (clampedAxes == 3) return makeFeature(FeatureKind::Vertex, signBits);
    if (clampedAxes == 2) {
        const std::uint32_t otherBits = signBits & ~(1u << freeAxis);
        return makeFeature(FeatureKind::Edge, static_cast<std::uint32_t>(freeAxis) * 8 + otherBits);
    }
    return makeFeature(FeatureKind::Face, static_cast<std::uint32_t>(faceAxis) * 2 + ((signBits >> faceAxis) & 1u));
}
// [ch03-closed-form-features]

}  // namespace

ContactQuery collideSpheres(const Vec3& centerA, Real radiusA, const Vec3& centerB, Real radiusB) {
    const Real span = centerA.cwiseAbs().maxCoeff() + centerB.cwiseAbs().maxCoeff();
    ContactQuery query = inflateCores(centerA, radiusA, centerB, radiusB, span, Vec3::UnitY(), "sphere_sphere");
    query.featureId = makeFeatureId(kSphereCore, kSphereCore);
    return query;
}

// [ch03-box-sphere]
ContactQuery collideBoxSphere(const Vec3& halfExtents, const Transform& box, const Vec3& center, Real radius) {
    ContactQuery query;
    query.routine = "box_sphere";
    const Vec3 local = box.applyInverse(center);
    const Vec3 clamped = local.cwiseMax(-halfExtents).cwiseMin(halfExtents);
    Vec3 localNormal;
    Vec3 localBoxPoint = clamped;
    std::uint32_t boxFeature = 0;
    if (clamped != local) {
        // Centre outside the box: the clamped point is the closest point of the box.
        boxFeature = boxRegionFeature(local, clamped);
        const Vec3 outward = local - clamped;
        const Real distance = outward.norm();
        localNormal = outward / distance;
        query.depth = radius - distance;
    } else {
        // Centre inside (or on) the box: it leaves fastest through the nearest face.
        const Vec3 faceGaps = halfExtents - local.cwiseAbs();
        int axis = 0;
        faceGaps.minCoeff(&axis);
        const Real side = local[axis] >= 0 ? Real(1) : Real(-1);
        localNormal = Vec3::Zero();
        localNormal[axis] = side;
        localBoxPoint[axis] = side * halfExtents[axis];
        query.depth = radius + faceGaps[axis];
        boxFeature = makeFeature(FeatureKind::Face, static_cast<std::uint32_t>(axis) * 2 + (side > 0 ? 1u : 0u));
    }
    query.featureId = makeFeatureId(boxFeature, kSphereCore);
    query.intersect = query.depth >= 0;
    query.normal = box.rotate(localNormal);
    query.pointA = box.apply(localBoxPoint);
    query.pointB = center - radius * query.normal;
    return query;
}
// [ch03-box-sphere]

ContactQuery collideCapsuleSphere(Real capsuleRadius, Real halfHeight, const Transform& capsule,
                                  const Vec3& center, Real radius) {
    const Vec3 top = capsule.apply(Vec3(0, halfHeight, 0)), bottom = capsule.apply(Vec3(0, -halfHeight, 0));
    const Vec3 axis = capsule.rotate(Vec3::UnitY());
    Vec3 onSegment, onCenter;
    closestPointsOfSegments(bottom, top, center, center, onSegment, onCenter);
    // A centre on the axis: any direction across the axis is as deep; lean away from the centre.
    const Vec3 fallback = perpendicularTowards(axis, center - capsule.position);
    const Real span = capsule.position.cwiseAbs().maxCoeff() + halfHeight + center.cwiseAbs().maxCoeff();
    ContactQuery query = inflateCores(onSegment, capsuleRadius, center, radius, span, fallback, "capsule_sphere");
    query.featureId = makeFeatureId(segmentFeature(onSegment, bottom, top), kSphereCore);
    return query;
}

ContactQuery collideCapsules(Real radiusA, Real halfHeightA, const Transform& capsuleA, Real radiusB,
                             Real halfHeightB, const Transform& capsuleB) {
    const Vec3 axisA = capsuleA.rotate(Vec3::UnitY()), axisB = capsuleB.rotate(Vec3::UnitY());
    Vec3 onA, onB;
    const Vec3 bottomA = capsuleA.apply(Vec3(0, -halfHeightA, 0)), topA = capsuleA.apply(Vec3(0, halfHeightA, 0));
    const Vec3 bottomB = capsuleB.apply(Vec3(0, -halfHeightB, 0)), topB = capsuleB.apply(Vec3(0, halfHeightB, 0));
    closestPointsOfSegments(bottomA, topA, bottomB, topB, onA, onB);
    // Crossing axes: the segments' Minkowski difference is a flat parallelogram around the
    // origin, so the shallowest way out is across its plane, the common perpendicular.
    const Vec3 centres = capsuleB.position - capsuleA.position;
    Vec3 fallback = axisA.cross(axisB);
    const Real length = fallback.norm();
    if (length > kEpsilon) {
        fallback /= length;
        if (fallback.dot(centres) < 0) fallback = -fallback;
    } else {
        fallback = perpendicularTowards(axisA, centres);
    }
    const Real span = capsuleA.position.cwiseAbs().maxCoeff() + halfHeightA + capsuleB.position.cwiseAbs().maxCoeff() +
                      halfHeightB;
    ContactQuery query = inflateCores(onA, radiusA, onB, radiusB, span, fallback, "capsule_capsule");
    query.featureId = makeFeatureId(segmentFeature(onA, bottomA, topA), segmentFeature(onB, bottomB, topB));
    return query;
}

ContactQuery swapped(const ContactQuery& query) {
    ContactQuery result = query;
    result.normal = -query.normal;
    result.pointA = query.pointB;
    result.pointB = query.pointA;
    result.featureId = swappedFeatureId(query.featureId);
    return result;
}

}  // namespace stepwise
