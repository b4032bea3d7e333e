// stepwise_extremes, section 4: mass ratios, sizes and speeds far from the engine's defaults
// (extremes.cpp runs the tables; docs/reliability.md shows them).
#include "extremes.h"

#include "app/registry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stepwise::extremes {

namespace {

// --- 4. mass ratios, sizes and speeds -------------------------------------------------------------

struct Outcome {
    double sink = 0;        // deepest the top body sank into what it rests on, m
    double endSink = 0;     // the same at the end
    double drift = 0;       // largest distance the top body moved from where it started, m
    double speed = 0;       // its speed at the end, m/s
    bool finite = true;
};

Outcome settle(World world, int top, int below, double restingGap, long frames) {
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    const Vec3 start = world.bodies[std::size_t(top)].transform.position;
    Outcome outcome;
    for (long frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        if (!allFinite(world)) {
            outcome.finite = false;
            break;
        }
        const Vec3 topPosition = world.bodies[std::size_t(top)].transform.position;
        const double gap = double(topPosition.y() - world.bodies[std::size_t(below)].transform.position.y());
        outcome.sink = std::max(outcome.sink, restingGap - gap);
        outcome.endSink = restingGap - gap;
        outcome.drift = std::max(outcome.drift, double((topPosition - start).norm()));
    }
    outcome.speed = double(world.motionOf(top)->linearVelocity.norm());
    return outcome;
}

}  // namespace

void ratiosTable(bool quick) {
    const long frames = quick ? 300 : 1800;
    std::printf("\nMass ratios: a 1 m ball resting on a 1 m ball on the ground, exactly on the vertical, the top one\n"
                "heavier by the ratio; %ld frames, %s build. Sink: how far the top ball pressed into the lower one\n"
                "beyond the slop it started at, while on it; drift: how far the top ball moved; stands: still on\n"
                "the lower ball at the end, within 1 cm.\n\n", frames, precision());
    std::printf("%-10s %12s %12s %14s %8s %8s\n", "top:lower", "max sink m", "drift m", "end speed m/s", "finite",
                "stands");
    for (double ratio : {1.0, 10.0, 100.0, 1000.0}) {
        World world;
        addBox(world, "ground", BodyType::Static, Vec3(0, Real(-0.5), 0), Vec3(10, Real(0.5), 10));
        const Real slop = world.settings.slop;
        BodyDef ball;
        ball.shape = Shape::sphere(Real(0.5));
        ball.name = "lower";
        ball.transform.position = Vec3(0, Real(0.5) - slop, 0);
        const int lower = addBody(world, ball);
        ball.name = "top";
        ball.transform.position = Vec3(0, Real(1.5) - 2 * slop, 0);
        ball.density = Real(1000 * ratio);
        const int top = addBody(world, ball);
        const Outcome outcome = settle(world, top, lower, 1 - double(slop), frames);
        const bool stands = outcome.finite && std::abs(outcome.endSink) < 0.01;
        std::printf("%-10s %12.3g %12.3g %14.3g %8s %8s\n", ("1:" + std::to_string(int(ratio))).c_str(), outcome.sink,
                    outcome.drift, outcome.speed, outcome.finite ? "yes" : "no", stands ? "yes" : "no");
    }
}

void sizesTable(bool quick) {
    const long frames = quick ? 300 : 1800;
    std::printf("\nSizes: a 1 cm cube resting on a 200 m ground (static), on a 100 m slab (dynamic, on that ground),\n"
                "and dropped from 1 m onto the ground; %ld frames, %s build. Sink: how far the cube sank below\n"
                "resting on the surface (largest, and at the end); the slop alone lets it sink %.3g m.\n\n", frames, precision(),
                double(Settings{}.slop));
    std::printf("%-34s %12s %12s %12s %14s %8s\n", "case", "max sink m", "end sink m", "drift m", "end speed m/s",
                "finite");
    for (int variant = 0; variant < 3; ++variant) {
        World world;
        const Real slop = world.settings.slop;
        addBox(world, "ground", BodyType::Static, Vec3(0, Real(-0.5), 0), Vec3(100, Real(0.5), 100));
        int below = 0;
        if (variant == 1) below = addBox(world, "slab", BodyType::Dynamic, Vec3(0, Real(0.5) - slop, 0), Vec3(50, Real(0.5), 50));
        const double top = variant == 1 ? 1 : 0;
        const double drop = variant == 2 ? 1 : 0;
        const int cube = addBox(world, "cube", BodyType::Dynamic, Vec3(0, Real(top + 0.005 + drop), 0),
                                Vec3(Real(0.005), Real(0.005), Real(0.005)));
        const double restingGap = 0.5 + 0.005;  // the cube's centre above the centre of what it rests on
        const Outcome outcome = settle(world, cube, below, restingGap, frames);
        const char* names[] = {"1 cm cube on static 200 m ground", "1 cm cube on dynamic 100 m slab",
                               "1 cm cube dropped 1 m on ground"};
        std::printf("%-34s %12.3g %12.3g %12.3g %14.3g %8s\n", names[variant], outcome.sink, outcome.endSink,
                    variant == 2 ? 0.0 : outcome.drift, outcome.speed, outcome.finite ? "yes" : "no");
    }
}

void speedTable(bool quick) {
    (void)quick;
    std::printf("\nSpeed: a 10 cm ball at 1000 m/s, 60 frames at 60 Hz, %s build: flying free (energy drift), and\n"
                "at a 1 m thick wall 100 m away (chapter 7 plans continuous collision for the ball).\n\n", precision());
    World free;
    free.settings.gravity = Vec3::Zero();
    BodyDef ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(Real(0.1));
    ball.linearVelocity = Vec3(1000, 0, 0);
    addBody(free, ball);
    Pipeline pipeline = chapterRegistry().makePipeline(free);
    const double before = computeEnergy(free).total();
    for (int frame = 0; frame < 60; ++frame) pipeline.step(free);
    std::printf("%-40s %.3g (relative)\n", "energy change flying free", (computeEnergy(free).total() - before) / before);
    std::printf("%-40s %.6g m (exact 1000)\n", "distance flown in 1 s", double(free.bodies[0].transform.position.x()));

    World wall;
    wall.settings.gravity = Vec3::Zero();
    addBox(wall, "wall", BodyType::Static, Vec3(100, 0, 0), Vec3(Real(0.5), 10, 10));
    addBody(wall, ball);
    Pipeline wallPipeline = chapterRegistry().makePipeline(wall);
    for (int frame = 0; frame < 60; ++frame) wallPipeline.step(wall);
    const double x = double(wall.bodies[1].transform.position.x());
    std::printf("%-40s %s (ball at x = %.4g m after 1 s)\n", "ball stopped by the wall", x < 100 ? "yes" : "no, it tunnelled", x);
}

}  // namespace stepwise::extremes
