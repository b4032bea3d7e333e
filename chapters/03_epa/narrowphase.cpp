// Picks the routine for a pair of shapes and runs it: a closed form when the pair has one; for a
// round shape against any other, the distance between the cores while they are apart; otherwise
// GJK for the yes/no answer and EPA for the depth.
#include "03_epa/narrowphase.h"

#include "03_epa/closed_form.h"
#include "03_epa/features.h"

#include <cmath>

namespace stepwise {

bool hasClosedForm(ShapeType a, ShapeType b) {
    const auto roundType = [](ShapeType type) { return type == ShapeType::Sphere || type == ShapeType::Capsule; };
    if (roundType(a) && roundType(b)) return true;
    return (a == ShapeType::Sphere && b == ShapeType::Box) || (a == ShapeType::Box && b == ShapeType::Sphere);
}

bool isValidShape(const Shape& shape) {
    const auto positive = [](Real value) { return isFinite(value) && value > 0; };
    switch (shape.type) {
        case ShapeType::Box:
            return positive(shape.halfExtents.x()) && positive(shape.halfExtents.y()) && positive(shape.halfExtents.z());
        case ShapeType::Sphere: return positive(shape.radius);
        case ShapeType::Capsule: return positive(shape.radius) && isFinite(shape.halfHeight) && shape.halfHeight >= 0;
        case ShapeType::Convex: return shape.hull != nullptr && !shape.hull->vertices.empty();
        case ShapeType::Cylinder: return positive(shape.radius) && positive(shape.halfHeight);
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: return false;  // not one convex set: chapter 13 collides their parts
    }
    return false;
}

namespace {

/// A finite position and a finite rotation that can be normalised (any length but zero).
bool isValidPose(const Transform& transform) {
    return isFinite(transform.position) && transform.rotation.coeffs().allFinite() &&
           transform.rotation.norm() > kEpsilon;
}

/// The pairs with a closed form, with A and B in the order the routines expect them.
ContactQuery collideClosedForm(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb) {
    const ShapeType typeA = a.type, typeB = b.type;
    if (typeA == ShapeType::Sphere && typeB == ShapeType::Sphere) {
        return collideSpheres(ta.position, a.radius, tb.position, b.radius);
    }
    if (typeA == ShapeType::Box) return collideBoxSphere(a.halfExtents, ta, tb.position, b.radius);
    if (typeB == ShapeType::Box) return swapped(collideBoxSphere(b.halfExtents, tb, ta.position, a.radius));
    if (typeA == ShapeType::Capsule && typeB == ShapeType::Capsule) {
        return collideCapsules(a.radius, a.halfHeight, ta, b.radius, b.halfHeight, tb);
    }
    if (typeA == ShapeType::Capsule) return collideCapsuleSphere(a.radius, a.halfHeight, ta, tb.position, b.radius);
    return swapped(collideCapsuleSphere(b.radius, b.halfHeight, tb, ta.position, a.radius));
}

// [ch03-gjk-epa]
ContactQuery collideGjkEpa(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                           const CollideOptions& options) {
    ContactQuery query;
    query.routine = "gjk_epa";
    const ConvexProxy proxyA{&a, ta, options.supportMode};
    const ConvexProxy proxyB{&b, tb, options.supportMode};
    const GjkResult gjk = gjkIntersect(proxyA, proxyB);
    query.gjkIterations = gjk.iterations;
    Vec3 touchingNormal = Vec3::Zero();  // EPA's guess where it found no volume around the origin
    if (gjk.intersect) {
        const EpaResult epa = epaPenetration(proxyA, proxyB, gjk.simplex, options.epa);
        query.epaIterations = epa.iterations;
        if (epa.exit != EpaExit::Degenerate) {
            query.intersect = true;
            query.depth = epa.depth;
            query.normal = epa.normal;
            query.pointA = epa.pointA;
            query.pointB = epa.pointB;
            query.featureId = epaFeatureId(proxyA, proxyB, epa.closestFace);
            return query;
        }
        // A - B has no volume around the origin: the shapes touch, or GJK's tolerance took a gap of
        // a fraction of a millimetre for contact (a cylinder's rim, a flat simplex). EPA's depth
        // is then only the least reach along a few trial directions, centimetres off; the distance
        // query below says which it is.
        touchingNormal = epa.normal;
    }
    if (!options.separationDistance && !gjk.intersect) return query;
    // Separated: the contract reports minus the distance, with the closest points.
    const GjkDistanceResult distance = gjkDistance(proxyA, proxyB);
    query.gjkIterations += distance.iterations;
    const Vec3 gap = distance.pointB - distance.pointA;
    const Real length = gap.norm();
    if (distance.separated && length > 0 && isFinite(length)) {
        query.depth = -distance.distance;
        query.normal = gap / length;
    } else if (gjk.intersect && distance.radiusOverlap > 0) {
        // The cores are apart and the radii reach across: a sphere or a capsule sunk into the
        // other shape, as deep as the radii overlap, along the axis between the cores (exact; a
        // sphere 1.5 mm into a cylinder's rim leaves EPA a flat polytope and reads 0 otherwise).
        query.intersect = true;
        query.depth = distance.radiusOverlap;
        query.normal = distance.axis;
    } else if (distance.axis.squaredNorm() > 0) {
        // Within round-off of touching the closest points coincide and give no direction; the
        // axis between the cores still does (for a sphere or a capsule it is exact). The line of
        // centres would not: a capsule lying on a box's face has its centre off to one side, and
        // a normal along it makes the round body's surface point along that normal (chapter 3's
        // followContactPoint) read centimetres deep where the shapes only touch.
        query.normal = distance.axis;
    } else if (touchingNormal.squaredNorm() > 0) {
        query.normal = touchingNormal;
    } else {
        const Vec3 centres = tb.position - ta.position;
        query.normal = centres.norm() > 0 ? Vec3(centres.normalized()) : Vec3(Vec3::UnitY());
    }
    query.pointA = distance.pointA;
    query.pointB = distance.pointB;
    if (gjk.exit == GjkExit::Intersect && !distance.separated &&
        (distance.pointB - distance.pointA).norm() > gjkTolerances(proxyA, proxyB).touching) {
        // Overlapping within round-off, GJK's witness points are a blend of its last simplex's
        // points, together only in exact arithmetic: of a 56 m sliver hull touching a 1.2 mm box
        // they came out 9.8 cm apart. Touching shapes meet at the smaller one's extreme point
        // towards the other, on its surface and within the touching tolerance of the other's.
        // Only where GJK's intersection test ended cleanly on the origin: where it found a
        // separating plane, or stalled and only failed to find one, and the distance could not
        // measure the gap (a centimetre across a 56 m sliver), the witness points are the better
        // answer.
        const SupportPoint extreme = minkowskiSupport(proxyA, proxyB, query.normal);
        const bool smallerA = shapeScale(a) <= shapeScale(b);
        query.pointA = query.pointB = smallerA ? extreme.onA : extreme.onB;
    }
    return query;
}
// [ch03-gjk-epa]

// [ch03-round-cores]
/// A sphere or a capsule against a shape without a closed form (a box, a hull, a cylinder): the
/// distance between the round shape's core (its centre, its segment) and the other shape answers
/// exactly while the cores are apart: apart by more than the radii, the shapes are that far
/// apart; within them, they overlap by the radii less the distance, along the line between the
/// cores. One distance walk does it, where GJK's yes-or-no walk and EPA on the rounded shape
/// would take two and answer only to EPA's tolerance (van den Bergen, "Collision Detection in
/// Interactive 3D Environments", 2003, collides rounded shapes this way, as Jolt and Box2D do).
/// Only cores that overlap, or a walk that cannot prove its gap, go on to GJK and EPA.
bool collideRoundCores(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                       const CollideOptions& options, ContactQuery& query) {
    const ConvexProxy proxyA{&a, ta, options.supportMode};
    const ConvexProxy proxyB{&b, tb, options.supportMode};
    const GjkDistanceResult distance = gjkDistance(proxyA, proxyB);
    query.routine = "round_cores";
    query.gjkIterations = distance.iterations;
    if (distance.separated) {
        if (!options.separationDistance) return true;  // apart; the caller asked no distance
        const Vec3 gap = distance.pointB - distance.pointA;
        const Real length = gap.norm();
        if (!(length > 0) || !isFinite(length)) return false;
        query.depth = -distance.distance;
        query.normal = gap / length;
    } else if (distance.radiusOverlap > 0) {  // proven: the cores are apart
        query.intersect = true;
        query.depth = distance.radiusOverlap;
        query.normal = distance.axis;
    } else {
        return false;  // the cores overlap or touch within round-off: EPA's case
    }
    query.pointA = distance.pointA;
    query.pointB = distance.pointB;
    return true;
}
// [ch03-round-cores]

}  // namespace

// [ch03-dispatch]
ContactQuery collideShapes(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                           const CollideOptions& options) {
    if (!isValidShape(a) || !isValidShape(b) || !isValidPose(ta) || !isValidPose(tb)) {
        ContactQuery invalid;
        invalid.routine = "invalid";
        return invalid;
    }
    // Work in a frame centred on A: world coordinates far from the origin would otherwise eat
    // the float mantissa before the shapes' small differences are ever formed.
    const Vec3 origin = ta.position;
    const Transform localA{Vec3::Zero(), ta.rotation.normalized()};
    const Transform localB{tb.position - origin, tb.rotation.normalized()};
    const bool closedForm = options.closedForms && hasClosedForm(a.type, b.type);
    const bool roundCores = options.closedForms && (isRound(a) || isRound(b));
    ContactQuery query;
    if (closedForm)
        query = collideClosedForm(a, localA, b, localB);
    else if (!roundCores || !collideRoundCores(a, localA, b, localB, options, query))
        query = collideGjkEpa(a, localA, b, localB, options);
    query.pointA += origin;
    query.pointB += origin;
    // The last line of defence of "never NaN": a non-finite answer becomes "no contact".
    if (!isFinite(query.depth) || !isFinite(query.normal) || !isFinite(query.pointA) || !isFinite(query.pointB)) {
        ContactQuery failed;
        failed.routine = "invalid";
        failed.gjkIterations = query.gjkIterations;
        failed.epaIterations = query.epaIterations;
        return failed;
    }
    return query;
}
// [ch03-dispatch]

}  // namespace stepwise
