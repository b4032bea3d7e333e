// Chapter 10's shock sweep (shock_propagation.h): its order, and what it does and leaves alone.
#include "12_planner/chapter.h"
#include "12_planner/shock_propagation.h"
#include "world/scene.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

using namespace stepwise;

TEST_CASE("the shock sweep climbs layer by layer, no group moving one body twice", "[ch12][solve]") {
    // Slots 1-2 rest on the world (depth 1), 3-4 on them (depth 2), 5 on 3 and 4 (depth 3).
    // Contacts: 0: world-1 (a body that does not move: left out), 1: 1-3, 2: 2-3, 3: 2-4,
    // 4: 3-5, 5: 5-4 (B lower), 6: 1-2 (side by side, one depth: left out).
    const std::vector<int> slotA = {0, 1, 2, 2, 3, 5, 1};
    const std::vector<int> slotB = {1, 3, 3, 4, 5, 4, 2};
    const std::vector<int> depth = {0, 1, 1, 2, 2, 3};
    ShockOrder order;
    orderShockSweep(slotA, slotB, depth, order);
    REQUIRE(order.entries.size() == 5);
    int lastLayer = 0;
    for (std::size_t group = 0; group + 1 < order.groupStart.size(); ++group) {
        std::set<int> uppers;
        for (int k = order.groupStart[group]; k < order.groupStart[group + 1]; ++k) {
            const int i = order.entries[static_cast<std::size_t>(k)];
            const bool lowerIsA = order.lowerIsA[static_cast<std::size_t>(k)] != 0;
            const int lower = lowerIsA ? slotA[static_cast<std::size_t>(i)] : slotB[static_cast<std::size_t>(i)];
            const int upper = lowerIsA ? slotB[static_cast<std::size_t>(i)] : slotA[static_cast<std::size_t>(i)];
            CHECK(depth[static_cast<std::size_t>(upper)] == depth[static_cast<std::size_t>(lower)] + 1);
            CHECK(depth[static_cast<std::size_t>(lower)] >= lastLayer);  // from the supports up
            lastLayer = depth[static_cast<std::size_t>(lower)];
            CHECK(uppers.insert(upper).second);  // a group moves each upper body once
        }
    }
    // Contact 5 holds its B side (slot 4, depth 2) still: slot 5 is the upper body.
    for (std::size_t k = 0; k < order.entries.size(); ++k)
        if (order.entries[k] == 5) CHECK(order.lowerIsA[k] == 0);
    // Slot 3 rests on 1 and 2: its two contacts in layer 1 go to two groups.
    CHECK(order.groupStart.size() - 1 == 4);  // layer 1: two groups; layer 2: two (slot 5 on 3 and 4)
}

namespace {

World referenceScene(const std::string& name) { return loadSceneFile("scenes/reference/" + name); }

}  // namespace

TEST_CASE("the shock sweep leaves a moving stack alone", "[ch12][solve]") {
    // Sixteen boxes dropped together onto the ground from half a metre: until they land, every
    // body is faster than the sleep speed, the sweep has no contact to take, and the two runs
    // are the same to the bit.
    World shocked = referenceScene("stack-16.json");
    for (Body& body : shocked.bodies)
        if (body.type == BodyType::Dynamic) body.transform.position.y() += Real(0.5);
    World plain = shocked;
    SpeedOptions noShock;
    noShock.shockPropagation = false;
    Pipeline withSweep = makeChapter12Pipeline(shocked, SpeedOptions{});
    Pipeline without = makeChapter12Pipeline(plain, noShock);
    for (int frame = 0; frame < 15; ++frame) {  // 0.25 s: 31 cm of fall, not yet landed
        withSweep.step(shocked);
        without.step(plain);
    }
    for (std::size_t i = 0; i < shocked.bodies.size(); ++i)
        CHECK(shocked.bodies[i].transform.position == plain.bodies[i].transform.position);
}

TEST_CASE("the shock sweep settles a stack that the same substeps leave swaying", "[ch12][solve]") {
    // The 20-row pyramid at the planner's five substeps, with and without the sweep, after 2 s
    // awake.
    World shocked = referenceScene("pyramid-20.json");
    shocked.settings.sleeping = false;
    World plain = shocked;
    SpeedOptions noShock;
    noShock.shockPropagation = false;
    Pipeline withSweep = makeChapter12Pipeline(shocked, SpeedOptions{});
    Pipeline without = makeChapter12Pipeline(plain, noShock);
    for (int frame = 0; frame < 120; ++frame) {
        withSweep.step(shocked);
        without.step(plain);
    }
    REQUIRE(shocked.step.iterationPlan.iterations == plain.step.iterationPlan.iterations);
    Real fastestShocked = 0, fastestPlain = 0;
    for (const Motion& motion : shocked.motions) fastestShocked = std::max(fastestShocked, motion.linearVelocity.norm());
    for (const Motion& motion : plain.motions) fastestPlain = std::max(fastestPlain, motion.linearVelocity.norm());
    CHECK(shocked.step.iterationPlan.shockPropagation);
    INFO("fastest box: " << fastestShocked << " m/s with the sweep, " << fastestPlain << " without");
    CHECK(fastestShocked < Real(1e-3));
    CHECK(fastestShocked < fastestPlain);
}
