// Closed-form contacts: closest points of the shapes' cores, inflated by their radii.
#include "03_epa/closed_form.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

Real clamp01(Real value) { return std::min(std::max(value, Real(0)), Real(1)); }

// [ch03-inflate]
/// Contact of two "fat points": cores coreA and coreB with radii. The normal runs from core to
/// core; when the cores coincide every direction gives the same depth, so `fallback` decides.
ContactQuery inflateCores(const Vec3& coreA, Real radiusA, const Vec3& coreB, Real radiusB,
                          const Vec3& fallbackNormal, const char* routine) {
    ContactQuery query;
    query.routine = routine;
    const Vec3 between = coreB - coreA;
    const Real distance = between.norm();
    query.normal = distance > 0 ? Vec3(between / distance) : fallbackNormal;
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

}  // namespace

ContactQuery collideSpheres(const Vec3& centerA, Real radiusA, const Vec3& centerB, Real radiusB) {
    return inflateCores(centerA, radiusA, centerB, radiusB, Vec3::UnitY(), "sphere_sphere");
}

// [ch03-box-sphere]
ContactQuery collideBoxSphere(const Vec3& halfExtents, const Transform& box, const Vec3& center, Real radius) {
    ContactQuery query;
    query.routine = "box_sphere";
    const Vec3 local = box.applyInverse(center);
    const Vec3 clamped = local.cwiseMax(-halfExtents).cwiseMin(halfExtents);
    Vec3 localNormal;
    Vec3 localBoxPoint = clamped;
    if (clamped != local) {
        // Centre outside the box: the clamped point is the closest point of the box.
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
    }
    query.intersect = query.depth >= 0;
    query.normal = box.rotate(localNormal);
    query.pointA = box.apply(localBoxPoint);
    query.pointB = center - radius * query.normal;
    return query;
}
// [ch03-box-sphere]

void closestPointsOfSegments(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2, Vec3& onFirst,
                             Vec3& onSecond) {
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const Real a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    const Real tiny = kEpsilon * kEpsilon * std::max({a, e, r.squaredNorm(), Real(1e-30)});
    Real s = 0, t = 0;
    if (a <= tiny && e <= tiny) {
        s = t = 0;  // both segments are points
    } else if (a <= tiny) {
        t = clamp01(f / e);
    } else {
        const Real c = d1.dot(r);
        if (e <= tiny) {
            s = clamp01(-c / a);
        } else {
            const Real b = d1.dot(d2);
            const Real denominator = a * e - b * b;
            if (denominator > kEpsilon * a * e) {
                s = clamp01((b * f - c * e) / denominator);
            } else {
                // Parallel: every point of the overlap is equally close; take its middle so a
                // single contact point sits in the centre of the touching stretch.
                s = Real(0.5) * (clamp01((p2 - p1).dot(d1) / a) + clamp01((q2 - p1).dot(d1) / a));
            }
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = clamp01(-c / a);
            } else if (t > 1) {
                t = 1;
                s = clamp01((b - c) / a);
            }
        }
    }
    onFirst = p1 + s * d1;
    onSecond = p2 + t * d2;
}

ContactQuery collideCapsuleSphere(Real capsuleRadius, Real halfHeight, const Transform& capsule,
                                  const Vec3& center, Real radius) {
    const Vec3 top = capsule.apply(Vec3(0, halfHeight, 0)), bottom = capsule.apply(Vec3(0, -halfHeight, 0));
    const Vec3 axis = capsule.rotate(Vec3::UnitY());
    Vec3 onSegment, onCenter;
    closestPointsOfSegments(bottom, top, center, center, onSegment, onCenter);
    // A centre on the axis: any direction across the axis is as deep; lean away from the centre.
    const Vec3 fallback = perpendicularTowards(axis, center - capsule.position);
    return inflateCores(onSegment, capsuleRadius, center, radius, fallback, "capsule_sphere");
}

ContactQuery collideCapsules(Real radiusA, Real halfHeightA, const Transform& capsuleA, Real radiusB,
                             Real halfHeightB, const Transform& capsuleB) {
    const Vec3 axisA = capsuleA.rotate(Vec3::UnitY()), axisB = capsuleB.rotate(Vec3::UnitY());
    Vec3 onA, onB;
    closestPointsOfSegments(capsuleA.apply(Vec3(0, -halfHeightA, 0)), capsuleA.apply(Vec3(0, halfHeightA, 0)),
                            capsuleB.apply(Vec3(0, -halfHeightB, 0)), capsuleB.apply(Vec3(0, halfHeightB, 0)), onA,
                            onB);
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
    return inflateCores(onA, radiusA, onB, radiusB, fallback, "capsule_capsule");
}

ContactQuery swapped(const ContactQuery& query) {
    ContactQuery result = query;
    result.normal = -query.normal;
    result.pointA = query.pointB;
    result.pointB = query.pointA;
    return result;
}

}  // namespace stepwise
