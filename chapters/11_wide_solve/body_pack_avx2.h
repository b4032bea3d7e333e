#pragma once
// The AVX2 float build's gather and scatter of eight bodies (body_pack.h's, specialised): two
// loads a body and an 8x8 transpose, where the generic code makes 8 x 13 scalar loads.
// Included at the end of body_pack.h.

#include "11_wide_solve/body_pack.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE)
// The AVX2 float build gathers eight bodies with two loads each and an 8x8 transpose (rows: lanes'
// states; columns: fields), the way Box3D gathers its bodies, instead of 8 x 13 scalar loads.
inline void transpose8(__m256 (&row)[8]) {
    const __m256 t0 = _mm256_unpacklo_ps(row[0], row[1]), t1 = _mm256_unpackhi_ps(row[0], row[1]);
    const __m256 t2 = _mm256_unpacklo_ps(row[2], row[3]), t3 = _mm256_unpackhi_ps(row[2], row[3]);
    const __m256 t4 = _mm256_unpacklo_ps(row[4], row[5]), t5 = _mm256_unpackhi_ps(row[4], row[5]);
    const __m256 t6 = _mm256_unpacklo_ps(row[6], row[7]), t7 = _mm256_unpackhi_ps(row[6], row[7]);
    const __m256 u0 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0)), u1 = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 u2 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0)), u3 = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 u4 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(1, 0, 1, 0)), u5 = _mm256_shuffle_ps(t4, t6, _MM_SHUFFLE(3, 2, 3, 2));
    const __m256 u6 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(1, 0, 1, 0)), u7 = _mm256_shuffle_ps(t5, t7, _MM_SHUFFLE(3, 2, 3, 2));
    row[0] = _mm256_permute2f128_ps(u0, u4, 0x20);
    row[1] = _mm256_permute2f128_ps(u1, u5, 0x20);
    row[2] = _mm256_permute2f128_ps(u2, u6, 0x20);
    row[3] = _mm256_permute2f128_ps(u3, u7, 0x20);
    row[4] = _mm256_permute2f128_ps(u0, u4, 0x31);
    row[5] = _mm256_permute2f128_ps(u1, u5, 0x31);
    row[6] = _mm256_permute2f128_ps(u2, u6, 0x31);
    row[7] = _mm256_permute2f128_ps(u3, u7, 0x31);
}

/// Lanes [first, first + 8) of `body` from eight states.
template <int N>
inline void gatherEight(const SolverBodyState* states, const int* slots, int first, BodyPack<N>& body) {
    static_assert(sizeof(SolverBodyState) == 16 * sizeof(float), "two 8-float rows per body");
    __m256 low[8], high[8];
    for (int i = 0; i < 8; ++i) {
        const float* state = reinterpret_cast<const float*>(&states[slots[first + i]]);
        low[i] = _mm256_load_ps(state);        // v.xyz w.xyz dp.xy
        high[i] = _mm256_load_ps(state + 8);   // dp.z dq.xyzw (3 unused)
    }
    transpose8(low);
    transpose8(high);
    Pack<N>* fields[13] = {&body.linearVelocity.x,  &body.linearVelocity.y,  &body.linearVelocity.z,
                           &body.angularVelocity.x, &body.angularVelocity.y, &body.angularVelocity.z,
                           &body.deltaPosition.x,   &body.deltaPosition.y,   &body.deltaPosition.z,
                           &body.deltaRotation.x,   &body.deltaRotation.y,   &body.deltaRotation.z,
                           &body.deltaRotation.w};
    for (int k = 0; k < 8; ++k) _mm256_store_ps(fields[k]->data() + first, low[k]);
    for (int k = 0; k < 5; ++k) _mm256_store_ps(fields[8 + k]->data() + first, high[k]);
}

template <int N>
inline void scatterEight(SolverBodyState* states, const int* slots, int first, const BodyPack<N>& body) {
    __m256 row[8] = {_mm256_load_ps(body.linearVelocity.x.data() + first),  _mm256_load_ps(body.linearVelocity.y.data() + first),
                     _mm256_load_ps(body.linearVelocity.z.data() + first),  _mm256_load_ps(body.angularVelocity.x.data() + first),
                     _mm256_load_ps(body.angularVelocity.y.data() + first), _mm256_load_ps(body.angularVelocity.z.data() + first),
                     _mm256_load_ps(body.deltaPosition.x.data() + first),   _mm256_load_ps(body.deltaPosition.y.data() + first)};
    transpose8(row);  // back to one row per lane; the delta position goes back as it was read
    for (int i = 0; i < 8; ++i)
        if (slots[first + i] != 0) _mm256_store_ps(reinterpret_cast<float*>(&states[slots[first + i]]), row[i]);
}

/// Every field of lanes [first, first + 8) back to their states (the integration's scatter).
template <int N>
inline void scatterAllEight(SolverBodyState* states, const int* slots, int first, const BodyPack<N>& body) {
    const __m256 zero = _mm256_setzero_ps();
    const auto lanes = [first](const Pack<N>& field) { return _mm256_load_ps(field.data() + first); };
    __m256 low[8] = {lanes(body.linearVelocity.x),  lanes(body.linearVelocity.y),  lanes(body.linearVelocity.z),
                     lanes(body.angularVelocity.x), lanes(body.angularVelocity.y), lanes(body.angularVelocity.z),
                     lanes(body.deltaPosition.x),   lanes(body.deltaPosition.y)};
    __m256 high[8] = {lanes(body.deltaPosition.z), lanes(body.deltaRotation.x), lanes(body.deltaRotation.y),
                      lanes(body.deltaRotation.z), lanes(body.deltaRotation.w), zero, zero, zero};
    transpose8(low);
    transpose8(high);
    for (int i = 0; i < 8; ++i) {
        if (slots[first + i] == 0) continue;
        float* state = reinterpret_cast<float*>(&states[slots[first + i]]);  // the 16 floats of one cache line
        _mm256_store_ps(state, low[i]);
        _mm256_store_ps(state + 8, high[i]);
    }
}

template <>
inline void scatterBodies<8>(SolverBodyState* states, const int* slots, const BodyPack<8>& body) {
    scatterAllEight(states, slots, 0, body);
}

template <>
inline BodyPack<8> gatherBodies<8>(const SolverBodyState* states, const int* slots) {
    BodyPack<8> body;
    gatherEight(states, slots, 0, body);
    return body;
}
template <>
inline void scatterVelocities<8>(SolverBodyState* states, const int* slots, const BodyPack<8>& body) {
    scatterEight(states, slots, 0, body);
}

#endif

}  // namespace STEPWISE_ISA
}  // namespace stepwise
