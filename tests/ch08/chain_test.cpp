// Chains of distance joints: how much they stretch at rest, swinging, and with a heavy end
// (the numbers: 1%, 2%, 3%), at 60 Hz with the default solver settings.
#include "08_joints/builders.h"
#include "08_joints/chapter.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace stepwise;

namespace {

struct StretchRun {
    Real largest = 0;     // over every frame
    Real final = 0;
    bool finite = true;
};

StretchRun runChain(const ChainSpec& spec, Real seconds, JointOptions options = {}) {
    World world;
    const Chain chain = addChain(world, spec);
    Pipeline pipeline = makeChapter08Pipeline(world, options);
    StretchRun run;
    const int frames = static_cast<int>(std::lround(seconds / world.settings.dt));
    for (int frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        const Real stretch = chainStretch(world, chain);
        run.finite = run.finite && std::isfinite(stretch);
        run.largest = std::max(run.largest, stretch);
        run.final = stretch;
    }
    return run;
}

}  // namespace

TEST_CASE("a 20-link chain hanging at rest stretches less than 1% over 10 s", "[ch08][chain]") {
    ChainSpec spec;
    spec.links = 20;
    const StretchRun run = runChain(spec, 10);
    INFO("largest stretch " << run.largest << ", final " << run.final);
    REQUIRE(run.finite);
    CHECK(run.largest < Real(0.01));
}

TEST_CASE("a 20-link chain swinging down from horizontal stretches less than 2%", "[ch08][chain]") {
    ChainSpec spec;
    spec.links = 20;
    spec.direction = Vec3(1, 0, 0);
    const StretchRun run = runChain(spec, 10);
    INFO("largest stretch " << run.largest << ", final " << run.final);
    REQUIRE(run.finite);
    CHECK(run.largest < Real(0.02));
}

TEST_CASE("a 10:1 mass at the end of a 10-link chain stretches it less than 3%", "[ch08][chain]") {
    ChainSpec spec;
    spec.links = 10;
    spec.endMass = 10;
    const StretchRun run = runChain(spec, 10);
    INFO("largest stretch " << run.largest << ", final " << run.final);
    REQUIRE(run.finite);
    CHECK(run.largest < Real(0.03));
    // Swinging too.
    spec.direction = Vec3(1, 0, 0);
    const StretchRun swinging = runChain(spec, 10);
    INFO("swinging: largest stretch " << swinging.largest);
    CHECK(swinging.largest < Real(0.03));
}

TEST_CASE("rigid Baumgarte joint rows make a 10-link chain diverge, and the soft rows do not", "[ch08][chain]") {
    ChainSpec spec;
    spec.links = 10;
    JointOptions rigid;
    rigid.feedback = JointFeedback::Kind::Baumgarte;
    const StretchRun rigidRun = runChain(spec, 2, rigid);
    const StretchRun softRun = runChain(spec, 2);
    INFO("rigid: largest stretch " << rigidRun.largest << "; soft: " << softRun.largest);
    CHECK((!rigidRun.finite || rigidRun.largest > Real(0.05)));
    CHECK(softRun.largest < Real(0.005));
}
