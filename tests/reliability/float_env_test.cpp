// The arithmetic rules the build's flags promise (cmake/StepwiseBuildFlags.cmake), checked in the
// running program: every intermediate rounds to its own type, and sums keep their written order.
#include <catch2/catch.hpp>

#include <cfloat>

namespace {

// Values through volatile, so that the compiler cannot fold the expressions at compile time.
template <typename T>
T opaque(T value) {
    volatile T held = value;
    return held;
}

}  // namespace

TEST_CASE("x87 and SSE: every intermediate rounds to its own type", "[reliability][float_env]") {
    // The x87 unit keeps intermediates in 80-bit registers and rounds them when stored, so a
    // result depends on register allocation. SSE2 (every x86-64 build; -msse2 -mfpmath=sse for
    // 32-bit x86, cmake/StepwiseBuildFlags.cmake) rounds every operation: FLT_EVAL_METHOD 0.
    STATIC_REQUIRE(FLT_EVAL_METHOD == 0);
    const float one = opaque(1.0f), tiny = opaque(0x1p-25f);
    CHECK((one + tiny) - one == 0.0f);  // an 80-bit intermediate would keep tiny
    const double oneD = opaque(1.0), tinyD = opaque(0x1p-54);
    CHECK((oneD + tinyD) - oneD == 0.0);
}

TEST_CASE("reassociation: sums keep the order they are written in", "[reliability][float_env]") {
    // -ffast-math (-fassociative-math) would let the optimiser regroup (a + b) + c as a + (b + c);
    // the build says -fno-fast-math.
#ifdef __FAST_MATH__
    FAIL("built with -ffast-math");
#endif
    const float big = opaque(1e8f), one = opaque(1.0f);
    CHECK((big + one) - big == 0.0f);  // 1e8 + 1 rounds back to 1e8 in float
    CHECK(one + (big - big) == 1.0f);
}
