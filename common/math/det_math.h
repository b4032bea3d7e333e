#pragma once
// The engine's own elementary functions, the same bits on every compiler, C library and
// instruction set. The C library's sin, exp or atan2 are free to differ in the last bit between
// glibc, the Microsoft CRT, mingw-w64's runtime and Apple's libm (the C and C++ standards set no
// accuracy for them), and one ulp in a scene's layout or a joint's angle grows, step by step, into
// another pile. These are built from + - * / and sqrt only, which IEEE 754 rounds exactly, so with
// contraction and fast-math off (cmake/StepwiseBuildFlags.cmake) every build computes the same
// result.
//
// The double versions follow fdlibm (Sun Microsystems, 1993: range reduction by a three-part pi/2
// or ln 2, then minimax polynomials on the reduced interval); their coefficients are fdlibm's.
// The float versions round the double ones, so they are within one float ulp of the truth.
// Accuracy over each domain is measured against the C library in tests/reliability/det_math_test.cpp.
//
// Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved. Developed at SunSoft, a Sun
// Microsystems, Inc. business. Permission to use, copy, modify, and distribute this software is
// freely granted, provided that this notice is preserved. (The coefficients and the structure of
// the kernels below are fdlibm's.)

namespace stepwise::det {

/// |x| up to 2^20 * pi/2 (1.6e6 rad) reduces exactly; beyond it the reduction loses accuracy,
/// and beyond 2^51 (no integer count of quarter turns fits) the answer is NaN.
double sin(double x);
double cos(double x);
double tan(double x);
double atan(double x);
double atan2(double y, double x);
double asin(double x);
double acos(double x);
double exp(double x);
double log(double x);
double log2(double x);
double pow(double x, double y);
double cbrt(double x);
double hypot(double x, double y);

// Float: the double function, rounded once.
inline float sin(float x) { return static_cast<float>(sin(static_cast<double>(x))); }
inline float cos(float x) { return static_cast<float>(cos(static_cast<double>(x))); }
inline float tan(float x) { return static_cast<float>(tan(static_cast<double>(x))); }
inline float atan(float x) { return static_cast<float>(atan(static_cast<double>(x))); }
inline float atan2(float y, float x) { return static_cast<float>(atan2(static_cast<double>(y), static_cast<double>(x))); }
inline float asin(float x) { return static_cast<float>(asin(static_cast<double>(x))); }
inline float acos(float x) { return static_cast<float>(acos(static_cast<double>(x))); }
inline float exp(float x) { return static_cast<float>(exp(static_cast<double>(x))); }
inline float log(float x) { return static_cast<float>(log(static_cast<double>(x))); }
inline float log2(float x) { return static_cast<float>(log2(static_cast<double>(x))); }
inline float pow(float x, float y) { return static_cast<float>(pow(static_cast<double>(x), static_cast<double>(y))); }
inline float cbrt(float x) { return static_cast<float>(cbrt(static_cast<double>(x))); }
inline float hypot(float x, float y) { return static_cast<float>(hypot(static_cast<double>(x), static_cast<double>(y))); }

}  // namespace stepwise::det
