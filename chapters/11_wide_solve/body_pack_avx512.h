#pragma once
// The AVX-512 build's sixteen lanes: two rows of eight each way, through the AVX2 transposes
// (body_pack_avx2.h). Included at the end of body_pack.h.

#include "11_wide_solve/body_pack_avx2.h"

namespace stepwise {
inline namespace STEPWISE_ISA {

#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE)
template <>
inline BodyPack<16> gatherBodies<16>(const SolverBodyState* states, const int* slots) {
    BodyPack<16> body;
    gatherEight(states, slots, 0, body);
    gatherEight(states, slots, 8, body);
    return body;
}
template <>
inline void scatterVelocities<16>(SolverBodyState* states, const int* slots, const BodyPack<16>& body) {
    scatterEight(states, slots, 0, body);
    scatterEight(states, slots, 8, body);
}
template <>
inline void scatterBodies<16>(SolverBodyState* states, const int* slots, const BodyPack<16>& body) {
    scatterAllEight(states, slots, 0, body);
    scatterAllEight(states, slots, 8, body);
}
#endif

}  // namespace STEPWISE_ISA
}  // namespace stepwise
