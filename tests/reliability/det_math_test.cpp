// The engine's own elementary functions (common/math/det_math.h): their accuracy against the C
// library over each domain the engine uses, and their exact bits on a few inputs, which any
// build, whatever its compiler, C library or instruction set, must reproduce.
#include "math/det_math.h"
#include "math/math.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>

using namespace stepwise;

namespace {

// The error of `value` against the long double reference, in units of the last place of `value`'s
// type (a fraction: 0.5 is correct rounding). long double carries 64 bits of mantissa on x86-64
// Linux and mingw-w64, 11 beyond double, which makes it a reference to a hundredth of an ulp; where
// it is double itself (MSVC) the measure is only good to about an ulp.
template <typename T>
double ulpError(T value, long double reference) {
    if (std::isnan(value) && std::isnan(reference)) return 0;
    const T rounded = static_cast<T>(reference);  // beyond T's range: infinity
    if (std::isinf(value) || std::isinf(rounded)) return value == rounded ? 0 : 1e30;
    const T magnitude = std::abs(static_cast<T>(reference));
    const T ulp = std::nextafter(magnitude, std::numeric_limits<T>::infinity()) - magnitude;
    return static_cast<double>(std::abs(static_cast<long double>(value) - reference) / ulp);
}

struct Domain {
    double low, high;
};

// The largest error over `samples` uniform points of a domain, in double and in float.
struct Worst {
    double inDouble = 0, inFloat = 0;
};

// The references take the very inputs the functions got, in their own type: the long double
// function of a double or float argument.
Worst worstError(const Domain& domain, const std::function<double(double)>& det,
                 const std::function<float(float)>& detFloat, const std::function<long double(double)>& reference,
                 const std::function<long double(float)>& referenceFloat, int samples = 20000) {
    std::mt19937_64 random(45);
    std::uniform_real_distribution<double> uniform(domain.low, domain.high);
    Worst worst;
    for (int i = 0; i < samples; ++i) {
        const double x = uniform(random);
        const float xf = static_cast<float>(x);
        worst.inDouble = std::max(worst.inDouble, ulpError(det(x), reference(x)));
        worst.inFloat = std::max(worst.inFloat, ulpError(detFloat(xf), referenceFloat(xf)));
    }
    return worst;
}

#define STEPWISE_WORST(name, low, high)                                                                  \
    worstError({low, high}, [](double x) { return det::name(x); }, [](float x) { return det::name(x); }, \
               [](double x) { return std::name(static_cast<long double>(x)); },                          \
               [](float x) { return std::name(static_cast<long double>(x)); })

// A function of two arguments along the line y = 0.37 x - 1.1, computed in each type.
#define STEPWISE_WORST2(name, low, high)                                                                          \
    worstError({low, high}, [](double x) { return det::name(x, 0.37 * x - 1.1); },                                \
               [](float x) { return det::name(x, 0.37f * x - 1.1f); },                                             \
               [](double x) { return std::name(static_cast<long double>(x), static_cast<long double>(0.37 * x - 1.1)); }, \
               [](float x) { return std::name(static_cast<long double>(x), static_cast<long double>(0.37f * x - 1.1f)); })

}  // namespace

TEST_CASE("libm differences: the engine's functions are within their stated ulps of the truth", "[reliability][det_math]") {
    struct Case {
        const char* name;
        Worst worst;
        double doubleBound;  // ulps; every float version is within one float ulp
    };
    const Case cases[] = {
        {"sin [-pi, pi]", STEPWISE_WORST(sin, -3.2, 3.2), 1},
        {"sin [-1e5, 1e5]", STEPWISE_WORST(sin, -1e5, 1e5), 1},
        {"cos [-pi, pi]", STEPWISE_WORST(cos, -3.2, 3.2), 1},
        {"cos [-1e5, 1e5]", STEPWISE_WORST(cos, -1e5, 1e5), 1},
        {"tan [-1.5, 1.5]", STEPWISE_WORST(tan, -1.5, 1.5), 2.5},
        {"atan [-1e6, 1e6]", STEPWISE_WORST(atan, -1e6, 1e6), 1},
        {"atan [-4, 4]", STEPWISE_WORST(atan, -4, 4), 1},
        {"asin [-1, 1]", STEPWISE_WORST(asin, -1, 1), 2},
        {"acos [-1, 1]", STEPWISE_WORST(acos, -1, 1), 2},
        {"exp [-745, 709]", STEPWISE_WORST(exp, -745, 709), 1},
        {"log [1e-300, 1e300]", STEPWISE_WORST(log, 1e-300, 1e300), 1},
        {"log [0.5, 2]", STEPWISE_WORST(log, 0.5, 2), 1},
        {"log2 [1e-6, 1e6]", STEPWISE_WORST(log2, 1e-6, 1e6), 1.5},
        {"cbrt [-1e3, 1e3]", STEPWISE_WORST(cbrt, -1e3, 1e3), 0.667},
        {"atan2(x, 0.37x - 1.1)", STEPWISE_WORST2(atan2, -10, 10), 1.5},
        {"hypot(x, 0.37x - 1.1)", STEPWISE_WORST2(hypot, -10, 10), 1.5},  // three roundings under the root
        // pow = exp(y log x): |y ln x| <= 6 here, so within 1 + 2 * 6 ulps (det_math_exp.cpp).
        {"pow(x, 0.37x - 1.1) [0.01, 10]", STEPWISE_WORST2(pow, 0.01, 10), 13},
    };
    for (const Case& c : cases) {
        INFO(c.name << ": double " << c.worst.inDouble << " ulp, float " << c.worst.inFloat << " ulp");
        CHECK(c.worst.inDouble <= c.doubleBound);
        CHECK(c.worst.inFloat <= 1.0);
    }
}

TEST_CASE("libm differences: the engine's functions give these exact bits in every build", "[reliability][det_math]") {
    // Read from this implementation once; a build that rounds one operation differently (a fused
    // multiply-add, an extended-precision register, a reordered sum) changes at least one of them.
    CHECK(det::sin(1.0) == 0x1.aed548f090ceep-1);
    CHECK(det::cos(1.0) == 0x1.14a280fb5068cp-1);
    CHECK(det::tan(1.0) == 0x1.8eb245cbee3a5p+0);
    CHECK(det::sin(100.0) == -0x1.03425b78c4db8p-1);
    CHECK(det::atan(1.0) == 0x1.921fb54442d18p-1);
    CHECK(det::atan2(1.0, 2.0) == 0x1.dac670561bb4fp-2);
    CHECK(det::asin(0.5) == 0x1.0c152382d7366p-1);
    CHECK(det::acos(0.5) == 0x1.0c152382d7365p+0);
    CHECK(det::exp(1.0) == 0x1.5bf0a8b14576ap+1);
    CHECK(det::log(10.0) == 0x1.26bb1bbb55516p+1);
    CHECK(det::log2(3.0) == 0x1.95c01a39fbd69p+0);
    CHECK(det::pow(10.0, -3.0) == 0x1.0624dd2f1a9fcp-10);  // by squaring: 1 / 1000, correctly rounded
    CHECK(det::cbrt(2.0) == 0x1.428a2f98d728bp+0);
    CHECK(det::hypot(1.0, 1.0) == 0x1.6a09e667f3bcdp+0);
    CHECK(det::sin(1.0f) == 0x1.aed548p-1f);
    CHECK(det::cos(1.0f) == 0x1.14a28p-1f);
    CHECK(det::atan2(1.0f, 2.0f) == 0x1.dac67p-2f);
    CHECK(det::pow(3.0f, 1.7f) == 0x1.9e45c4p+2f);
    // Exact where the answer is representable: grids of n^3 bodies size themselves by cbrt.
    for (int n = 1; n <= 2000; ++n) REQUIRE(det::cbrt(double(n) * n * n) == n);
    CHECK(det::log2(1024.0) == 10);
    CHECK(det::hypot(3.0, 4.0) == 5);
}

TEST_CASE("libm differences: the C standard's special cases", "[reliability][det_math]") {
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(std::isnan(det::sin(inf)));
    CHECK(std::isnan(det::log(-1.0)));
    CHECK(det::log(0.0) == -inf);
    CHECK(det::exp(-1000.0) == 0);
    CHECK(det::exp(1000.0) == inf);
    CHECK(det::atan2(0.0, -0.0) == Approx(3.14159265358979));
    CHECK(det::atan2(-0.0, -1.0) == Approx(-3.14159265358979));
    CHECK(det::atan2(inf, -inf) == Approx(3 * 0.785398163397448));
    CHECK(det::pow(-2.0, 3.0) == -8);
    CHECK(std::isnan(det::pow(-2.0, 0.5)));
    CHECK(det::pow(0.0, -1.0) == inf);
    CHECK(std::isnan(det::asin(1.5)));
    CHECK(det::hypot(inf, std::nan("")) == inf);
    CHECK(det::hypot(1e300, 1e300) == Approx(1.4142135623730951e300));
    CHECK(det::hypot(3e-320, 4e-320) == Approx(5e-320).epsilon(1e-3));
}

TEST_CASE("the engine calls its own functions when the build option is on", "[reliability][det_math]") {
    // STEPWISE_CROSS_PLATFORM_DETERMINISM (CMakeLists.txt): on, math::sin is det::sin to the bit;
    // off, the C library's.
    const Real angle = Real(0.7853);
    if (math::kCrossPlatformDeterminism) CHECK(math::sin(angle) == det::sin(angle));
    else CHECK(math::sin(angle) == std::sin(angle));
    const Quat turn = angleAxis(Real(0.5), Vec3::UnitY());
    CHECK(turn.w() == math::cos(Real(0.25)));
    CHECK(turn.y() == math::sin(Real(0.25)));
}
