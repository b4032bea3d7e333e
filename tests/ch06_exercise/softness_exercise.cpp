// Answer check for chapter 6's derive exercise (`ctest -L ch06-exercise`): the soft step's three
// numbers for a 30 Hz contact with damping ratio 10 over a relax substep of 1/600 s, as the page
// derives them from makeSoftness's formulas, against the engine's own function.
#include "06_manifolds/stabilisation.h"

#include <catch2/catch.hpp>

using namespace stepwise;

TEST_CASE("exercise: the soft step's numbers at 30 Hz, damping ratio 10, h = 1/600 s", "[ch06-exercise]") {
    const Softness soft = makeSoftness(Settings{}.contactHertz, Settings{}.contactDampingRatio, Real(1.0 / 600));
    CHECK(soft.biasRate == Approx(9.28).epsilon(1e-3));     // 1/s
    CHECK(soft.massScale == Approx(0.865).epsilon(1e-3));
    CHECK(soft.impulseScale == Approx(0.135).epsilon(4e-3));
    CHECK(soft.massScale + soft.impulseScale == Approx(1).epsilon(1e-5));
}
