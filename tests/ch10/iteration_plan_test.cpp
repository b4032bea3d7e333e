// Chapter 10's planner for solver_iterations "auto": more substeps where touching masses differ
// by more than 100 to 1, the scene's ten elsewhere.
#include "10_speed/chapter.h"
#include "10_speed/iteration_plan.h"
#include "world/report.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

using namespace stepwise;

namespace {

/// Four 1 m boxes, by default of 1, 10, 100 and 1000 kg with the heaviest on top
/// (scenes/reference/mass-ratio-tower.json).
World tower(const std::string& iterations, const std::array<int, 4>& masses = {1, 10, 100, 1000}) {
    std::string boxes;
    for (int i = 0; i < 4; ++i) {
        boxes += R"(, {"name": "box)" + std::to_string(i) + R"(", "shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, )" +
                 std::to_string(i) + R"(.5, 0], "mass": )" + std::to_string(masses[std::size_t(i)]) + "}";
    }
    return loadSceneFromString(R"({"name": "tower", "settings": {"solver_iterations": )" + iterations + R"(}, "bodies": [
        {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [50, 0.5, 50]}}, "position": [0, -0.5, 0]})" +
                               boxes + "]}");
}

struct Standing {
    Real drift = 0;  // largest sideways move of a box, m
    Real sag = 0;    // largest drop of a box, m
};

Standing runFiveSeconds(World& world) {
    SpeedOptions options;
    Pipeline pipeline = makeChapter10Pipeline(world, options);
    const World start = world;
    Standing standing;
    for (int frame = 0; frame < 300; ++frame) {
        pipeline.step(world);
        for (std::size_t i = 1; i < world.bodies.size(); ++i) {
            const Vec3 move = world.bodies[i].transform.position - start.bodies[i].transform.position;
            standing.drift = std::max(standing.drift, std::hypot(move.x(), move.z()));
            standing.sag = std::max(standing.sag, -move.y());
        }
    }
    return standing;
}

}  // namespace

TEST_CASE("solver_iterations auto: a 1:1000 tower stands, where the scene's ten let it fall", "[ch10][solve]") {
    World automatic = tower(R"("auto")");
    const Standing held = runFiveSeconds(automatic);
    INFO("auto: drift " << held.drift << " m, sag " << held.sag << " m");
    CHECK(held.drift < Real(0.01));
    CHECK(held.sag < Real(0.04));
    // 10 x sqrt(1000 / 100) = 31.6
    CHECK(automatic.step.iterationPlan.mostIterations == 32);
    CHECK(automatic.step.iterationPlan.largestRatio == Approx(1000));
    CHECK(describeIterationPlan(automatic).find("auto: up to 32") == 0);

    World ten = tower("10");
    const Standing fell = runFiveSeconds(ten);
    INFO("10: drift " << fell.drift << " m, sag " << fell.sag << " m");
    CHECK(fell.sag > Real(1));  // the light boxes are crushed and the tower comes down
    CHECK(ten.step.iterationPlan.mostIterations == 10);
    CHECK(describeIterationPlan(ten).find("the scene's solver_iterations") != std::string::npos);
}

TEST_CASE("solver_iterations auto keeps ten substeps for touching masses within 100 to 1", "[ch10][solve]") {
    // 100 kg on 1 kg stands at ten (chapter 6's heavy-on-light); only beyond that does it cost more.
    for (const std::array<int, 4>& masses : {std::array<int, 4>{1, 1, 1, 1}, std::array<int, 4>{1, 10, 100, 100}}) {
        World world = tower(R"("auto")", masses);
        const Standing standing = runFiveSeconds(world);
        INFO("top mass " << masses[3] << ": drift " << standing.drift << " m, sag " << standing.sag << " m");
        CHECK(standing.drift < Real(0.01));
        CHECK(world.step.iterationPlan.mostIterations == 10);
    }
}
