// sin, cos, tan, atan, atan2, asin, acos of common/math/det_math.h: fdlibm's kernels (k_sin.c,
// k_cos.c, s_atan.c, e_atan2.c) over Cody and Waite's reduction by a three-part pi/2.
#include "math/det_math.h"
#include "math/det_math_bits.h"

#include <cmath>  // std::sqrt only: IEEE 754 rounds it exactly, like + - * /

namespace stepwise::det {

namespace {

// pi/2 in three parts: the first two have 33 significant bits, so n * part is exact for
// |n| < 2^20 and x - n * kHalfPi1 loses nothing; together with the tail they carry 119 bits of pi/2
// (fdlibm's e_rem_pio2.c).
constexpr double kHalfPi1 = 1.57079632673412561417e+00;    // 0x3FF921FB54400000
constexpr double kHalfPi2 = 6.07710050630396597660e-11;    // 0x3DD0B4611A600000
constexpr double kHalfPi2Tail = 2.02226624879595063154e-21;  // 0x3BA3198A2E037073
constexpr double kTwoOverPi = 6.36619772367581382433e-01;
constexpr double kQuarterPi = 7.85398163397448278999e-01;
// Beyond 2^51 quarter turns, n no longer rounds to an integer (bits::roundToInteger).
constexpr double kLargestArgument = 2251799813685248.0 * 1.57079632679489661923;  // 2^51 * pi/2

// sin on [-pi/4, pi/4]: x + x^3 (S1 + x^2 S2 + ... + x^10 S6), a minimax fit (fdlibm k_sin.c);
// `tail` is the part of the argument the reduction could not hold in x.
double kernelSin(double x, double tail) {
    constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03,
                     S3 = -1.98412698298579493134e-04, S4 = 2.75573137070700676789e-06,
                     S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
    const double z = x * x, v = z * x;
    const double r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
    return x - ((z * (0.5 * tail - v * r) - tail) - v * S1);
}

// cos on [-pi/4, pi/4]: 1 - x^2/2 + x^4 (C1 + ... + x^10 C6), with 1 - x^2/2 summed so that its
// rounding error is carried (fdlibm k_cos.c, FreeBSD's form).
double kernelCos(double x, double tail) {
    constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03,
                     C3 = 2.48015872894767294178e-05, C4 = -2.75573143513906633035e-07,
                     C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
    const double z = x * x, w = z * z;
    const double r = z * (C1 + z * (C2 + z * C3)) + w * w * (C4 + z * (C5 + z * C6));
    const double hz = 0.5 * z, one = 1.0 - hz;
    return one + (((1.0 - one) - hz) + (z * r - x * tail));
}

struct Reduced {
    int quadrant;     // n mod 4
    double head, tail;  // x - n pi/2 = head + tail, |head| <= pi/4 (about)
};

// [reliability-reduce]
// x = n pi/2 + r (Cody and Waite; fdlibm's e_rem_pio2.c, its second, always-taken round).
Reduced reduce(double x) {
    const double n = bits::roundToInteger(x * kTwoOverPi);
    const double t = x - n * kHalfPi1;
    const double w1 = n * kHalfPi2;
    const double r = t - w1;
    const double w = n * kHalfPi2Tail - ((t - r) - w1);
    const double head = r - w;
    const auto count = static_cast<long long>(n);
    return {static_cast<int>(count & 3), head, (r - head) - w};
}
// [reliability-reduce]

bool outOfRange(double x) { return !(bits::abs(x) <= kLargestArgument); }  // NaN, inf, huge

}  // namespace

double sin(double x) {
    if (bits::abs(x) <= kQuarterPi) return kernelSin(x, 0);
    if (outOfRange(x)) return bits::nan();
    const Reduced r = reduce(x);
    switch (r.quadrant) {
        case 0: return kernelSin(r.head, r.tail);
        case 1: return kernelCos(r.head, r.tail);
        case 2: return -kernelSin(r.head, r.tail);
        default: return -kernelCos(r.head, r.tail);
    }
}

double cos(double x) {
    if (bits::abs(x) <= kQuarterPi) return kernelCos(x, 0);
    if (outOfRange(x)) return bits::nan();
    const Reduced r = reduce(x);
    switch (r.quadrant) {
        case 0: return kernelCos(r.head, r.tail);
        case 1: return -kernelSin(r.head, r.tail);
        case 2: return -kernelCos(r.head, r.tail);
        default: return kernelSin(r.head, r.tail);
    }
}

// sin / cos of the reduced argument: two roundings of the kernels and one of the division, so
// within about two ulps (fdlibm's own k_tan.c is closer, at three times the code).
double tan(double x) {
    if (bits::abs(x) <= kQuarterPi) return kernelSin(x, 0) / kernelCos(x, 0);
    if (outOfRange(x)) return bits::nan();
    const Reduced r = reduce(x);
    const double s = kernelSin(r.head, r.tail), c = kernelCos(r.head, r.tail);
    return (r.quadrant & 1) == 0 ? s / c : -c / s;
}

// atan: the argument is moved next to one of 0, atan(1/2), atan(1), atan(3/2) or pi/2 by the
// tangent's addition formula, then a polynomial in x^2 of degree 22 (fdlibm s_atan.c).
double atan(double x) {
    constexpr double kHigh[] = {4.63647609000806093515e-01, 7.85398163397448278999e-01,
                                9.82793723247329054082e-01, 1.57079632679489655800e+00};
    constexpr double kLow[] = {2.26987774529616870924e-17, 3.06161699786838301793e-17,
                               1.39033110312309984516e-17, 6.12323399573676603587e-17};
    constexpr double aT[] = {3.33333333333329318027e-01,  -1.99999999998764832476e-01, 1.42857142725034663711e-01,
                             -1.11111104054623557880e-01, 9.09088713343650656196e-02,  -7.69187620504482999495e-02,
                             6.66107313738753120669e-02,  -5.83357013379057348645e-02, 4.97687799461593236017e-02,
                             -3.65315727442169155270e-02, 1.62858201153657823623e-02};
    if (bits::isNan(x)) return x + x;
    const bool negative = bits::signBit(x);
    double a = bits::abs(x);
    if (a >= 7.378697629483821e19) return negative ? -(kHigh[3] + kLow[3]) : kHigh[3] + kLow[3];  // 2^66
    int id = -1;
    if (a >= 0.4375) {
        if (a < 1.1875) {
            if (a < 0.6875) id = 0, a = (2.0 * a - 1.0) / (2.0 + a);
            else id = 1, a = (a - 1.0) / (a + 1.0);
        } else {
            if (a < 2.4375) id = 2, a = (a - 1.5) / (1.0 + 1.5 * a);
            else id = 3, a = -1.0 / a;
        }
    }
    const double z = a * a, w = z * z;
    const double s1 = z * (aT[0] + w * (aT[2] + w * (aT[4] + w * (aT[6] + w * (aT[8] + w * aT[10])))));
    const double s2 = w * (aT[1] + w * (aT[3] + w * (aT[5] + w * (aT[7] + w * aT[9]))));
    if (id < 0) return x - x * (s1 + s2);
    const double result = kHigh[id] - ((a * (s1 + s2) - kLow[id]) - a);
    return negative ? -result : result;
}

// atan2 by quadrant from atan(|y/x|), with pi's low part added where the result is near pi
// (fdlibm e_atan2.c). The C standard's special cases: signed zeros and infinities.
double atan2(double y, double x) {
    constexpr double kPi = 3.1415926535897931160e+00, kPiLow = 1.2246467991473531772e-16;
    constexpr double kHalfPi = 1.5707963267948965580e+00;
    if (bits::isNan(x) || bits::isNan(y)) return x + y;
    const bool yNegative = bits::signBit(y), xNegative = bits::signBit(x);
    if (y == 0) return xNegative ? (yNegative ? -kPi : kPi) : y;
    if (x == 0) return yNegative ? -kHalfPi : kHalfPi;
    if (bits::isInf(x)) {
        double z;
        if (bits::isInf(y)) z = xNegative ? 3 * kPi / 4 : kPi / 4;
        else z = xNegative ? kPi : 0.0;
        return yNegative ? -z : z;
    }
    if (bits::isInf(y)) return yNegative ? -kHalfPi : kHalfPi;
    const double z = atan(bits::abs(y / x));
    if (!xNegative) return yNegative ? -z : z;
    return yNegative ? (z - kPiLow) - kPi : kPi - (z - kPiLow);
}

// asin and acos through atan2 with the other side sqrt(1 - x^2) = sqrt((1 - x)(1 + x)): 1 - x is
// exact for x in [1/2, 1] (Sterbenz), so the side keeps its relative accuracy near |x| = 1.
double asin(double x) {
    if (!(bits::abs(x) <= 1.0)) return bits::nan();
    return atan2(x, std::sqrt((1.0 - x) * (1.0 + x)));
}

double acos(double x) {
    if (!(bits::abs(x) <= 1.0)) return bits::nan();
    return atan2(std::sqrt((1.0 - x) * (1.0 + x)), x);
}

}  // namespace stepwise::det
