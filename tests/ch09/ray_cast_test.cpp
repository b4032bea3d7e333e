// Ray casts against the closed forms: each shape's answer, computed here independently in long
// double from the shape's definition (a sphere's quadratic, the box's and the hull's planes, the
// capsule as the set of points within its radius of its segment), within 1e-6 m; hits, misses,
// grazing rays and rays that start inside. And the GJK cast against the same answers.
#include "09_debug/ray_cast.h"
#include "09_debug/ray_targets.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

using namespace stepwise;

namespace {

using Exact = long double;

constexpr Real kTolerance = Real(1e-6);   // m, the bound

struct ExactVec {
    Exact x, y, z;
    ExactVec(const Vec3& v) : x(v.x()), y(v.y()), z(v.z()) {}
    ExactVec(Exact ax, Exact ay, Exact az) : x(ax), y(ay), z(az) {}
    ExactVec operator-(const ExactVec& o) const { return {x - o.x, y - o.y, z - o.z}; }
    ExactVec operator+(const ExactVec& o) const { return {x + o.x, y + o.y, z + o.z}; }
    ExactVec operator*(Exact s) const { return {x * s, y * s, z * s}; }
    Exact dot(const ExactVec& o) const { return x * o.x + y * o.y + z * o.z; }
};

/// Signed distance from the shape's surface of a point given in the shape's frame, exactly: the
/// oracle's definition of each shape.
Exact signedDistance(const Shape& shape, const ExactVec& p) {
    switch (shape.type) {
        case ShapeType::Sphere: return std::sqrt(p.dot(p)) - Exact(shape.radius);
        case ShapeType::Box: {
            const Exact qx = std::fabs(p.x) - shape.halfExtents.x(), qy = std::fabs(p.y) - shape.halfExtents.y(),
                        qz = std::fabs(p.z) - shape.halfExtents.z();
            const ExactVec outside(std::max(qx, Exact(0)), std::max(qy, Exact(0)), std::max(qz, Exact(0)));
            return std::sqrt(outside.dot(outside)) + std::min(std::max(qx, std::max(qy, qz)), Exact(0));
        }
        case ShapeType::Capsule: {
            const Exact y = std::clamp(p.y, Exact(-shape.halfHeight), Exact(shape.halfHeight));
            const ExactVec offset(p.x, p.y - y, p.z);
            return std::sqrt(offset.dot(offset)) - Exact(shape.radius);
        }
        case ShapeType::Convex: {
            Exact largest = -1e30L;
            for (const HullFace& face : shape.hull->faces)
                largest = std::max(largest, ExactVec(face.normal).dot(p) - Exact(face.offset));
            return largest;   // exact on the surface and inside; a lower bound outside, enough to find the entry
        }
        case ShapeType::Cylinder: {
            const Exact radial = std::sqrt(p.x * p.x + p.z * p.z) - Exact(shape.radius);
            const Exact axial = std::fabs(p.y) - Exact(shape.halfHeight);
            const Exact outsideR = std::max(radial, Exact(0)), outsideA = std::max(axial, Exact(0));
            return std::sqrt(outsideR * outsideR + outsideA * outsideA) + std::min(std::max(radial, axial), Exact(0));
        }
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // not drawn by this test
    }
    return 0;
}

ExactVec toLocal(const Transform& pose, const ExactVec& world) {
    const Mat3 rotation = pose.rotation.toRotationMatrix();
    const ExactVec d = world - ExactVec(pose.position);
    return {d.dot(ExactVec(rotation.col(0))), d.dot(ExactVec(rotation.col(1))), d.dot(ExactVec(rotation.col(2)))};
}

/// The first t at which the ray enters the shape, by bisection on the exact signed distance
/// between the last point known outside and the first known inside (found by marching in steps
/// smaller than the shape): nothing of the code under test is used.
std::optional<Exact> exactEntry(const Ray& ray, const Shape& shape, const Transform& pose) {
    const ExactVec origin(ray.origin), direction(ray.direction);
    const auto distanceAt = [&](Exact t) { return signedDistance(shape, toLocal(pose, origin + direction * t)); };
    if (distanceAt(0) <= 0) return Exact(0);
    // March through the bounding sphere in steps of 1/512 of the shape's size.
    const ExactVec fromCentre = origin - ExactVec(pose.position);
    const Exact radius = Exact(boundingRadius(shape)) * Exact(1.01);
    const Exact half = fromCentre.dot(direction), rest = fromCentre.dot(fromCentre) - radius * radius;
    if (half * half - rest < 0) return std::nullopt;
    const Exact enter = std::max(Exact(0), -half - std::sqrt(half * half - rest)), leave = -half + std::sqrt(half * half - rest);
    if (leave < 0) return std::nullopt;
    const Exact step = Exact(shapeScale(shape)) / 512;
    Exact outside = enter, inside = -1;
    for (Exact t = enter + step; t <= leave + step; t += step) {
        if (distanceAt(t) <= 0) {
            inside = t;
            break;
        }
        outside = t;
    }
    if (inside < 0) return std::nullopt;
    for (int i = 0; i < 200; ++i) {
        const Exact middle = (outside + inside) / 2;
        (distanceAt(middle) <= 0 ? inside : outside) = middle;
    }
    return inside;
}

void checkAgainstOracle(const Ray& ray, const RayTarget& target, const RayHit& hit) {
    const std::optional<Exact> entry = exactEntry(ray, target.shape, target.pose);
    // A ray passing within the oracle's step of the surface may be called either way; only a
    // clear hit or a clear miss must agree.
    if (!entry) {
        if (hit.hit) {
            const Exact surface = signedDistance(target.shape, toLocal(target.pose, ExactVec(hit.point)));
            CHECK(std::fabs(double(surface)) <= double(kTolerance));
        }
        return;
    }
    REQUIRE(hit.hit);
    if (*entry == 0) {
        CHECK(hit.distance == 0);
        return;
    }
    // The error that matters in metres is the one across the surface: along a grazing ray the
    // same surface error is a longer distance (1 / cos of the incidence), for any method.
    const ExactVec local = toLocal(target.pose, ExactVec(hit.point));
    CHECK(std::fabs(double(signedDistance(target.shape, local))) <= double(kTolerance));
    const Exact incidence = std::max(std::fabs(Exact(hit.normal.dot(ray.direction))), Exact(1e-3));
    CHECK(std::fabs(double((Exact(hit.distance) - *entry) * incidence)) <= double(kTolerance));
    {
        const ExactVec outward = toLocal(target.pose, ExactVec(hit.point + Real(1e-3) * hit.normal));
        CHECK(signedDistance(target.shape, outward) > 0);
        CHECK(hit.normal.dot(ray.direction) <= 0);
    }
}

}  // namespace

TEST_CASE("ray casts: the closed forms against the exact entry, within 1e-6 m", "[ch09][ray]") {
    for (const RayTarget& target : rayTargets()) {
        INFO(target.name);
        Random random(21);
        int hits = 0, misses = 0;
        for (int i = 0; i < 300; ++i) {
            const Ray ray = aimedRay(target, random);
            const RayHit hit = target.shape.type == ShapeType::Convex ? rayHullPlanes(ray, target.pose, *target.shape.hull)
                                                                      : castRay(ray, target.shape, target.pose);
            checkAgainstOracle(ray, target, hit);
            (hit.hit ? hits : misses) += 1;
        }
        CHECK(hits > 100);     // the aim is at the bounds: most rays hit...
        CHECK(misses > 5);     // ...and the bounds' corners make some miss
    }
}

TEST_CASE("ray casts: GJK on the support map meets the closed forms within 1e-6 m", "[ch09][ray]") {
    for (const RayTarget& target : rayTargets()) {
        INFO(target.name);
        Random random(22);
        const ConvexProxy proxy{&target.shape, target.pose};
        for (int i = 0; i < 300; ++i) {
            const Ray ray = aimedRay(target, random);
            const RayHit gjk = rayConvex(ray, proxy);
            checkAgainstOracle(ray, target, gjk);
            CHECK(gjk.iterations <= 40);
        }
    }
}

TEST_CASE("ray casts: a ray that starts inside hits at 0, one that points away misses", "[ch09][ray]") {
    for (const RayTarget& target : rayTargets()) {
        INFO(target.name);
        const Vec3 centre = target.pose.position;
        const RayHit inside = castRay(Ray{centre, Vec3::UnitX(), 10}, target.shape, target.pose);
        CHECK(inside.hit);
        CHECK(inside.startedInside);
        CHECK(inside.distance == 0);
        const RayHit gjkInside = rayConvex(Ray{centre, Vec3::UnitX(), 10}, ConvexProxy{&target.shape, target.pose});
        CHECK(gjkInside.startedInside);
        const Vec3 outside = centre + Vec3(0, 5, 0);
        CHECK_FALSE(castRay(Ray{outside, Vec3::UnitY(), 10}, target.shape, target.pose).hit);
        CHECK_FALSE(rayConvex(Ray{outside, Vec3::UnitY(), 10}, ConvexProxy{&target.shape, target.pose}).hit);
        // Straight down onto it hits; not when the reach ends before it.
        CHECK(castRay(Ray{outside, -Vec3::UnitY(), 10}, target.shape, target.pose).hit);
        CHECK_FALSE(castRay(Ray{outside, -Vec3::UnitY(), 3}, target.shape, target.pose).hit);
    }
}

TEST_CASE("ray casts: grazing rays along a face and past a sphere's rim", "[ch09][ray]") {
    // Along the top face of a unit box, exactly in its plane: the slab test must not divide by
    // zero; the ray touches the face and counts as a hit at the edge it crosses.
    const Transform pose{Vec3::Zero(), Quat::Identity()};
    const RayHit along = rayBox(Ray{Vec3(-3, Real(0.5), 0), Vec3::UnitX(), 10}, pose, Vec3::Constant(Real(0.5)));
    CHECK(along.hit);
    CHECK(along.distance == Approx(2.5).margin(1e-6));
    // Just above it: a miss.
    CHECK_FALSE(rayBox(Ray{Vec3(-3, Real(0.5001), 0), Vec3::UnitX(), 10}, pose, Vec3::Constant(Real(0.5))).hit);
    // Tangent to a sphere, and just outside: hit at the touching point, then a miss.
    const RayHit tangent = raySphere(Ray{Vec3(-3, 1, 0), Vec3::UnitX(), 10}, Vec3::Zero(), 1);
    CHECK(tangent.hit);
    CHECK(tangent.distance == Approx(3).margin(1e-3));
    CHECK_FALSE(raySphere(Ray{Vec3(-3, Real(1.0001), 0), Vec3::UnitX(), 10}, Vec3::Zero(), 1).hit);
    // A capsule hit on its side, on its cap, and along its axis from outside.
    const Transform upright{Vec3::Zero(), Quat::Identity()};
    CHECK(rayCapsule(Ray{Vec3(-3, Real(0.2), 0), Vec3::UnitX(), 10}, upright, Real(0.5), 1).distance == Approx(2.5).margin(1e-6));
    CHECK(rayCapsule(Ray{Vec3(0, 5, 0), -Vec3::UnitY(), 10}, upright, Real(0.5), 1).distance == Approx(3.5).margin(1e-6));
    const RayHit cap = rayCapsule(Ray{Vec3(-3, Real(1.3), 0), Vec3::UnitX(), 10}, upright, Real(0.5), 1);
    CHECK(cap.distance == Approx(3 - std::sqrt(0.25 - 0.09)).margin(1e-6));
    CHECK(cap.normal.y() > 0);
}

TEST_CASE("ray casts: the world's nearest body, with and without static bodies", "[ch09][ray]") {
    World world;
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(10, Real(0.5), 10));
    BodyDef near, far;
    near.name = "near";
    near.shape = Shape::sphere(Real(0.5));
    near.transform.position = Vec3(0, Real(0.5), 2);
    far.name = "far";
    far.shape = Shape::box(Vec3::Constant(Real(0.5)));
    far.transform.position = Vec3(0, Real(0.5), -2);
    const int nearIndex = addBody(world, near);
    const int farIndex = addBody(world, far);
    const WorldRayHit first = castRay(world, Ray{Vec3(0, Real(0.5), 10), -Vec3::UnitZ(), 100});
    CHECK(first.body == nearIndex);
    CHECK(first.hit.distance == Approx(7.5).margin(1e-5));
    CHECK(castRay(world, Ray{Vec3(0, Real(0.5), -10), Vec3::UnitZ(), 100}).body == farIndex);
    // Straight down beside both: the ground, unless static bodies are skipped.
    CHECK(castRay(world, Ray{Vec3(5, 5, 0), -Vec3::UnitY(), 100}).body == 0);
    CHECK(castRay(world, Ray{Vec3(5, 5, 0), -Vec3::UnitY(), 100}, true).body == -1);
    // A degenerate ray is no hit, not a crash.
    CHECK(castRay(world, Ray{Vec3(5, 5, 0), Vec3::Zero(), 100}).body == -1);
    CHECK(castRay(world, Ray{Vec3(std::nan(""), 5, 0), -Vec3::UnitY(), 100}).body == -1);
}
