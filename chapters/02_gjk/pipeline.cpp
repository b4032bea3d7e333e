// The narrowphase stage of chapter 2: every pair, one boolean GJK query each.

#include "02_gjk/chapter.h"

#include "01_integrators/chapter.h"

namespace stepwise {

ConvexProxy makeProxy(const Body& body, SupportMode mode) {
    ConvexProxy proxy;
    proxy.shape = &body.shape;
    proxy.transform = body.transform;
    proxy.mode = mode;
    return proxy;
}

// [ch02-narrowphase]
int findIntersectingPairs(World& world, SupportMode mode) {
    world.pairs.clear();
    int queries = 0;
    const int bodyCount = static_cast<int>(world.bodies.size());
    for (int i = 0; i < bodyCount; ++i) {
        for (int j = i + 1; j < bodyCount; ++j) {
            const Body& bodyA = world.bodies[i];
            const Body& bodyB = world.bodies[j];
            // Two static bodies never need a contact: nothing could respond to it.
            if (bodyA.type == BodyType::Static && bodyB.type == BodyType::Static) continue;
            ++queries;
            if (gjkIntersect(makeProxy(bodyA, mode), makeProxy(bodyB, mode)).intersect)
                world.pairs.push_back(BodyPair{i, j});
        }
    }
    return queries;
}

Pipeline makeChapter02Pipeline(const World& world) {
    Pipeline pipeline = makeChapter01Pipeline(world);
    Stage stage;
    stage.name = stageName(stage_group::kNarrowphase, "gjk");
    stage.frequency = StageFrequency::FrameStart;
    stage.run = [](World& stepWorld, Real) { findIntersectingPairs(stepWorld); };
    pipeline.add(std::move(stage));
    return pipeline;
}
// [ch02-narrowphase]

}  // namespace stepwise
