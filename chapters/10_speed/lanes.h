#pragma once
// Several numbers that go through the same arithmetic side by side: one contact per lane.
//
// The contact solver of this chapter is written once, over Pack<N>. With N = 1 it is a plain
// scalar Gauss-Seidel solver; with N = kWideLanes (8 floats or 4 doubles: one 256-bit AVX2
// register) every operation below is a fixed-length loop that the compiler turns into one SIMD
// instruction when the file is built with AVX2 (chapters/10_speed/CMake flags; any other target
// gets the same loops as scalar code, with the same results). Writing the lanes as loops instead
// of intrinsics keeps the solver readable and portable (MSVC, GCC, Clang; x86 and ARM): Box3D
// wraps SSE2/NEON intrinsics behind the same kind of small type (its b2FloatW).

#include "math/math.h"

#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace stepwise {

/// Lanes of the wide solver: as many Reals as one 32-byte (AVX2) register holds.
constexpr int kWideLanes = static_cast<int>(32 / sizeof(Real));

template <int N>
struct alignas(N * sizeof(Real) >= 32 ? 32 : alignof(Real)) Pack {
    Real lane[N];

    static Pack splat(Real value) {
        Pack result;
        for (int i = 0; i < N; ++i) result.lane[i] = value;
        return result;
    }
    Real& operator[](int i) { return lane[i]; }
    Real operator[](int i) const { return lane[i]; }
};

#define STEPWISE_PACK_BINARY(op)                                           \
    template <int N>                                                       \
    inline Pack<N> operator op(const Pack<N>& a, const Pack<N>& b) {       \
        Pack<N> r;                                                         \
        for (int i = 0; i < N; ++i) r.lane[i] = a.lane[i] op b.lane[i];    \
        return r;                                                          \
    }
STEPWISE_PACK_BINARY(+)
STEPWISE_PACK_BINARY(-)
STEPWISE_PACK_BINARY(*)
#undef STEPWISE_PACK_BINARY

template <int N>
inline Pack<N> operator-(const Pack<N>& a) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.lane[i] = -a.lane[i];
    return r;
}
template <int N>
inline Pack<N> operator*(Real s, const Pack<N>& a) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.lane[i] = s * a.lane[i];
    return r;
}
template <int N>
inline Pack<N> min(const Pack<N>& a, const Pack<N>& b) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.lane[i] = a.lane[i] < b.lane[i] ? a.lane[i] : b.lane[i];
    return r;
}
template <int N>
inline Pack<N> max(const Pack<N>& a, const Pack<N>& b) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.lane[i] = a.lane[i] > b.lane[i] ? a.lane[i] : b.lane[i];
    return r;
}
/// Per lane: test > 0 ? ifPositive : otherwise (a blend, no branch).
template <int N>
inline Pack<N> selectPositive(const Pack<N>& test, const Pack<N>& ifPositive, const Pack<N>& otherwise) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.lane[i] = test.lane[i] > 0 ? ifPositive.lane[i] : otherwise.lane[i];
    return r;
}

#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE)
// [ch10-avx2-pack]
// Where the file is built for AVX2 (wide_solver.cpp), the float packs of kWideLanes use the
// 256-bit instructions directly: the loops above would be correct but compilers leave most of them
// scalar. Overloads, not templates, so they win overload resolution for exactly Pack<8>.
inline __m256 load(const Pack<8>& a) { return _mm256_load_ps(a.lane); }
inline Pack<8> packOf(__m256 v) {
    Pack<8> r;
    _mm256_store_ps(r.lane, v);
    return r;
}
inline Pack<8> operator+(const Pack<8>& a, const Pack<8>& b) { return packOf(_mm256_add_ps(load(a), load(b))); }
inline Pack<8> operator-(const Pack<8>& a, const Pack<8>& b) { return packOf(_mm256_sub_ps(load(a), load(b))); }
inline Pack<8> operator*(const Pack<8>& a, const Pack<8>& b) { return packOf(_mm256_mul_ps(load(a), load(b))); }
inline Pack<8> operator-(const Pack<8>& a) { return packOf(_mm256_xor_ps(load(a), _mm256_set1_ps(-0.0f))); }
inline Pack<8> operator*(Real s, const Pack<8>& a) { return packOf(_mm256_mul_ps(_mm256_set1_ps(s), load(a))); }
inline Pack<8> min(const Pack<8>& a, const Pack<8>& b) { return packOf(_mm256_min_ps(load(a), load(b))); }
inline Pack<8> max(const Pack<8>& a, const Pack<8>& b) { return packOf(_mm256_max_ps(load(a), load(b))); }
inline Pack<8> selectPositive(const Pack<8>& test, const Pack<8>& ifPositive, const Pack<8>& otherwise) {
    const __m256 positive = _mm256_cmp_ps(load(test), _mm256_setzero_ps(), _CMP_GT_OQ);
    return packOf(_mm256_blendv_ps(load(otherwise), load(ifPositive), positive));
}
// [ch10-avx2-pack]
#endif

/// A 3-vector per lane, stored as three packs (structure of arrays).
template <int N>
struct PackVec3 {
    Pack<N> x, y, z;
};

template <int N>
inline PackVec3<N> operator+(const PackVec3<N>& a, const PackVec3<N>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <int N>
inline PackVec3<N> operator-(const PackVec3<N>& a, const PackVec3<N>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <int N>
inline PackVec3<N> operator*(const Pack<N>& s, const PackVec3<N>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <int N>
inline Pack<N> dot(const PackVec3<N>& a, const PackVec3<N>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <int N>
inline PackVec3<N> cross(const PackVec3<N>& a, const PackVec3<N>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// A symmetric 3x3 matrix per lane (an inverse inertia in world axes): six packs.
template <int N>
struct PackSym3 {
    Pack<N> xx, yy, zz, xy, xz, yz;
};
template <int N>
inline PackVec3<N> operator*(const PackSym3<N>& m, const PackVec3<N>& v) {
    return {m.xx * v.x + m.xy * v.y + m.xz * v.z, m.xy * v.x + m.yy * v.y + m.yz * v.z,
            m.xz * v.x + m.yz * v.y + m.zz * v.z};
}

/// A unit quaternion per lane (a body's rotation since the step began).
template <int N>
struct PackQuat {
    Pack<N> x, y, z, w;
};
/// q v q*, as v + 2 w (u x v) + 2 u x (u x v) with u the vector part.
template <int N>
inline PackVec3<N> rotate(const PackQuat<N>& q, const PackVec3<N>& v) {
    const PackVec3<N> u{q.x, q.y, q.z};
    const PackVec3<N> t = cross(u, v);
    const PackVec3<N> twiceT{t.x + t.x, t.y + t.y, t.z + t.z};
    return v + q.w * twiceT + cross(u, twiceT);
}

}  // namespace stepwise
