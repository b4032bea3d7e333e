#pragma once
// Thin boxes spun on a floor: the scenes in which a body turns far within a frame while a contact
// touches it (chapter 11's pieces; the suites of chapters 11 and 12).
#include "world/scene.h"

#include <cstdio>

namespace stepwise::test {

/// A 1.05 kg box of the given half extents dropped at 3 m/s onto a floor 35 cm below, spinning at
/// `spin` (rad/s, world axes), restitution `bounce`.
inline World spunOnFloor(const char* halfExtents, const Vec3& spin, Real bounce) {
    char scene[1024];
    std::snprintf(scene, sizeof scene, R"({"settings": {"ccd": "off", "sleeping": false}, "bodies": [
        {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [10, 0.5, 10]}}, "position": [0, -0.5, 0]},
        {"name": "spun", "shape": {"box": {"half_extents": %s}}, "position": [0, 0.35, 0], "mass": 1.05,
         "restitution": %.9g, "velocity": [0, -3, 0], "angular_velocity": [%.9g, %.9g, %.9g],
         "orientation": [0.1, -0.2, 0.15, 0.96306801]}]})",
                  halfExtents, static_cast<double>(bounce), static_cast<double>(spin.x()),
                  static_cast<double>(spin.y()), static_cast<double>(spin.z()));
    return loadSceneFromString(scene);
}

// A needle, a plate and a stick; spins of 40 to 190 rad/s about axes every way.
inline constexpr const char* kThinBoxes[] = {"[0.014, 0.0065, 0.237]", "[0.3, 0.004, 0.2]", "[0.04, 0.04, 0.45]"};
inline const Vec3 kSpins[] = {Vec3(188, 0, 0), Vec3(0, 120, 150), Vec3(90, -60, 40), Vec3(-30, 20, 150)};

}  // namespace stepwise::test
