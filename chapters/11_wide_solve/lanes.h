#pragma once
// Several numbers that go through the same arithmetic side by side: one contact per lane.
//
// The contact solver of this chapter is written once, over Pack<N>. With N = 1 it is a plain
// scalar Gauss-Seidel solver; with N = kWideLanes (8 floats or 4 doubles: one 256-bit AVX2
// register) every operation below is one SIMD instruction where the file is built for AVX2
// (wide_solver.cpp, chapters/CMakeLists.txt), and the same arithmetic on narrower instructions
// elsewhere, with the same results. Writing the lanes as plain operators instead of intrinsics
// keeps the solver readable and portable (MSVC, GCC, Clang; x86 and ARM): Box3D wraps SSE2/NEON
// intrinsics behind the same kind of small type (its b2FloatW).

#include "math/math.h"

#include <cmath>

#if defined(__AVX__)
#include <immintrin.h>
#endif

// [ch11-isa]
// Functions over packs are compiled into every file that includes them, for the instruction set
// that file is built for (wide_solver.cpp: AVX2 or AVX-512; every other file: the baseline). The
// same template instantiated in two such files would be two definitions of one function, and the
// linker may keep either for both; so each instruction set's copies live in a namespace of their
// own, inline so that callers name them as usual. The types (Pack, PackVec3, ...) stay outside:
// blocks cross between the files, and their layout is spelled out to be the same in every one.
#if defined(__AVX512F__)
#define STEPWISE_ISA isa_avx512
#elif defined(__AVX2__)
#define STEPWISE_ISA isa_avx2
#elif defined(__AVX__)
#define STEPWISE_ISA isa_avx
#else
#define STEPWISE_ISA isa_baseline
#endif
// [ch11-isa]
#define STEPWISE_LANE_INLINE STEPWISE_ALWAYS_INLINE  // math/math.h

namespace stepwise {

// The width of the wide solver's registers: 32 bytes (AVX2), or 64 where the build chose AVX-512
// (STEPWISE_WIDE_ISA=AVX512, chapters/CMakeLists.txt, defines it for every file that sees this header).
#ifndef STEPWISE_WIDE_BYTES
#define STEPWISE_WIDE_BYTES 32
#endif
/// Lanes of the wide solver: as many Reals as one register holds (8 floats with AVX2, 16 with AVX-512).
constexpr int kWideLanes = static_cast<int>(STEPWISE_WIDE_BYTES / sizeof(Real));
/// The lanes of the blocks the planner's prices were measured on (256-bit): every build plans the
/// same (iteration_plan.h), whatever width it solves at.
constexpr int kPricedLanes = static_cast<int>(32 / sizeof(Real));

// [ch11-pack]
#if defined(__GNUC__)
// GCC and Clang: the lanes are a vector-extension value, which the compiler keeps in registers and
// maps to whatever the translation unit is built for (AVX2 in wide_solver.cpp, SSE2 elsewhere).
#define STEPWISE_VECTOR_PACKS 1
#endif

// The alignment is spelled out: a vector type's natural alignment depends on the compiler and the
// instruction set a file is built for (a 32-byte vector is aligned to 16 bytes with SSE2, to 32
// with AVX2), and every file must agree on the layout.
template <int N>
struct alignas(N * sizeof(Real) >= 64 ? 64 : N * sizeof(Real) >= 32 ? 32 : alignof(Real)) Pack {
#if defined(STEPWISE_VECTOR_PACKS)
    typedef Real Values __attribute__((vector_size(N * sizeof(Real))));
    Values v;
    STEPWISE_LANE_INLINE Real& operator[](int i) { return reinterpret_cast<Real*>(&v)[i]; }
    STEPWISE_LANE_INLINE Real operator[](int i) const { return reinterpret_cast<const Real*>(&v)[i]; }
    STEPWISE_LANE_INLINE static Pack splat(Real value) { return Pack{value - Values{}}; }
#else
    // Elsewhere (MSVC): plain arrays and loops, the same arithmetic, the same results.
    Real v[N];
    STEPWISE_LANE_INLINE Real& operator[](int i) { return v[i]; }
    STEPWISE_LANE_INLINE Real operator[](int i) const { return v[i]; }
    STEPWISE_LANE_INLINE static Pack splat(Real value) {
        Pack result;
        for (int i = 0; i < N; ++i) result.v[i] = value;
        return result;
    }
#endif
    STEPWISE_LANE_INLINE Real* data() { return reinterpret_cast<Real*>(&v); }
    STEPWISE_LANE_INLINE const Real* data() const { return reinterpret_cast<const Real*>(&v); }
};

inline namespace STEPWISE_ISA {

#if defined(STEPWISE_VECTOR_PACKS)
#define STEPWISE_PACK_BINARY(op) \
    template <int N>             \
    inline Pack<N> operator op(const Pack<N>& a, const Pack<N>& b) { return Pack<N>{a.v op b.v}; }
#else
#define STEPWISE_PACK_BINARY(op)                                        \
    template <int N>                                                    \
    inline Pack<N> operator op(const Pack<N>& a, const Pack<N>& b) {    \
        Pack<N> r;                                                      \
        for (int i = 0; i < N; ++i) r.v[i] = a.v[i] op b.v[i];          \
        return r;                                                       \
    }
#endif
STEPWISE_PACK_BINARY(+)
STEPWISE_PACK_BINARY(-)
STEPWISE_PACK_BINARY(*)
STEPWISE_PACK_BINARY(/)
#undef STEPWISE_PACK_BINARY
// [ch11-pack]

template <int N>
inline Pack<N> operator-(const Pack<N>& a) { return Pack<N>::splat(0) - a; }
/// Negation that flips the sign of zero too, as a scalar unary minus does (operator- above is
/// 0 - a, which turns -0 into +0): code that must give a scalar rule's bits uses this one.
template <int N>
inline Pack<N> negated(const Pack<N>& a) {
#if defined(STEPWISE_VECTOR_PACKS)
    return Pack<N>{-a.v};
#else
    Pack<N> result;
    for (int i = 0; i < N; ++i) result.v[i] = -a.v[i];
    return result;
#endif
}
template <int N>
inline Pack<N> operator*(Real s, const Pack<N>& a) { return Pack<N>::splat(s) * a; }

#if defined(STEPWISE_VECTOR_PACKS)
template <int N>
inline Pack<N> min(const Pack<N>& a, const Pack<N>& b) { return Pack<N>{a.v < b.v ? a.v : b.v}; }
template <int N>
inline Pack<N> max(const Pack<N>& a, const Pack<N>& b) { return Pack<N>{a.v > b.v ? a.v : b.v}; }
/// Per lane: test > 0 ? ifPositive : otherwise (a blend, no branch).
template <int N>
inline Pack<N> selectPositive(const Pack<N>& test, const Pack<N>& ifPositive, const Pack<N>& otherwise) {
    return Pack<N>{test.v > Pack<N>::splat(0).v ? ifPositive.v : otherwise.v};
}
/// Per lane: test >= 0 ? ifNonNegative : otherwise.
template <int N>
inline Pack<N> selectNonNegative(const Pack<N>& test, const Pack<N>& ifNonNegative, const Pack<N>& otherwise) {
    return Pack<N>{test.v >= Pack<N>::splat(0).v ? ifNonNegative.v : otherwise.v};
}
#else
template <int N>
inline Pack<N> selectNonNegative(const Pack<N>& test, const Pack<N>& ifNonNegative, const Pack<N>& otherwise) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.v[i] = test.v[i] >= 0 ? ifNonNegative.v[i] : otherwise.v[i];
    return r;
}
template <int N>
inline Pack<N> min(const Pack<N>& a, const Pack<N>& b) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i];
    return r;
}
template <int N>
inline Pack<N> max(const Pack<N>& a, const Pack<N>& b) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i];
    return r;
}
template <int N>
inline Pack<N> selectPositive(const Pack<N>& test, const Pack<N>& ifPositive, const Pack<N>& otherwise) {
    Pack<N> r;
    for (int i = 0; i < N; ++i) r.v[i] = test.v[i] > 0 ? ifPositive.v[i] : otherwise.v[i];
    return r;
}
#endif
/// Per lane square root (one instruction on AVX2; the friction cone's clamp needs a length).
template <int N>
inline Pack<N> sqrt(const Pack<N>& a) {
#if defined(__AVX2__) && defined(STEPWISE_VECTOR_PACKS)
    if constexpr (N * sizeof(Real) == 32) {
        using Values = typename Pack<N>::Values;
        if constexpr (sizeof(Real) == 4)
            return Pack<N>{reinterpret_cast<Values>(_mm256_sqrt_ps(reinterpret_cast<__m256>(a.v)))};
        else
            return Pack<N>{reinterpret_cast<Values>(_mm256_sqrt_pd(reinterpret_cast<__m256d>(a.v)))};
    } else if constexpr (N * sizeof(Real) == 64) {
        // AVX-512's sixteen lanes as two halves: as fast as one 512-bit root, which is split in two
        // inside the core anyway, and GCC 12 warns about its own header's _mm512_sqrt_ps.
        Pack<N / 2> low, high;
        for (int i = 0; i < N / 2; ++i) low[i] = a[i], high[i] = a[i + N / 2];
        low = sqrt(low);
        high = sqrt(high);
        Pack<N> root;
        for (int i = 0; i < N / 2; ++i) root[i] = low[i], root[i + N / 2] = high[i];
        return root;
    }
#endif
    Pack<N> r;
    for (int i = 0; i < N; ++i) r[i] = std::sqrt(a[i]);
    return r;
}
/// What anyLane asks of each lane: whether it is below zero, or whether it is not zero (NaN is
/// not zero).
enum class ZeroTest { Below, NotEqual };

/// Whether any lane passes `kTest` (a branch over the whole pack).
template <ZeroTest kTest, int N>
inline bool anyLane(const Pack<N>& a) {
#if defined(__AVX__) && defined(STEPWISE_VECTOR_PACKS)
    constexpr int predicate = kTest == ZeroTest::Below ? _CMP_LT_OQ : _CMP_NEQ_UQ;
#endif
#if defined(__AVX512F__) && defined(STEPWISE_VECTOR_PACKS)
    if constexpr (N * sizeof(Real) == 64) {
        if constexpr (sizeof(Real) == 4)
            return _mm512_cmp_ps_mask(reinterpret_cast<__m512>(a.v), _mm512_setzero_ps(), predicate) != 0;
        else
            return _mm512_cmp_pd_mask(reinterpret_cast<__m512d>(a.v), _mm512_setzero_pd(), predicate) != 0;
    }
#endif
#if defined(__AVX__) && defined(STEPWISE_VECTOR_PACKS)
    // One compare and a mask test, where the loop below compiles to a compare and a branch a lane.
    if constexpr (N * sizeof(Real) == 32) {
        if constexpr (sizeof(Real) == 4) {
            const __m256 values = reinterpret_cast<__m256>(a.v);
            return _mm256_movemask_ps(_mm256_cmp_ps(values, _mm256_setzero_ps(), predicate)) != 0;
        } else {
            const __m256d values = reinterpret_cast<__m256d>(a.v);
            return _mm256_movemask_pd(_mm256_cmp_pd(values, _mm256_setzero_pd(), predicate)) != 0;
        }
    }
#endif
    bool any = false;
    for (int i = 0; i < N; ++i) any |= kTest == ZeroTest::Below ? a[i] < 0 : !(a[i] == 0);
    return any;
}
/// Whether any lane holds a value below zero.
template <int N>
inline bool anyNegative(const Pack<N>& a) {
    return anyLane<ZeroTest::Below>(a);
}
/// Whether any lane holds a value other than zero (NaN counts: it is not zero).
template <int N>
inline bool anyNonZero(const Pack<N>& a) {
    return anyLane<ZeroTest::NotEqual>(a);
}

/// A 3-vector per lane, stored as three packs (structure of arrays).
}  // namespace STEPWISE_ISA
template <int N>
struct PackVec3 {
    Pack<N> x, y, z;
};
inline namespace STEPWISE_ISA {

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

/// Per lane: test > 0 ? ifPositive : otherwise, for each component.
template <int N>
inline PackVec3<N> select(const Pack<N>& test, const PackVec3<N>& ifPositive, const PackVec3<N>& otherwise) {
    return {selectPositive(test, ifPositive.x, otherwise.x), selectPositive(test, ifPositive.y, otherwise.y),
            selectPositive(test, ifPositive.z, otherwise.z)};
}

/// A symmetric 3x3 matrix per lane (an inverse inertia in world axes): six packs.
}  // namespace STEPWISE_ISA
template <int N>
struct PackSym3 {
    Pack<N> xx, yy, zz, xy, xz, yz;
};
inline namespace STEPWISE_ISA {
template <int N>
inline PackVec3<N> operator*(const PackSym3<N>& m, const PackVec3<N>& v) {
    return {m.xx * v.x + m.xy * v.y + m.xz * v.z, m.xy * v.x + m.yy * v.y + m.yz * v.z,
            m.xz * v.x + m.yz * v.y + m.zz * v.z};
}

/// A unit quaternion per lane (a body's rotation since the step began).
}  // namespace STEPWISE_ISA
template <int N>
struct PackQuat {
    Pack<N> x, y, z, w;
};
inline namespace STEPWISE_ISA {
/// The inverse rotation of a unit quaternion.
template <int N>
inline PackQuat<N> conjugate(const PackQuat<N>& q) {
    return {-q.x, -q.y, -q.z, q.w};
}
/// q v q*, as v + 2 w (u x v) + 2 u x (u x v) with u the vector part.
template <int N>
inline PackVec3<N> rotate(const PackQuat<N>& q, const PackVec3<N>& v) {
    const PackVec3<N> u{q.x, q.y, q.z};
    const PackVec3<N> t = cross(u, v);
    const PackVec3<N> twiceT{t.x + t.x, t.y + t.y, t.z + t.z};
    return v + q.w * twiceT + cross(u, twiceT);
}
/// The Hamilton product a b: turn by b, then by a.
template <int N>
inline PackQuat<N> multiply(const PackQuat<N>& a, const PackQuat<N>& b) {
    return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z,
            a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}
/// q over its length (a unit quaternion drifts off unit length as products round).
template <int N>
inline PackQuat<N> normalized(const PackQuat<N>& q) {
    const Pack<N> length = sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
    return {q.x / length, q.y / length, q.z / length, q.w / length};
}

}  // namespace STEPWISE_ISA
}  // namespace stepwise
