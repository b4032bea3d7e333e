#include "09_debug/ray_cast.h"

#include "02_gjk/closest_point.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

RayHit insideHit(const Ray& ray) {
    RayHit result;
    result.hit = true;
    result.startedInside = true;
    result.point = ray.origin;
    result.normal = -ray.direction;
    return result;
}

/// The nearer root of |f + t d|^2 = r^2 for a ray starting outside (c = |f|^2 - r^2 > 0) and
/// heading in (along = f.d < 0), with dd = d.d. The discriminant is taken from the closest approach
/// (r^2 minus its squared distance) and the root as c / (-along + sqrt(...)): both keep their digits
/// where the textbook (-b - sqrt(b^2 - 4ac)) / 2a cancels (Haines et al., "Precision Improvements
/// for Ray/Sphere Intersection", Ray Tracing Gems, 2019). Negative when the ray misses.
Real nearerRoot(const Vec3& f, const Vec3& d, Real dd, Real radius) {
    const Real along = f.dot(d);
    const Vec3 closestApproach = f - (along / dd) * d;
    const Real clearance = radius * radius - closestApproach.squaredNorm();
    if (clearance < 0) return -1;
    const Real c = (f.squaredNorm() - radius * radius);
    return c / (-along + std::sqrt(dd * clearance));
}

RayHit withinReach(RayHit result, const Ray& ray) {
    if (result.hit && !result.startedInside && result.distance > ray.maxDistance) return RayHit{};
    return result;
}

}  // namespace

// [ch09-ray-sphere]
RayHit raySphere(const Ray& ray, const Vec3& center, Real radius) {
    const Vec3 fromCenter = ray.origin - center;
    if (fromCenter.squaredNorm() <= radius * radius) return insideHit(ray);
    if (fromCenter.dot(ray.direction) >= 0) return RayHit{};   // outside and heading away
    const Real distance = nearerRoot(fromCenter, ray.direction, 1, radius);
    if (distance < 0) return RayHit{};
    RayHit result;
    result.hit = true;
    result.distance = distance;
    result.point = ray.origin + distance * ray.direction;
    result.normal = (fromCenter + distance * ray.direction).normalized();
    return withinReach(result, ray);
}
// [ch09-ray-sphere]

RayHit rayBox(const Ray& ray, const Transform& pose, const Vec3& halfExtents) {
    const Mat3 toLocal = pose.rotation.toRotationMatrix().transpose();
    const Vec3 origin = toLocal * (ray.origin - pose.position);
    const Vec3 direction = toLocal * ray.direction;
    if ((origin.cwiseAbs().array() <= halfExtents.array()).all()) return insideHit(ray);
    // Slabs: the ray is inside the box while it is inside all three; it enters at the latest
    // entry and must not have left any slab before.
    Real entry = -kRealMax, exit = kRealMax;
    int entryAxis = -1;
    Real entrySign = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (direction[axis] == 0) {
            if (std::abs(origin[axis]) > halfExtents[axis]) return RayHit{};
            continue;
        }
        const Real near = (-std::copysign(halfExtents[axis], direction[axis]) - origin[axis]) / direction[axis];
        const Real far = (std::copysign(halfExtents[axis], direction[axis]) - origin[axis]) / direction[axis];
        if (near > entry) {
            entry = near;
            entryAxis = axis;
            entrySign = direction[axis] > 0 ? Real(-1) : Real(1);
        }
        exit = std::min(exit, far);
    }
    if (entryAxis < 0 || entry > exit || entry < 0) return RayHit{};
    Vec3 localPoint = origin + entry * direction;
    localPoint[entryAxis] = entrySign * halfExtents[entryAxis];   // on the face, not a rounding off it
    RayHit result;
    result.hit = true;
    result.distance = entry;
    result.point = pose.position + pose.rotation * localPoint;
    result.normal = pose.rotation * (entrySign * Vec3::Unit(entryAxis));
    return withinReach(result, ray);
}

RayHit rayCapsule(const Ray& ray, const Transform& pose, Real radius, Real halfHeight) {
    const Mat3 toLocal = pose.rotation.toRotationMatrix().transpose();
    const Vec3 origin = toLocal * (ray.origin - pose.position);
    const Vec3 direction = toLocal * ray.direction;
    const Vec3 nearestOnCore(0, std::clamp(origin.y(), -halfHeight, halfHeight), 0);
    if ((origin - nearestOnCore).squaredNorm() <= radius * radius) return insideHit(ray);

    // The capsule holds its side and both end spheres, so its entry is the nearest of the side's
    // entry (where it lies between the ends) and the two spheres' entries.
    RayHit best;
    const Vec3 flatOrigin(origin.x(), 0, origin.z());
    const Vec3 flatDirection(direction.x(), 0, direction.z());
    const Real flatLength2 = flatDirection.squaredNorm();
    if (flatLength2 > 0 && flatOrigin.squaredNorm() > radius * radius && flatOrigin.dot(flatDirection) < 0) {
        const Real distance = nearerRoot(flatOrigin, flatDirection, flatLength2, radius);
        const Real y = origin.y() + distance * direction.y();
        if (distance >= 0 && std::abs(y) <= halfHeight) {
            best.hit = true;
            best.distance = distance;
            const Vec3 local = origin + distance * direction;
            best.point = pose.position + pose.rotation * local;
            best.normal = pose.rotation * Vec3(local.x(), 0, local.z()).normalized();
        }
    }
    for (Real end : {-halfHeight, halfHeight}) {
        const RayHit cap = raySphere(Ray{origin, direction, kRealMax}, Vec3(0, end, 0), radius);
        if (cap.hit && (!best.hit || cap.distance < best.distance)) {
            best = cap;
            best.point = pose.position + pose.rotation * cap.point;
            best.normal = pose.rotation * cap.normal;
        }
    }
    return withinReach(best, ray);
}

RayHit rayHullPlanes(const Ray& ray, const Transform& pose, const ConvexHull& hull) {
    const Mat3 toLocal = pose.rotation.toRotationMatrix().transpose();
    const Vec3 origin = toLocal * (ray.origin - pose.position);
    const Vec3 direction = toLocal * ray.direction;
    Real entry = -kRealMax, exit = kRealMax;
    const HullFace* entryFace = nullptr;
    bool inside = true;
    for (const HullFace& face : hull.faces) {
        const Real height = face.normal.dot(origin) - face.offset;   // > 0: outside this plane
        const Real approach = face.normal.dot(direction);
        inside = inside && height <= 0;
        if (approach == 0) {
            if (height > 0) return RayHit{};
            continue;
        }
        const Real crossing = -height / approach;
        if (approach < 0) {
            if (crossing > entry) {
                entry = crossing;
                entryFace = &face;
            }
        } else {
            exit = std::min(exit, crossing);
        }
    }
    if (inside) return insideHit(ray);
    if (!entryFace || entry > exit || entry < 0) return RayHit{};
    RayHit result;
    result.hit = true;
    result.distance = entry;
    result.point = ray.origin + entry * ray.direction;
    result.normal = pose.rotation * entryFace->normal;
    return withinReach(result, ray);
}

// [ch09-ray-gjk]
RayHit rayConvex(const Ray& ray, const ConvexProxy& shape, int maxIterations) {
    // van den Bergen's loop. x = origin + t direction; the simplex keeps support points p_i of the
    // shape, and v is the point of conv{x - p_i} nearest the origin: x minus the nearest point of
    // the shape's simplex. A support point p beyond which x lies (v.(x - p) > 0) gives a plane
    // separating x from the shape; x jumps to where the ray crosses that plane, or, if the ray
    // runs away from the plane, there is no hit.
    const Real scale = shapeScale(*shape.shape) + (ray.origin - shape.center()).norm();
    const Real tolerance2 = Real(16) * kEpsilon * kEpsilon * scale * scale;
    Vec3 supports[4];
    int count = 0;
    Real t = 0;
    Vec3 x = ray.origin;
    Vec3 normal = Vec3::Zero();
    Vec3 v = x - shape.center();
    RayHit result;
    for (int iteration = 0; iteration < maxIterations; ++iteration) {
        result.iterations = iteration + 1;
        const Vec3 p = shape.support(v);
        const Vec3 w = x - p;
        const Real vw = v.dot(w);
        if (vw > 0) {
            const Real vr = v.dot(ray.direction);
            if (vr >= 0) return RayHit{};
            t -= vw / vr;
            if (t > ray.maxDistance) return RayHit{};
            x = ray.origin + t * ray.direction;
            normal = v;
        }
        bool repeated = false;
        for (int i = 0; i < count; ++i) repeated = repeated || supports[i] == p;
        if (!repeated) supports[count++] = p;
        Vec3 relative[4];
        for (int i = 0; i < count; ++i) relative[i] = x - supports[i];
        const SimplexClosest closest = closestPointToOrigin(relative, count, scale);
        Vec3 kept[4];
        for (int i = 0; i < closest.keptCount; ++i) kept[i] = supports[closest.kept[i]];
        count = closest.keptCount;
        std::copy(kept, kept + count, supports);
        v = closest.point;
        if (count == 4 || v.squaredNorm() <= tolerance2 || (repeated && vw <= 0)) break;
    }
    if (t == 0) return insideHit(ray);
    result.hit = true;
    result.distance = t;
    result.point = x;
    result.normal = normal.normalized();
    return result;
}
// [ch09-ray-gjk]

RayHit castRay(const Ray& ray, const Shape& shape, const Transform& pose) {
    switch (shape.type) {
        case ShapeType::Sphere: return raySphere(ray, pose.position, shape.radius);
        case ShapeType::Box: return rayBox(ray, pose, shape.halfExtents);
        case ShapeType::Capsule: return rayCapsule(ray, pose, shape.radius, shape.halfHeight);
        case ShapeType::Convex: return shape.hull ? rayConvex(ray, ConvexProxy{&shape, pose}) : RayHit{};
    }
    return RayHit{};
}

namespace {

/// Entry distance of the ray into a box, or a negative number when it misses within reach.
Real rayBounds(const Ray& ray, const Aabb& bounds, Real reach) {
    Real entry = 0, exit = reach;
    for (int axis = 0; axis < 3; ++axis) {
        if (ray.direction[axis] == 0) {
            if (ray.origin[axis] < bounds.min[axis] || ray.origin[axis] > bounds.max[axis]) return -1;
            continue;
        }
        Real near = (bounds.min[axis] - ray.origin[axis]) / ray.direction[axis];
        Real far = (bounds.max[axis] - ray.origin[axis]) / ray.direction[axis];
        if (near > far) std::swap(near, far);
        entry = std::max(entry, near);
        exit = std::min(exit, far);
        if (entry > exit) return -1;
    }
    return entry;
}

}  // namespace

WorldRayHit castRay(const World& world, const Ray& ray, bool skipStatic) {
    WorldRayHit best;
    if (!ray.origin.allFinite() || !ray.direction.allFinite() || ray.direction.squaredNorm() == 0) return best;
    Ray unit = ray;
    unit.direction = ray.direction.normalized();
    for (int index = 0; index < static_cast<int>(world.bodies.size()); ++index) {
        const Body& body = world.bodies[index];
        if (skipStatic && body.type == BodyType::Static) continue;
        const Real reach = best.body >= 0 ? best.hit.distance : unit.maxDistance;
        if (rayBounds(unit, computeAabb(body.shape, body.transform), reach) < 0) continue;
        const RayHit hit = castRay(unit, body.shape, body.transform);
        if (hit.hit && (best.body < 0 || hit.distance < best.hit.distance)) {
            best.body = index;
            best.hit = hit;
        }
    }
    return best;
}

}  // namespace stepwise
