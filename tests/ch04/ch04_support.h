#pragma once
// Small helpers shared by the chapter 4 suite.

#include "03_epa/narrowphase.h"
#include "world/world.h"

#include <cmath>

namespace stepwise::test {

/// Penetration of two bodies as chapter 3's narrowphase measures it (0 when apart).
inline Real overlapDepth(const World& world, int a, int b) {
    const Body& bodyA = world.bodies[a];
    const Body& bodyB = world.bodies[b];
    const ContactQuery query = collideShapes(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform);
    return query.intersect ? query.depth : Real(0);
}

/// A one-point contact between two bodies along `normal` (A to B), with B's deepest point at
/// `pointB` and the given depth: pointA = pointB + depth * normal.
inline Contact makeContact(int bodyA, int bodyB, const Vec3& normal, const Vec3& pointB, Real depth) {
    Contact contact;
    contact.bodyA = bodyA;
    contact.bodyB = bodyB;
    contact.normal = normal;
    contact.points[0].pointB = pointB;
    contact.points[0].pointA = pointB + depth * normal;
    contact.points[0].depth = depth;
    contact.pointCount = 1;
    return contact;
}

inline double relativeError(double value, double expected) { return std::abs(value - expected) / std::abs(expected); }

}  // namespace stepwise::test
