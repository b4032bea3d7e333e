#include "06_manifolds/chapter.h"
#include "06_manifolds/scenes.h"
#include <catch2/catch.hpp>
#include <cstdio>
using namespace stepwise;
TEST_CASE("scratch2", "[.scratch2]") {
    World world = buildBoxStack(16);
    Pipeline pipeline = makeChapter06Pipeline(world);
    const World start = world;
    for (int frame = 1; frame <= 600; ++frame) {
        pipeline.step(world);
        int points = 0, persisted = 0, speculative = 0;
        for (auto& c : world.contacts) for (int i = 0; i < c.pointCount; ++i) { ++points; persisted += c.points[i].persisted; speculative += c.points[i].depth < 0; }
        double worst = 0; int which = -1;
        for (const Motion& m : world.motions) {
            Vec3 d = world.bodies[m.bodyIndex].transform.position - start.bodies[m.bodyIndex].transform.position;
            double h = std::hypot((double)d.x(), (double)d.z());
            if (h > worst) worst = h, which = m.bodyIndex;
        }
        if (frame % 20 == 0 || points != 64 || persisted != 64)
            std::printf("f %d points %d persisted %d spec %d worst %d %.5f\n", frame, points, persisted, speculative, which, worst);
        if (frame == 300) break;
    }
}
