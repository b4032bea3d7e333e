#pragma once
// "The same bits", not "the same value": a NaN equals itself and -0 differs from +0. What a
// record kept beside the World (chapter 9's snapshots, chapter 11's handed joint rows) asks of the
// numbers it holds against the World's, to know that nothing was edited since.

#include "math/math.h"

#include <cstring>
#include <type_traits>

namespace stepwise {

/// Any plain value: a number, or a struct of numbers without padding.
template <class T>
bool sameBits(const T& a, const T& b) {
    static_assert(std::is_trivially_copyable_v<T>, "sameBits compares an object's bytes");
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}
inline bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), 3 * sizeof(Real)) == 0; }
inline bool sameBits(const Mat3& a, const Mat3& b) { return std::memcmp(a.data(), b.data(), 9 * sizeof(Real)) == 0; }
inline bool sameBits(const Quat& a, const Quat& b) {
    return std::memcmp(a.coeffs().data(), b.coeffs().data(), 4 * sizeof(Real)) == 0;
}

}  // namespace stepwise
