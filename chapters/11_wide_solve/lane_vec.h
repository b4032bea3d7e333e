#pragma once
// Three-vectors of lanes (or of plain numbers, one lane's view) and the sums chapter 8's Eigen
// arithmetic makes, in the order Eigen rounds them: what lets a lane kernel give a scalar rule's
// bits (packed_joint_sweep.cpp, joint_lane_feedback.cpp).

#include "11_wide_solve/lanes.h"

namespace stepwise::lane_vec {

template <class T>
struct Vec {
    T x, y, z;
};
template <class T>
STEPWISE_LANE_INLINE Vec<T> operator+(const Vec<T>& a, const Vec<T>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T>
STEPWISE_LANE_INLINE Vec<T> operator-(const Vec<T>& a, const Vec<T>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T>
STEPWISE_LANE_INLINE Vec<T> operator*(const T& s, const Vec<T>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <class T>
STEPWISE_LANE_INLINE Vec<T> cross(const Vec<T>& a, const Vec<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// [ch11-eigen-order]
// How Eigen rounds a 3-vector dot product and a 3x3 matrix times a vector, which the scalar sweep
// used: with floats (four to an SSE register, so three do not fill one) every sum goes
// x0 + (x1 + x2); with doubles (two to a register) the dot product and the matrix's first two rows
// go (x0 + x1) + x2, its last row x0 + (x1 + x2). tests/ch11/joint_lanes_test.cpp holds the lanes
// to the scalar sweep's bits.
#if defined(STEPWISE_DOUBLE)
template <class T>
STEPWISE_LANE_INLINE T dot3(const Vec<T>& a, const Vec<T>& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
template <class T>
STEPWISE_LANE_INLINE Vec<T> times(const T (&m)[9], const Vec<T>& v) {
    return {(m[0] * v.x + m[1] * v.y) + m[2] * v.z, (m[3] * v.x + m[4] * v.y) + m[5] * v.z,
            m[6] * v.x + (m[7] * v.y + m[8] * v.z)};
}
#else
template <class T>
STEPWISE_LANE_INLINE T dot3(const Vec<T>& a, const Vec<T>& b) { return a.x * b.x + (a.y * b.y + a.z * b.z); }
template <class T>
STEPWISE_LANE_INLINE Vec<T> times(const T (&m)[9], const Vec<T>& v) {
    return {m[0] * v.x + (m[1] * v.y + m[2] * v.z), m[3] * v.x + (m[4] * v.y + m[5] * v.z),
            m[6] * v.x + (m[7] * v.y + m[8] * v.z)};
}
#endif
// [ch11-eigen-order]

}  // namespace stepwise::lane_vec
