// Compiled with the wide solve's instruction set (AVX2 and FMA where the build targets them,
// chapters/CMakeLists.txt): where the compiler could fuse a*b + c into one rounding, it must not.
#include <catch2/catch.hpp>

namespace {

template <typename T>
T opaque(T value) {
    volatile T held = value;
    return held;
}

double multiplyAdd(double a, double b, double c) { return a * b + c; }
float multiplyAdd(float a, float b, float c) { return a * b + c; }

}  // namespace

TEST_CASE("contraction: a*b + c rounds twice, even where the build targets FMA", "[reliability][float_env]") {
    // (1 + 2^-27)(1 - 2^-27) = 1 - 2^-54 rounds to 1 (a tie, to even); minus 1 gives 0. A fused
    // multiply-add rounds once and gives -2^-54. -ffp-contract=off (GCC, Clang) and /fp:precise
    // (MSVC) forbid the fusion; a build that allows it gives other bits wherever the compiler
    // chose to fuse, and the golden hashes differ.
    const double a = opaque(1 + 0x1p-27), b = opaque(1 - 0x1p-27), c = opaque(-1.0);
    CHECK(multiplyAdd(a, b, c) == 0.0);
    // In float: (1 + 2^-13)(1 - 2^-13) = 1 - 2^-26 rounds to 1.
    const float af = opaque(1 + 0x1p-13f), bf = opaque(1 - 0x1p-13f), cf = opaque(-1.0f);
    CHECK(multiplyAdd(af, bf, cf) == 0.0f);
#if defined(__FMA__)
    SUCCEED("compiled with FMA available: contraction was possible and did not happen");
#endif
}
