// Exercise check for chapter 9 (`ctest -L ch09-exercise`): rewrite rayBox in
// chapters/09_debug/ray_cast.cpp from the page's slab test (in the box's own frame, each axis's
// slab holds the ray over [near, far]; the ray enters at the latest near, misses when that comes
// after the earliest far, and a ray starting inside hits at distance 0), and run this. Boxes at
// random poses and sizes, rays aimed at them, past them, along their faces and from inside: each
// answer is checked against the box's definition (the points within its half extents), marched
// and bisected in long double, which shares nothing with the code under test.
#include "09_debug/ray_cast.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace stepwise;

namespace {

using Exact = long double;

constexpr double kTolerance = 1e-5;   // m, across the surface

/// Signed distance from the box's surface of a world point: > 0 outside, <= 0 inside.
Exact boxDistance(const Transform& pose, const Vec3& half, const Exact world[3]) {
    const Mat3 rotation = pose.rotation.toRotationMatrix();
    Exact outside = 0, largest = -1e30L;
    for (int axis = 0; axis < 3; ++axis) {
        Exact local = 0;
        for (int k = 0; k < 3; ++k) local += (world[k] - Exact(pose.position[k])) * Exact(rotation(k, axis));
        const Exact q = std::fabs(local) - Exact(half[axis]);
        outside += q > 0 ? q * q : 0;
        largest = std::max(largest, q);
    }
    return std::sqrt(outside) + std::min(largest, Exact(0));
}

Exact distanceAlong(const Ray& ray, const Transform& pose, const Vec3& half, Exact t) {
    const Exact point[3] = {Exact(ray.origin.x()) + t * Exact(ray.direction.x()), Exact(ray.origin.y()) + t * Exact(ray.direction.y()),
                            Exact(ray.origin.z()) + t * Exact(ray.direction.z())};
    return boxDistance(pose, half, point);
}

/// The first t at which the ray is inside the box: march in steps of 1/2048 of the box's
/// diagonal through the box's bounding sphere (up to the ray's length), then bisect. None when
/// the march never gets inside.
std::optional<Exact> exactEntry(const Ray& ray, const Transform& pose, const Vec3& half) {
    if (distanceAlong(ray, pose, half, 0) <= 0) return Exact(0);
    const Exact radius = Exact(half.norm()) * Exact(1.01);
    Exact towards = 0, apart = 0;   // the centre along the ray, and the origin's squared distance from it
    for (int k = 0; k < 3; ++k) {
        const Exact offset = Exact(pose.position[k]) - Exact(ray.origin[k]);
        towards += offset * Exact(ray.direction[k]);
        apart += offset * offset;
    }
    const Exact clearance = radius * radius - (apart - towards * towards);
    if (clearance < 0) return std::nullopt;
    const Exact reach = std::min(Exact(ray.maxDistance), towards + std::sqrt(clearance));
    const Exact step = Exact(half.norm()) / 2048;
    Exact outside = std::max(Exact(0), towards - std::sqrt(clearance)), inside = -1;
    for (Exact t = outside + step; t <= reach + step; t += step) {
        if (distanceAlong(ray, pose, half, t) <= 0) {
            inside = t;
            break;
        }
        outside = t;
    }
    if (inside < 0) return std::nullopt;
    for (int i = 0; i < 100; ++i) {
        const Exact middle = (outside + inside) / 2;
        (distanceAlong(ray, pose, half, middle) <= 0 ? inside : outside) = middle;
    }
    if (inside > Exact(ray.maxDistance)) return std::nullopt;   // the box lies beyond the ray's end
    return inside;
}

void checkCast(const Ray& ray, const Transform& pose, const Vec3& half) {
    const RayHit hit = rayBox(ray, pose, half);
    const std::optional<Exact> entry = exactEntry(ray, pose, half);
    const Exact pointOnRay[3] = {Exact(hit.point.x()), Exact(hit.point.y()), Exact(hit.point.z())};
    if (!entry) {
        // A ray that passes within the march's step of an edge may be called either way; a hit
        // must then lie on the surface.
        if (hit.hit) CHECK(std::fabs(double(boxDistance(pose, half, pointOnRay))) <= kTolerance);
        return;
    }
    REQUIRE(hit.hit);
    if (*entry == 0) {
        CHECK(hit.distance == 0);
        CHECK(hit.startedInside);
        return;
    }
    CHECK_FALSE(hit.startedInside);
    // On the surface, at the exact entry (measured across the surface: along a grazing ray the
    // same surface error is a longer distance, 1 / cos of the incidence).
    CHECK(std::fabs(double(boxDistance(pose, half, pointOnRay))) <= kTolerance);
    const double incidence = std::max(std::fabs(double(hit.normal.dot(ray.direction))), 1e-3);
    CHECK(std::fabs(double(Exact(hit.distance) - *entry)) * incidence <= kTolerance);
    CHECK((hit.point - (ray.origin + hit.distance * ray.direction)).norm() <= Real(kTolerance));
    // The normal: unit, one of the box's face normals, outward and against the ray.
    CHECK(hit.normal.norm() == Approx(1).margin(1e-5));
    const Vec3 local = pose.rotation.conjugate() * hit.normal;
    CHECK(local.cwiseAbs().maxCoeff() == Approx(1).margin(1e-5));
    CHECK(hit.normal.dot(ray.direction) <= Real(1e-6));
    const Vec3 outward = hit.point + Real(1e-3) * hit.normal;
    const Exact outwardPoint[3] = {Exact(outward.x()), Exact(outward.y()), Exact(outward.z())};
    CHECK(boxDistance(pose, half, outwardPoint) > 0);
}

}  // namespace

TEST_CASE("exercise: rayBox enters where the slabs overlap, against the box's definition", "[ch09-exercise]") {
    Random random(909);
    auto uniform = [&](double low, double high) { return static_cast<Real>(random.uniform(low, high)); };
    auto unitVector = [&]() {
        Vec3 v;
        do v = Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        while (v.squaredNorm() < Real(0.01) || v.squaredNorm() > 1);
        return Vec3(v.normalized());
    };
    for (int trial = 0; trial < 400; ++trial) {
        const Vec3 half(uniform(0.1, 1.5), uniform(0.1, 1.5), uniform(0.1, 1.5));
        Transform pose{Vec3(uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)),
                       trial % 4 == 0 ? Quat::Identity() : Quat(Eigen::AngleAxis<Real>(uniform(0, 3.1), unitVector()))};
        Ray ray;
        const int kind = trial % 5;
        // The point aimed at, in the box's frame: inside (a hit), just past a face (a near miss),
        // or anywhere nearby.
        Vec3 aim = half.cwiseProduct(Vec3(uniform(-0.95, 0.95), uniform(-0.95, 0.95), uniform(-0.95, 0.95)));
        if (kind == 1) aim[trial % 3] = half[trial % 3] * uniform(1.01, 1.3) * (trial % 2 ? 1 : -1);
        if (kind == 2) aim = half.cwiseProduct(Vec3(uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)));
        const Vec3 target = pose.apply(aim);
        ray.direction = unitVector();
        ray.origin = target - uniform(2.5, 6) * ray.direction;
        if (kind == 3) {
            // Along the box's own axes: two direction components exactly zero.
            const int axis = trial % 3;
            Vec3 direction = Vec3::Zero();
            direction[axis] = trial % 2 ? 1 : -1;
            ray.direction = pose.rotation * direction;
            ray.origin = target - Real(4) * ray.direction;   // with the identity pose, exact zeros
        }
        if (kind == 4) ray.origin = target;   // starts inside
        if (trial % 7 == 0) ray.maxDistance = uniform(0.5, 4);
        INFO("trial " << trial << ", kind " << kind);
        checkCast(ray, pose, half);
    }
}

TEST_CASE("exercise: rayBox on rays whose answer is known by hand", "[ch09-exercise]") {
    const Transform pose{Vec3(1, 0, 0), Quat::Identity()};
    const Vec3 half(1, Real(0.5), Real(0.5));
    // Along x from x = -3: the face x = 0 is 3 m away, normal -x.
    RayHit hit = rayBox(Ray{Vec3(-3, 0, 0), Vec3::UnitX(), kRealMax}, pose, half);
    REQUIRE(hit.hit);
    CHECK(hit.distance == Approx(3).margin(1e-6));
    CHECK(hit.normal.x() == Approx(-1).margin(1e-6));
    // The same ray, 2 m long: the box is out of reach.
    CHECK_FALSE(rayBox(Ray{Vec3(-3, 0, 0), Vec3::UnitX(), 2}, pose, half).hit);
    // In the plane of the top face, y = 0.5: touching counts, so it enters through the x face at
    // 3 m (a zero direction component times an infinite reciprocal is NaN: mind it).
    hit = rayBox(Ray{Vec3(-3, Real(0.5), 0), Vec3::UnitX(), kRealMax}, pose, half);
    REQUIRE(hit.hit);
    CHECK(hit.distance == Approx(3).margin(1e-5));
    CHECK(hit.normal.x() == Approx(-1).margin(1e-6));
    // Pointing away: a miss.
    CHECK_FALSE(rayBox(Ray{Vec3(-3, 0, 0), -Vec3::UnitX(), kRealMax}, pose, half).hit);
    // Down the diagonal (1, -1)/sqrt 2 from (-1, 1.5, 0): the x slab holds it from t = 1.414 (to
    // 4.243), the y slab from t = 1.414 (to 2.828): it enters at their common start, on the edge
    // x = 0, y = 0.5.
    hit = rayBox(Ray{Vec3(-1, Real(1.5), 0), Vec3(1, -1, 0).normalized(), kRealMax}, pose, half);
    REQUIRE(hit.hit);
    CHECK(hit.distance == Approx(std::sqrt(2.0)).margin(1e-5));
    // From (-1, 2.5, 0) the same way: the y slab holds it from 2.828 to 4.243, the x slab from
    // 1.414 to 4.243, so it enters at 2.828 through the top face (normal +y).
    hit = rayBox(Ray{Vec3(-1, Real(2.5), 0), Vec3(1, -1, 0).normalized(), kRealMax}, pose, half);
    REQUIRE(hit.hit);
    CHECK(hit.distance == Approx(2 * std::sqrt(2.0)).margin(1e-5));
    CHECK(hit.normal.y() == Approx(1).margin(1e-6));
    // From (-1, 4, 0): the y slab from 4.95 to 6.36, the x slab ends at 4.243 before: a miss.
    CHECK_FALSE(rayBox(Ray{Vec3(-1, 4, 0), Vec3(1, -1, 0).normalized(), kRealMax}, pose, half).hit);
    // Starting inside: distance 0.
    hit = rayBox(Ray{Vec3(Real(1.2), 0, 0), Vec3::UnitY(), kRealMax}, pose, half);
    REQUIRE(hit.hit);
    CHECK(hit.distance == 0);
    CHECK(hit.startedInside);
}
