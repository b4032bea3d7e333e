#pragma once
// Ray casts: which body is under the mouse, and where exactly a ray enters a shape. Spheres,
// boxes and capsules in closed form (Ericson, Real-Time Collision Detection, 2005, 5.3.2, 5.3.3
// and 5.3.7); convex hulls, or any shape, by GJK on the ray (van den Bergen, "Ray Casting against
// General Convex Objects with Application to Continuous Collision Detection", 2004), which needs
// nothing but chapter 2's support map.

#include "02_gjk/support.h"
#include "world/world.h"

namespace stepwise {

/// A ray from `origin` along the unit `direction`, up to `maxDistance` metres.
struct Ray {
    Vec3 origin = Vec3::Zero();
    Vec3 direction = Vec3::UnitX();
    Real maxDistance = kRealMax;
};

/// Where a ray first meets a solid shape. A ray that starts inside the shape hits it at
/// distance 0 (the shapes are solid, as Jolt's and Box3D's casts treat them), with
/// `startedInside` set and the normal against the ray.
struct RayHit {
    bool hit = false;
    Real distance = 0;               // m along the ray
    Vec3 point = Vec3::Zero();       // world
    Vec3 normal = Vec3::Zero();      // unit, outward at the point
    bool startedInside = false;
    int iterations = 0;              // GJK: support points asked for; closed forms: 0
};

// [ch09-ray-closed-forms]
/// A sphere of `radius` centred on `center`.
RayHit raySphere(const Ray& ray, const Vec3& center, Real radius);
/// A box with the given half extents at a pose: the slab test in the box's own frame.
RayHit rayBox(const Ray& ray, const Transform& pose, const Vec3& halfExtents);
/// A capsule (segment along the pose's local y, +-halfHeight, swept by radius): the infinite
/// cylinder clipped to the segment, else the nearer end sphere.
RayHit rayCapsule(const Ray& ray, const Transform& pose, Real radius, Real halfHeight);
// [ch09-ray-closed-forms]

/// A convex hull by its face planes (Cyrus and Beck 1978): the ray enters the latest of the planes
/// it crosses inwards and must not leave any before. Exact for polytopes; what the GJK cast of a
/// hull is measured against.
RayHit rayHullPlanes(const Ray& ray, const Transform& pose, const ConvexHull& hull);

/// GJK ray cast against any convex proxy: the ray's point x = origin + t direction walks towards
/// the shape, each support plane the simplex finds moving t forward, until x is within a
/// relative tolerance of the shape.
RayHit rayConvex(const Ray& ray, const ConvexProxy& shape, int maxIterations = 64);

/// One shape at a pose: closed forms where there is one, GJK for hulls.
RayHit castRay(const Ray& ray, const Shape& shape, const Transform& pose);

struct WorldRayHit {
    int body = -1;                   // -1: nothing hit
    RayHit hit;
};

/// The nearest body the ray hits (bounds first, then the shape); `skipStatic` leaves out static
/// bodies (picking does not want the ground).
WorldRayHit castRay(const World& world, const Ray& ray, bool skipStatic = false);

}  // namespace stepwise
