#pragma once
// The stress scene: many bodies dropped on one large ground, packed tightly (dense) or spread
// out (sparse), as spheres (closed-form contacts), "diamonds" (convex hulls: GJK and EPA), boxes,
// capsules, cylinders, or a mix. One generator for the demo, the benches, the tests, `stepwise stress` and scene
// files ({ "generator": { "stress": { ... } } }, docs/scene-format.md).

#include "world/scene_limits.h"
#include "world/world.h"

#include <cstdint>
#include <string>

namespace stepwise {

class JsonCursor;

enum class StressDensity { Sparse, Dense };
/// Mixed: spheres, diamonds and boxes in turn; All: every kind in turn (capsules and cylinders too).
enum class StressShape { Sphere, Diamond, Box, Mixed, Capsule, Cylinder, All };

const char* toString(StressDensity density);
const char* toString(StressShape shape);

struct StressParams {
    int count = 1000;                         // dynamic bodies (the ground comes on top)
    StressDensity density = StressDensity::Sparse;
    StressShape shape = StressShape::Mixed;
    Real dropHeight = 2;                      // m from the ground to the lowest bodies' bottoms
    std::uint32_t seed = 5;                   // jitter of positions and orientations
};

/// At most the bodies a scene file may list (world/scene_limits.h).
constexpr int kStressMaxCount = static_cast<int>(kMaxBodies);
constexpr Real kStressMaxDropHeight = 1000;   // m

/// Centre spacing of the bodies, m. Every body fits in a ball of 1 m across: dense packs those
/// balls touching (neighbouring spheres touch), sparse leaves 3 m between them.
Real stressSpacing(StressDensity density);

/// Adds the ground (a static box whose top is y = 0, wide enough for the layout) and the bodies:
/// sparse on a square grid in one layer, dense in a cube-shaped block; each jittered within its
/// cell and turned at random (seeded, the same on every platform).
void addStressBodies(World& world, const StressParams& params);

/// A world named "sap-stress" (or `name`) with the default settings and addStressBodies.
World buildStressScene(const StressParams& params, const std::string& name = "sap-stress");

/// The shape kinds' names in scene files and on the command line ("sphere", ..., "all").
const Names<StressShape>& stressShapeNames();

/// Reads the generator's parameters from a scene file ({ "count": 1000, "density": "sparse",
/// "shape": "mixed", "drop_height": 2, "arrangement": 5 }, every key optional). Throws SceneError
/// naming the JSON path of a bad value.
StressParams readStressParams(const JsonCursor& cursor);

/// The scene file that regenerates the scene: { "format": ..., "generator": { "stress": ... } }.
std::string stressSceneFile(const StressParams& params, const Settings& settings, const std::string& name);

}  // namespace stepwise
