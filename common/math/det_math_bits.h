#pragma once
// Bit-level helpers the deterministic functions share (common/math/det_math.h): exact operations
// on a double's representation, no rounding anywhere.

#include <cstdint>
#include <cstring>
#include <limits>

namespace stepwise::det::bits {

inline std::uint64_t of(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

inline double from(std::uint64_t b) {
    double x;
    std::memcpy(&x, &b, sizeof x);
    return x;
}

constexpr std::uint64_t kMagnitude = ~(std::uint64_t(1) << 63);
constexpr std::uint64_t kInfinity = std::uint64_t(0x7FF) << 52;
inline bool isNan(double x) { return (of(x) & kMagnitude) > kInfinity; }
inline bool isInf(double x) { return (of(x) & kMagnitude) == kInfinity; }
inline bool signBit(double x) { return (of(x) >> 63) != 0; }
inline double abs(double x) { return from(of(x) & kMagnitude); }
inline double nan() { return std::numeric_limits<double>::quiet_NaN(); }

/// 2^k for -1022 <= k <= 1023, built from its exponent field (exact).
inline double pow2(int k) { return from(static_cast<std::uint64_t>(k + 1023) << 52); }

/// x * 2^k with one rounding at most (only when the result is subnormal), for any int k that keeps
/// the result within a factor 2^2000 of x: the product is split into exact steps.
inline double scale(double x, int k) {
    while (k > 1023) x *= pow2(1023), k -= 1023;
    while (k < -1022) x *= pow2(-1022), k += 1022;
    return x * pow2(k);
}

/// Round to the nearest integer, ties to even, for |x| < 2^51: adding 1.5 * 2^52 leaves no bits
/// below the units place, and IEEE addition rounds to nearest even.
constexpr double kRoundShift = 6755399441055744.0;  // 1.5 * 2^52
inline double roundToInteger(double x) { return (x + kRoundShift) - kRoundShift; }

}  // namespace stepwise::det::bits
