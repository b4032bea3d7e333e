// Capsules spun on a bouncy floor (chapter 11's collisions before contacts, collide.h): a capsule
// spinning on one end bobs its cap faster than the restitution threshold every substep while it
// rests there, and a collision struck at a point that is already pushing pushes twice.
#include "11_wide_solve/chapter.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <cstdio>
#include <random>

using namespace stepwise;

namespace {

/// A capsule of radius `radius` and half height `halfHeight` (1,000 kg/m^3, restitution 0.5)
/// dropped at 3 m/s just above a floor, spinning at 150 rad/s about `axis`, turned by `turn`.
World spunCapsule(Real radius, Real halfHeight, const Vec3& axis, const Quat& turn) {
    char scene[1024];
    std::snprintf(scene, sizeof scene, R"({"settings": {"ccd": "off", "sleeping": false}, "bodies": [
        {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [10, 0.5, 10]}}, "position": [0, -0.5, 0]},
        {"name": "capsule", "shape": {"capsule": {"radius": %.9g, "half_height": %.9g}}, "position": [0, %.9g, 0],
         "density": 1000, "restitution": 0.5, "velocity": [0, -3, 0], "angular_velocity": [%.9g, %.9g, %.9g],
         "orientation": [%.9g, %.9g, %.9g, %.9g]}]})",
                  double(radius), double(halfHeight), double(radius + halfHeight + Real(0.05)), double(150 * axis.x()),
                  double(150 * axis.y()), double(150 * axis.z()), double(turn.x()), double(turn.y()), double(turn.z()),
                  double(turn.w()));
    return loadSceneFromString(scene);
}

}  // namespace

TEST_CASE("capsules spun on a bouncy floor end no frame far above the energy they started with", "[ch11][fast]") {
    const Real sizes[3][2] = {{Real(0.1), Real(0.3)}, {Real(0.05), Real(0.4)}, {Real(0.2), Real(0.15)}};
    std::mt19937 random(7);
    std::normal_distribution<Real> normal(0, 1);
    double worstPeak = 0;
    for (const auto& size : sizes)
        for (int k = 0; k < 24; ++k) {
            const Vec3 axis = Vec3(normal(random), normal(random), normal(random)).normalized();
            const Quat turn(Eigen::AngleAxis<Real>(Real(0.4) * Real(k), Vec3(normal(random), normal(random), normal(random)).normalized()));
            World world = spunCapsule(size[0], size[1], axis, turn);
            Pipeline pipeline = makeChapter11Pipeline(world);
            const double start = computeEnergy(world).total();
            for (int frame = 0; frame < 120; ++frame) {
                pipeline.step(world);
                worstPeak = std::max(worstPeak, (computeEnergy(world).total() - start) / start);
            }
        }
    // Striking resting points too, the worst of the 72 runs peaks 44% above its start (float). Now
    // none does in float, and the worst in double 2.5%: what is left is not the collisions (with the
    // collision sweep off the float runs gain at most 0.67% in a frame and none ends above its start).
    CHECK(worstPeak <= 0.03);
}
