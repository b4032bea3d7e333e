// Chapter 11's scenes.
#include "11_wide_solve/scenes.h"

#include "08_joints/builders.h"
#include "08_joints/joint_view.h"
#include "08_joints/scenes.h"
#include "10_skip_work/scenes.h"
#include "math/random.h"

#include <cmath>

namespace stepwise {

World buildRagdollField(int ragdolls, Real frictionTorque, unsigned seed) {
    World world = emptyWorld("ragdoll-field-" + std::to_string(ragdolls));
    addGround(world);
    Random random(seed);
    constexpr int kPerColumn = 4;
    constexpr Real kSpacing = 2;  // m between columns: a lying ragdoll (1.8 m) reaches its neighbours
    const int columns = (ragdolls + kPerColumn - 1) / kPerColumn;
    const int side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(columns)))));
    for (int i = 0; i < ragdolls; ++i) {
        const int column = i / kPerColumn, level = i % kPerColumn;
        RagdollSpec spec;
        spec.prefix = "ragdoll" + std::to_string(i);
        spec.frictionTorque = frictionTorque;
        const Real x = (static_cast<Real>(column % side) - Real(0.5) * static_cast<Real>(side - 1)) * kSpacing;
        const Real z = (static_cast<Real>(column / side) - Real(0.5) * static_cast<Real>(side - 1)) * kSpacing;
        // One draw per statement (z, then x), as in chapter 8's pile (docs/reliability.md).
        const Real jitterZ = random.uniformReal(Real(-0.3), Real(0.3));
        const Real jitterX = random.uniformReal(Real(-0.3), Real(0.3));
        spec.pelvis = Vec3(x + jitterX, Real(1.2) + Real(1.0) * static_cast<Real>(level), z + jitterZ);
        spec.orientation = Quat(angleAxis(random.uniformReal(0, 2 * kPi), Vec3::UnitY())) *
                           Quat(angleAxis(kPi / 2, Vec3::UnitX()));
        addRagdoll(world, spec);
    }
    return world;
}

void addChapter11Scenes(Registry& registry) {
    registry.addScene({"wide-pyramid", 11, "11 the wide solve", prose(R"(
        a 30-row pyramid (465 boxes) stands on the wide solve; the performance monitor shows each
        stage's time, the solve's among them, until the settled pyramid falls asleep)"),
                       [] { return buildPyramidRow(1, 30); }, {}});
    registry.addScene({"wide-ragdolls", 11, "11 the wide solve", prose(R"(
        forty ragdolls fall in ten heaps onto the ground and come to rest, every joint within a
        centimetre; their joints are solved in the same substeps as their contacts, and the whole
        field falls asleep within a few seconds)"),
                       [] { return buildRagdollField(40); }, jointView()});
}

}  // namespace stepwise
