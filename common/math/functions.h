#pragma once
// The elementary functions engine code calls, as math::sin(x) and so on: the engine's own
// (det_math.h: the same bits from every compiler, C library and instruction set) when the build
// has STEPWISE_CROSS_PLATFORM_DETERMINISM on, its default; the C library's when it is off (a
// little faster, the same bits only where the C library is the same). Code that feeds a result
// into the simulation calls these, never std::sin; plots and printed statistics may use either.

#include "math/det_math.h"

#include <cmath>

#ifndef STEPWISE_CROSS_PLATFORM_DETERMINISM
#define STEPWISE_CROSS_PLATFORM_DETERMINISM 1
#endif

namespace stepwise::math {

/// Whether this build computes the elementary functions itself (CMake option
/// STEPWISE_CROSS_PLATFORM_DETERMINISM, docs/reliability.md).
constexpr bool kCrossPlatformDeterminism = STEPWISE_CROSS_PLATFORM_DETERMINISM != 0;

// [reliability-math-select]
// One float and one double overload per function, so that a call site's type picks the precision
// exactly as std:: would, and the two settings compile the same call sites.
#define STEPWISE_MATH_UNARY(name)                                                       \
    inline float name(float x) {                                                        \
        if constexpr (kCrossPlatformDeterminism) return det::name(x);                   \
        else return std::name(x);                                                       \
    }                                                                                   \
    inline double name(double x) {                                                      \
        if constexpr (kCrossPlatformDeterminism) return det::name(x);                   \
        else return std::name(x);                                                       \
    }
#define STEPWISE_MATH_BINARY(name)                                                      \
    inline float name(float a, float b) {                                               \
        if constexpr (kCrossPlatformDeterminism) return det::name(a, b);                \
        else return std::name(a, b);                                                    \
    }                                                                                   \
    inline double name(double a, double b) {                                            \
        if constexpr (kCrossPlatformDeterminism) return det::name(a, b);                \
        else return std::name(a, b);                                                    \
    }

STEPWISE_MATH_UNARY(sin)
STEPWISE_MATH_UNARY(cos)
STEPWISE_MATH_UNARY(tan)
STEPWISE_MATH_UNARY(atan)
STEPWISE_MATH_UNARY(asin)
STEPWISE_MATH_UNARY(acos)
STEPWISE_MATH_UNARY(exp)
STEPWISE_MATH_UNARY(log)
STEPWISE_MATH_UNARY(log2)
STEPWISE_MATH_UNARY(cbrt)
STEPWISE_MATH_BINARY(atan2)
STEPWISE_MATH_BINARY(pow)
STEPWISE_MATH_BINARY(hypot)

// [reliability-math-select]

#undef STEPWISE_MATH_UNARY
#undef STEPWISE_MATH_BINARY

}  // namespace stepwise::math
