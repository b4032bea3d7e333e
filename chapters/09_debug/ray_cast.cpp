#include "09_debug/ray_cast.h"

#include "02_gjk/closest_point.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

// [ch09-ray-local]
/// The ray in a shape's own frame, started afresh just outside the shape's bounding sphere. Far
/// from the shape, every product of the ray's coordinates loses the digits that decide where it
/// enters (a float ray 3 m away has 0.2 um steps; a grazing entry multiplies them): so the move
/// to the shape's frame and up to its sphere is done in double, and the routines below work on
/// small local numbers. The distance skipped is added back at the end (Haines et al., "Precision
/// Improvements for Ray/Sphere Intersection", Ray Tracing Gems, 2019, start near the sphere too).
struct LocalRay {
    Vec3 origin = Vec3::Zero();
    Vec3 direction = Vec3::UnitX();
    double skipped = 0;     // world distance from the ray's origin to `origin`
    bool misses = false;    // the ray misses the bounding sphere, or leaves it before starting
};

LocalRay localRay(const Ray& ray, const Transform& pose, Real boundRadius) {
    using Vec3d = Eigen::Vector3d;
    const Eigen::Quaterniond toLocal = pose.rotation.cast<double>().conjugate();
    const Vec3d direction = toLocal * ray.direction.cast<double>();
    const Vec3d origin = toLocal * (ray.origin.cast<double>() - pose.position.cast<double>());
    LocalRay local;
    const double along = -origin.dot(direction);            // to the closest approach to the centre
    const double radius = 1.01 * double(boundRadius) + 1e-9;
    const double clearance = radius * radius - (origin + along * direction).squaredNorm();
    local.misses = clearance < 0 || along + std::sqrt(std::max(0.0, clearance)) < 0;
    local.skipped = std::max(0.0, along - std::sqrt(std::max(0.0, clearance)));
    local.origin = (origin + local.skipped * direction).cast<Real>();
    local.direction = direction.cast<Real>();
    return local;
}
// [ch09-ray-local]

/// A local hit (distance along the local ray, normal in the shape's frame) back in the world.
RayHit toWorld(const Ray& ray, const Transform& pose, const LocalRay& local, Real localDistance, const Vec3& localNormal) {
    RayHit result;
    result.hit = true;
    result.distance = Real(local.skipped + double(localDistance));
    result.startedInside = local.skipped == 0 && localDistance == 0;
    if (result.distance > ray.maxDistance) return RayHit{};
    result.point = ray.origin + result.distance * ray.direction;
    result.normal = result.startedInside ? Vec3(-ray.direction) : Vec3(pose.rotation * localNormal);
    return result;
}

/// The nearer root of |f + t d|^2 = r^2 for a ray starting outside (c = |f|^2 - r^2 > 0) and
/// heading in (f.d < 0), with dd = d.d. The discriminant is taken from the closest approach (r^2
/// minus its squared distance) and the root as c / (-f.d + sqrt(...)): both keep their digits
/// where the textbook (-b - sqrt(b^2 - 4ac)) / 2a cancels (Haines et al., 2019). Negative: a miss.
Real nearerRoot(const Vec3& f, const Vec3& d, Real dd, Real radius) {
    const Real along = f.dot(d);
    const Vec3 closestApproach = f - (along / dd) * d;
    const Real clearance = radius * radius - closestApproach.squaredNorm();
    if (clearance < 0) return -1;
    const Real c = f.squaredNorm() - radius * radius;
    return c / (-along + std::sqrt(dd * clearance));
}

/// Local sphere at the origin: distance along the local ray, or -1; 0 when it starts inside.
Real localSphere(const Vec3& origin, const Vec3& direction, Real radius) {
    if (origin.squaredNorm() <= radius * radius) return 0;
    if (origin.dot(direction) >= 0) return -1;
    return nearerRoot(origin, direction, 1, radius);
}

}  // namespace

// [ch09-ray-sphere]
RayHit raySphere(const Ray& ray, const Vec3& center, Real radius) {
    const Transform pose{center, Quat::Identity()};
    const LocalRay local = localRay(ray, pose, radius);
    if (local.misses) return RayHit{};
    const Real distance = localSphere(local.origin, local.direction, radius);
    if (distance < 0) return RayHit{};
    return toWorld(ray, pose, local, distance, (local.origin + distance * local.direction).normalized());
}
// [ch09-ray-sphere]

// [ch09-ray-box]
RayHit rayBox(const Ray& ray, const Transform& pose, const Vec3& halfExtents) {
    const LocalRay local = localRay(ray, pose, halfExtents.norm());
    if (local.misses) return RayHit{};
    const Vec3& origin = local.origin;
    const Vec3& direction = local.direction;
    if ((origin.cwiseAbs().array() <= halfExtents.array()).all()) return toWorld(ray, pose, local, 0, Vec3::Zero());
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
    return toWorld(ray, pose, local, entry, entrySign * Vec3::Unit(entryAxis));
}
// [ch09-ray-box]

RayHit rayCapsule(const Ray& ray, const Transform& pose, Real radius, Real halfHeight) {
    const LocalRay local = localRay(ray, pose, radius + halfHeight);
    if (local.misses) return RayHit{};
    const Vec3& origin = local.origin;
    const Vec3& direction = local.direction;
    const Vec3 nearestOnCore(0, std::clamp(origin.y(), -halfHeight, halfHeight), 0);
    if ((origin - nearestOnCore).squaredNorm() <= radius * radius) return toWorld(ray, pose, local, 0, Vec3::Zero());

    // The capsule holds its side and both end spheres, so its entry is the nearest of the side's
    // entry (where it lies between the ends) and the two spheres' entries.
    Real best = -1;
    Vec3 bestNormal = Vec3::Zero();
    const Vec3 flatOrigin(origin.x(), 0, origin.z());
    const Vec3 flatDirection(direction.x(), 0, direction.z());
    const Real flatLength2 = flatDirection.squaredNorm();
    if (flatLength2 > 0 && flatOrigin.squaredNorm() > radius * radius && flatOrigin.dot(flatDirection) < 0) {
        const Real distance = nearerRoot(flatOrigin, flatDirection, flatLength2, radius);
        if (distance >= 0 && std::abs(origin.y() + distance * direction.y()) <= halfHeight) {
            best = distance;
            bestNormal = (flatOrigin + distance * flatDirection).normalized();
        }
    }
    for (Real end : {-halfHeight, halfHeight}) {
        const Vec3 fromEnd = origin - Vec3(0, end, 0);
        const Real distance = localSphere(fromEnd, direction, radius);
        if (distance > 0 && (best < 0 || distance < best)) {
            best = distance;
            bestNormal = (fromEnd + distance * direction).normalized();
        }
    }
    if (best < 0) return RayHit{};
    return toWorld(ray, pose, local, best, bestNormal);
}

RayHit rayHullPlanes(const Ray& ray, const Transform& pose, const ConvexHull& hull) {
    Real reach = 0;
    for (const Vec3& vertex : hull.vertices) reach = std::max(reach, vertex.norm());
    const LocalRay local = localRay(ray, pose, reach);
    if (local.misses) return RayHit{};
    Real entry = -kRealMax, exit = kRealMax;
    const HullFace* entryFace = nullptr;
    bool inside = true;
    for (const HullFace& face : hull.faces) {
        const Real height = face.normal.dot(local.origin) - face.offset;   // > 0: outside this plane
        const Real approach = face.normal.dot(local.direction);
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
    if (inside) return toWorld(ray, pose, local, 0, Vec3::Zero());
    if (!entryFace || entry > exit || entry < 0) return RayHit{};
    return toWorld(ray, pose, local, entry, entryFace->normal);
}

// [ch09-ray-gjk]
RayHit rayConvex(const Ray& ray, const ConvexProxy& proxy, int maxIterations) {
    const Shape& shape = *proxy.shape;
    const LocalRay local = localRay(ray, proxy.transform, boundingRadius(shape));
    if (local.misses) return RayHit{};
    // van den Bergen's loop, in the shape's frame. x = origin + t direction; the simplex keeps
    // support points p_i of the shape, and v is the point of conv{x - p_i} nearest the origin: x
    // minus the nearest point of the shape's simplex. A support point p beyond which x lies
    // (v.(x - p) > 0) gives a plane separating x from the shape; x jumps to where the ray crosses
    // that plane, or, if the ray runs away from the plane, there is no hit. A sphere or a capsule
    // is cast as its core (a point, a segment) grown by its radius, the planes pushed out by it:
    // on the core the loop ends in a few steps, where on the round surface it would only creep
    // closer (the paper's section on shapes with a margin; chapter 2's distance does the same).
    const bool round = isRound(shape);
    const Real margin = roundRadius(shape);
    const auto coreSupport = [&](const Vec3& direction) -> Vec3 {
        if (shape.type == ShapeType::Sphere) return Vec3::Zero();
        if (shape.type == ShapeType::Capsule) return Vec3(0, direction.y() >= 0 ? shape.halfHeight : -shape.halfHeight, 0);
        return localSupport(shape, direction, proxy.mode);
    };
    const Real scale = shapeScale(shape);
    const Real tolerance = Real(4) * kEpsilon * scale;
    const Vec3 centre = proxy.transform.rotateInverse(proxy.center() - proxy.transform.position);
    Vec3 supports[4];
    int count = 0;
    Real t = 0;
    Vec3 x = local.origin;
    Vec3 normal = Vec3::Zero();
    Vec3 v = x - centre;
    int iterations = 0;
    for (; iterations < maxIterations; ++iterations) {
        const Vec3 p = coreSupport(v);
        const Vec3 w = x - p;
        const Real vLength = v.norm();
        const Real gap = v.dot(w) - margin * vLength;   // > 0: x is beyond the (pushed-out) plane
        if (gap > 0) {
            const Real vr = v.dot(local.direction);
            if (vr >= 0) return RayHit{};
            t -= gap / vr;
            x = local.origin + t * local.direction;
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
        // Done when x is on the shape: within the tolerance of the core plus the margin, inside
        // the simplex, or the support repeats (the plane cannot move x any further).
        if (count == 4 || v.norm() <= margin + tolerance || (repeated && gap <= tolerance)) {
            ++iterations;
            break;
        }
    }
    if (round && t > 0) normal = v;   // from the core's nearest point (x - v) out to x: the surface normal
    RayHit result = toWorld(ray, proxy.transform, local, t, t == 0 ? Vec3::Zero() : Vec3(normal.normalized()));
    result.iterations = iterations;
    return result;
}
// [ch09-ray-gjk]

namespace {

// A ray against one triangle (Moller and Trumbore, "Fast, minimum storage ray-triangle
// intersection", 1997), from either side: a picked surface, not a solid.
void rayTriangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c, RayHit& nearest) {
    const Vec3 edge1 = b - a, edge2 = c - a;
    const Vec3 p = ray.direction.cross(edge2);
    const Real determinant = edge1.dot(p);
    if (std::abs(determinant) < Real(1e-12)) return;  // parallel to the plane
    const Vec3 s = ray.origin - a;
    const Real u = s.dot(p) / determinant;
    if (u < 0 || u > 1) return;
    const Vec3 q = s.cross(edge1);
    const Real v = ray.direction.dot(q) / determinant;
    if (v < 0 || u + v > 1) return;
    const Real t = edge2.dot(q) / determinant;
    if (t < 0 || t > ray.maxDistance || (nearest.hit && t >= nearest.distance)) return;
    Vec3 normal = edge1.cross(edge2).normalized();
    if (normal.dot(ray.direction) > 0) normal = -normal;
    nearest = RayHit{true, t, ray.origin + t * ray.direction, normal, false, 0};
}

RayHit rayMesh(const Ray& ray, const TriangleMesh& mesh, const Transform& pose) {
    RayHit nearest;
    for (const auto& corners : mesh.triangles)
        rayTriangle(ray, pose.apply(mesh.vertices[static_cast<std::size_t>(corners[0])]),
                    pose.apply(mesh.vertices[static_cast<std::size_t>(corners[1])]),
                    pose.apply(mesh.vertices[static_cast<std::size_t>(corners[2])]), nearest);
    return nearest;
}

RayHit rayHeightField(const Ray& ray, const HeightField& field, const Transform& pose) {
    RayHit nearest;
    const auto at = [&](int row, int column) {
        return pose.apply(Vec3(Real(column) * field.cellSize,
                               field.heights[static_cast<std::size_t>(row * field.columns + column)], Real(row) * field.cellSize));
    };
    for (int row = 0; row + 1 < field.rows; ++row)
        for (int column = 0; column + 1 < field.columns; ++column) {
            const Vec3 a = at(row, column), b = at(row, column + 1), c = at(row + 1, column), d = at(row + 1, column + 1);
            if (!a.allFinite() || !b.allFinite() || !c.allFinite() || !d.allFinite()) continue;  // a hole
            rayTriangle(ray, a, d, b, nearest);
            rayTriangle(ray, a, c, d, nearest);
        }
    return nearest;
}

}  // namespace

RayHit castRay(const Ray& ray, const Shape& shape, const Transform& pose) {
    switch (shape.type) {
        case ShapeType::Sphere: return raySphere(ray, pose.position, shape.radius);
        case ShapeType::Box: return rayBox(ray, pose, shape.halfExtents);
        case ShapeType::Capsule: return rayCapsule(ray, pose, shape.radius, shape.halfHeight);
        case ShapeType::Convex: return shape.hull ? rayConvex(ray, ConvexProxy{&shape, pose}) : RayHit{};
        case ShapeType::Cylinder: return rayConvex(ray, ConvexProxy{&shape, pose});
        case ShapeType::Compound: {
            RayHit nearest;
            for (const CompoundChild& child : shape.compound->children) {
                const RayHit hit = castRay(ray, child.shape, compose(pose, child.transform));
                if (hit.hit && (!nearest.hit || hit.distance < nearest.distance)) nearest = hit;
            }
            return nearest;
        }
        case ShapeType::Mesh: return rayMesh(ray, *shape.mesh, pose);
        case ShapeType::HeightField: return rayHeightField(ray, *shape.heightField, pose);
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
