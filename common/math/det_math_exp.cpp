// exp, log, log2, pow, cbrt, hypot of common/math/det_math.h: fdlibm's e_exp.c, e_log.c and
// s_cbrt.c (FreeBSD's revision), and hypot by exact power-of-two scaling.
#include "math/det_math.h"
#include "math/det_math_bits.h"

#include <cmath>  // std::sqrt only: IEEE 754 rounds it exactly, like + - * /
#include <utility>

namespace stepwise::det {

namespace {

// ln 2 in two parts: the high part has 32 significant bits, so k * kLn2High is exact for any
// exponent k a double can have (fdlibm).
constexpr double kLn2High = 6.93147180369123816490e-01;  // 0x3FE62E42FEE00000
constexpr double kLn2Low = 1.90821492927058770002e-10;   // 0x3DEA39EF35793C76
constexpr double kInvLn2 = 1.44269504088896338700e+00;
constexpr double kTwo54 = 18014398509481984.0;           // 2^54: lifts a subnormal into the normals

// log(1 + f) - f for sqrt(2)/2 <= 1 + f < sqrt(2): with s = f / (2 + f), log(1 + f) = 2 atanh(s)
// = 2s + 2s^3/3 + ..., so log(1 + f) = f - hfsq + s (hfsq + R(s^2)) with hfsq = f^2 / 2 and R a
// minimax polynomial (fdlibm e_log.c). Returned as the two pieces that keep the sum exact-ish.
struct LogParts {
    double k;     // the binary exponent
    double f;     // mantissa - 1
    double hfsq;  // f^2 / 2
    double sR;    // s (hfsq + R)
};

LogParts logParts(double x) {
    constexpr double Lg1 = 6.666666666666735130e-01, Lg2 = 3.999999999940941908e-01, Lg3 = 2.857142874366239149e-01,
                     Lg4 = 2.222219843214978396e-01, Lg5 = 1.818357216161805012e-01, Lg6 = 1.531383769920937332e-01,
                     Lg7 = 1.479819860511658591e-01;
    constexpr std::uint64_t kSqrt2Mantissa = 0x6A09E667F3BCDULL;  // the fraction bits of sqrt(2)
    int k = 0;
    if (x < 2.2250738585072014e-308) x *= kTwo54, k = -54;  // subnormal
    const std::uint64_t b = bits::of(x);
    std::uint64_t mantissa = b & ((std::uint64_t(1) << 52) - 1);
    k += static_cast<int>(b >> 52) - 1023;
    // 1 + f in [sqrt(2)/2, sqrt(2)): a mantissa above sqrt(2)'s is halved (exponent field 1022).
    std::uint64_t exponentField = 1023;
    if (mantissa >= kSqrt2Mantissa) exponentField = 1022, ++k;
    const double m = bits::from((exponentField << 52) | mantissa);
    const double f = m - 1.0;  // exact (Sterbenz)
    const double s = f / (2.0 + f), z = s * s, w = z * z;
    const double t1 = w * (Lg2 + w * (Lg4 + w * Lg6));
    const double t2 = z * (Lg1 + w * (Lg3 + w * (Lg5 + w * Lg7)));
    const double hfsq = 0.5 * f * f;
    return {static_cast<double>(k), f, hfsq, s * (hfsq + t1 + t2)};
}

}  // namespace

// exp(x) = 2^k exp(r), x = k ln2 + r, |r| <= ln2 / 2; exp(r) = 1 + 2r / (R(r^2) - r), with
// R a minimax fit of r (e^r + 1) / (e^r - 1) (fdlibm e_exp.c, its Remez coefficients).
double exp(double x) {
    constexpr double P1 = 1.66666666666666019037e-01, P2 = -2.77777777770155933842e-03,
                     P3 = 6.61375632143793436117e-05, P4 = -1.65339022054652515390e-06,
                     P5 = 4.13813679705723846039e-08;
    constexpr double kOverflow = 7.09782712893383973096e+02;    // ln(largest double)
    constexpr double kUnderflow = -7.45133219101941108420e+02;  // ln(smallest subnormal / 2)
    if (bits::isNan(x)) return x + x;
    if (x > kOverflow) return bits::from(bits::kInfinity);
    if (x < kUnderflow) return 0.0;
    const double k = bits::roundToInteger(x * kInvLn2);
    const double hi = x - k * kLn2High;  // exact
    const double lo = k * kLn2Low;
    const double r = hi - lo, t = r * r;
    const double c = r - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5))));
    const double y = 1.0 - ((lo - (r * c) / (2.0 - c)) - hi);
    return bits::scale(y, static_cast<int>(k));
}

double log(double x) {
    if (bits::isNan(x)) return x + x;
    if (x < 0) return bits::nan();
    if (x == 0) return -bits::from(bits::kInfinity);
    if (bits::isInf(x)) return x;
    const LogParts p = logParts(x);
    return p.k * kLn2High - ((p.hfsq - (p.sR + p.k * kLn2Low)) - p.f);
}

// log2(x) = k + log(1 + f) / ln 2: the exponent stays exact, so log2 of a power of two is exact.
double log2(double x) {
    if (bits::isNan(x)) return x + x;
    if (x < 0) return bits::nan();
    if (x == 0) return -bits::from(bits::kInfinity);
    if (bits::isInf(x)) return x;
    const LogParts p = logParts(x);
    return p.k + (p.f - (p.hfsq - p.sR)) * kInvLn2;
}

namespace {

// Whether y is an integer, and an odd one, from + and - alone (every double of magnitude 2^52 or
// more is an even integer).
bool isInteger(double y) {
    const double a = bits::abs(y);
    return a >= 4503599627370496.0 || bits::roundToInteger(a) == a;
}
bool isOddInteger(double y) {
    const double a = bits::abs(y);
    if (a >= 9007199254740992.0 || !isInteger(y)) return false;  // 2^53 and beyond: even
    const double half = 0.5 * a;                                 // exact
    return bits::roundToInteger(half) != half;
}

// x^n by squaring for a small integer n: at most 2 log2(n) roundings, and exact where x^n is
// representable (pow(2, 10), pow(-2, 3)), where exp(n log x) would miss by an ulp.
constexpr double kLargestSquaringExponent = 64;
double powInteger(double x, double n) {
    double result = 1.0, base = x;
    for (int k = static_cast<int>(bits::abs(n)); k > 0; k >>= 1) {
        if (k & 1) result *= base;
        if (k > 1) base *= base;
    }
    return n < 0 ? 1.0 / result : result;
}

}  // namespace

// pow(x, y) = exp(y log x): the relative error of y log x grows with its size, so the result is
// within 1 + 2|y ln x| ulps in double (within one ulp for the float version, computed in double).
// The C standard's special cases: pow(x, 0) = pow(1, y) = 1, negative x only for integer y,
// signed zeros and infinities.
double pow(double x, double y) {
    if (y == 0 || x == 1) return 1.0;
    if (bits::isNan(x) || bits::isNan(y)) return x + y;
    bool negate = false;
    if (bits::signBit(x)) {
        if (!isInteger(y)) return x == 0 ? (y > 0 ? 0.0 : bits::from(bits::kInfinity)) : bits::nan();
        negate = isOddInteger(y);
        x = -x;
    }
    double result;
    if (x == 0) result = y > 0 ? 0.0 : bits::from(bits::kInfinity);
    else if (bits::isInf(x)) result = y > 0 ? x : 0.0;
    else if (bits::isInf(y)) result = (x > 1) == (y > 0) ? bits::from(bits::kInfinity) : 0.0;
    else if (isInteger(y) && bits::abs(y) <= kLargestSquaringExponent) result = powInteger(x, y);
    else result = exp(y * log(x));
    return negate ? -result : result;
}

// Cube root: a first guess from the exponent divided by 3 in the bits, a polynomial step to 23
// bits, rounded to 22 bits so that t^3 is exact enough, then one Newton step (FreeBSD s_cbrt.c,
// Bruce Evans): error below 0.667 ulp, so an exact cube's root comes out exact.
double cbrt(double x) {
    constexpr std::uint32_t B1 = 715094163;  // (1023 - 1023/3 - 0.03306235651) * 2^20
    constexpr std::uint32_t B2 = 696219795;  // (1023 - 1023/3 - 54/3 - 0.03306235651) * 2^20
    constexpr double P0 = 1.87595182427177009643, P1 = -1.88497979543377169875, P2 = 1.621429720105354466140,
                     P3 = -0.758397934778766047437, P4 = 0.145996192886612446982;
    const std::uint64_t b = bits::of(x);
    const std::uint32_t sign = static_cast<std::uint32_t>(b >> 32) & 0x80000000u;
    const std::uint32_t high = static_cast<std::uint32_t>(b >> 32) & 0x7fffffffu;
    if (high >= 0x7ff00000u) return x + x;  // NaN, inf
    double t;
    if (high < 0x00100000u) {  // zero or subnormal
        if (x == 0) return x;
        t = x * kTwo54;
        const std::uint32_t lifted = static_cast<std::uint32_t>(bits::of(t) >> 32) & 0x7fffffffu;
        t = bits::from(static_cast<std::uint64_t>(sign | (lifted / 3 + B2)) << 32);
    } else {
        t = bits::from(static_cast<std::uint64_t>(sign | (high / 3 + B1)) << 32);
    }
    double r = (t * t) * (t / x);
    t = t * ((P0 + r * (P1 + r * P2)) + ((r * r) * r) * (P3 + r * P4));
    t = bits::from((bits::of(t) + 0x80000000ULL) & 0xffffffffc0000000ULL);
    const double s = t * t;
    r = x / s;
    const double w = t + t;
    r = (r - t) / (w + r);
    return t + t * r;
}

// sqrt(x^2 + y^2) with the larger side scaled by a power of two (exact) into [2^-500, 2^500], so
// neither square overflows nor loses the sum to underflow: one rounding of the sum, one of sqrt.
double hypot(double x, double y) {
    double a = bits::abs(x), b = bits::abs(y);
    if (bits::isInf(a) || bits::isInf(b)) return bits::from(bits::kInfinity);
    if (bits::isNan(a) || bits::isNan(b)) return a + b;
    if (a < b) std::swap(a, b);
    if (b == 0) return a;
    int k = 0;
    if (a > bits::pow2(500)) k = 600;
    else if (a < bits::pow2(-500)) k = -600;
    a = bits::scale(a, -k);
    b = bits::scale(b, -k);
    return bits::scale(std::sqrt(a * a + b * b), k);
}

}  // namespace stepwise::det
