// The joints' three sweeps (warm start, biased pass, relax pass) and the errors' advance, a group
// of joints at a time, one joint per lane (packed_joint_rows.h). Built for the wide solve's
// instruction set (chapters/CMakeLists.txt). Every lane does chapter 8's arithmetic in the order
// the scalar rows did it, sums of three products as Eigen rounds them (ch11-eigen-order below), so
// the groups give the same numbers as a sweep joint after joint in the groups' order.
#include "11_wide_solve/packed_joint_rows.h"

#include "11_wide_solve/body_pack.h"
#include "11_wide_solve/lane_vec.h"

#include <type_traits>

namespace stepwise {

namespace {

constexpr int N = kWideLanes;
using Lanes = Pack<N>;
using namespace lane_vec;

/// One side's bodies' velocities in the view.
template <class T>
struct Bodies {
    Vec<T> linear, angular;
};

/// A group's bodies, all lanes (and, in the AVX2 float build, the two floats that share their row
/// of the state, carried back as they were read).
struct WideBodies {
    Bodies<Lanes> side;
    Lanes rest[2];
};

#if defined(__AVX2__) && !defined(STEPWISE_DOUBLE) && STEPWISE_WIDE_BYTES == 32
// Eight states' first rows (v, w, two floats of the delta position) loaded whole and transposed,
// as the contacts gather theirs (body_pack_avx2.h).
STEPWISE_LANE_INLINE WideBodies gatherAll(const SolverBodyState* states, const int* slots) {
    __m256 row[8];
    for (int i = 0; i < 8; ++i) row[i] = _mm256_load_ps(reinterpret_cast<const float*>(&states[slots[i]]));
    transpose8(row);
    WideBodies body;
    Lanes* fields[8] = {&body.side.linear.x,  &body.side.linear.y,  &body.side.linear.z, &body.side.angular.x,
                        &body.side.angular.y, &body.side.angular.z, &body.rest[0],  &body.rest[1]};
    for (int k = 0; k < 8; ++k) _mm256_store_ps(fields[k]->data(), row[k]);
    return body;
}

// Slot 0 is never written: its lanes pushed nothing, and several lanes may read it.
STEPWISE_LANE_INLINE void scatterAll(SolverBodyState* states, const int* slots, const WideBodies& body) {
    __m256 row[8] = {_mm256_load_ps(body.side.linear.x.data()),  _mm256_load_ps(body.side.linear.y.data()),
                     _mm256_load_ps(body.side.linear.z.data()),  _mm256_load_ps(body.side.angular.x.data()),
                     _mm256_load_ps(body.side.angular.y.data()), _mm256_load_ps(body.side.angular.z.data()),
                     _mm256_load_ps(body.rest[0].data()),   _mm256_load_ps(body.rest[1].data())};
    transpose8(row);
    for (int i = 0; i < 8; ++i)
        if (slots[i] != 0) _mm256_store_ps(reinterpret_cast<float*>(&states[slots[i]]), row[i]);
}
#else
STEPWISE_LANE_INLINE WideBodies gatherAll(const SolverBodyState* states, const int* slots) {
    WideBodies body;
    for (int i = 0; i < N; ++i) {
        const SolverBodyState& s = states[slots[i]];
        body.side.linear.x[i] = s.linearVelocity[0];
        body.side.linear.y[i] = s.linearVelocity[1];
        body.side.linear.z[i] = s.linearVelocity[2];
        body.side.angular.x[i] = s.angularVelocity[0];
        body.side.angular.y[i] = s.angularVelocity[1];
        body.side.angular.z[i] = s.angularVelocity[2];
    }
    return body;
}

// Slot 0 is never written: its lanes pushed nothing, and several lanes may read it.
STEPWISE_LANE_INLINE void scatterAll(SolverBodyState* states, const int* slots, const WideBodies& body) {
    for (int i = 0; i < N; ++i) {
        if (slots[i] == 0) continue;
        SolverBodyState& s = states[slots[i]];
        s.linearVelocity[0] = body.side.linear.x[i];
        s.linearVelocity[1] = body.side.linear.y[i];
        s.linearVelocity[2] = body.side.linear.z[i];
        s.angularVelocity[0] = body.side.angular.x[i];
        s.angularVelocity[1] = body.side.angular.y[i];
        s.angularVelocity[2] = body.side.angular.z[i];
    }
}
#endif

// [ch11-lane-view]
// The kernels below are written once, over a view of the group: all its lanes at once (AllLanes,
// SIMD), or one lane read as plain numbers (OneLane): a group of one joint (a chain's links each
// share a body with the next, so each group holds one) is swept as the scalar code would, without
// gathering eight lanes for one. The arithmetic is the same either way, so are the bits.
struct AllLanes {
    using Value = Lanes;
    STEPWISE_LANE_INLINE Value operator()(const Lanes& field) const { return field; }
    STEPWISE_LANE_INLINE void put(Lanes& field, const Value& value) const { field = value; }
};
struct OneLane {
    using Value = Real;
    int lane = 0;
    STEPWISE_LANE_INLINE Value operator()(const Lanes& field) const { return field[lane]; }
    STEPWISE_LANE_INLINE void put(Lanes& field, Value value) const { field[lane] = value; }
};
// [ch11-lane-view]

// Negation that flips the sign of zero too, as the scalar code's unary minus does (lanes.h's
// negated for packs).
STEPWISE_LANE_INLINE Real negated(Real a) { return -a; }
using stepwise::negated;
template <class T>
STEPWISE_LANE_INLINE Vec<T> negated(const Vec<T>& v) { return {negated(v.x), negated(v.y), negated(v.z)}; }

// Per lane: test > 0 ? a : b, and libstdc++'s min and max (the first when neither is less).
STEPWISE_LANE_INLINE Real pick(Real test, Real a, Real b) { return test > 0 ? a : b; }
STEPWISE_LANE_INLINE Lanes pick(const Lanes& test, const Lanes& a, const Lanes& b) { return selectPositive(test, a, b); }
STEPWISE_LANE_INLINE Real least(Real a, Real b) { return a < b ? a : b; }
STEPWISE_LANE_INLINE Lanes least(const Lanes& a, const Lanes& b) { return min(a, b); }
STEPWISE_LANE_INLINE Real most(Real a, Real b) { return a > b ? a : b; }
STEPWISE_LANE_INLINE Lanes most(const Lanes& a, const Lanes& b) { return max(a, b); }
template <class T>
STEPWISE_LANE_INLINE T constant(Real value) {
    if constexpr (std::is_same_v<T, Real>) return value; else return Lanes::splat(value);
}


template <class View>
STEPWISE_LANE_INLINE Vec<typename View::Value> load(const View& view, const PackVec3<N>& field) {
    return {view(field.x), view(field.y), view(field.z)};
}
template <class View>
STEPWISE_LANE_INLINE void put(const View& view, PackVec3<N>& field, const Vec<typename View::Value>& value) {
    view.put(field.x, value.x);
    view.put(field.y, value.y);
    view.put(field.z, value.z);
}
template <class View>
STEPWISE_LANE_INLINE void loadMatrix(const View& view, const Lanes (&field)[9], typename View::Value (&m)[9]) {
    for (int k = 0; k < 9; ++k) m[k] = view(field[k]);
}

// One body's velocities as plain numbers, and back (slot 0 never written).
Bodies<Real> gatherOne(const SolverBodyState* states, int slot) {
    const SolverBodyState& s = states[slot];
    return {{s.linearVelocity[0], s.linearVelocity[1], s.linearVelocity[2]},
            {s.angularVelocity[0], s.angularVelocity[1], s.angularVelocity[2]}};
}
void scatterOne(SolverBodyState* states, int slot, const Bodies<Real>& body) {
    if (slot == 0) return;
    SolverBodyState& s = states[slot];
    s.linearVelocity[0] = body.linear.x;
    s.linearVelocity[1] = body.linear.y;
    s.linearVelocity[2] = body.linear.z;
    s.angularVelocity[0] = body.angular.x;
    s.angularVelocity[1] = body.angular.y;
    s.angularVelocity[2] = body.angular.z;
}

// How fast the anchors part: B's anchor's velocity less A's (the point rows' J v).
template <class View, class T = typename View::Value>
STEPWISE_LANE_INLINE Vec<T> anchorsRate(const View& view, const JointBlockLanes& block, const Bodies<T>& a, const Bodies<T>& b) {
    return ((b.linear + cross(b.angular, load(view, block.armB))) - a.linear) - cross(a.angular, load(view, block.armA));
}

// The block's impulse change into both bodies.
template <class View, class T = typename View::Value>
STEPWISE_LANE_INLINE void pushBlock(const View& view, const JointBlockLanes& block, const Vec<T>& impulse, Bodies<T>& a,
                                    Bodies<T>& b) {
    T inertiaA[9], inertiaB[9];
    loadMatrix(view, block.inverseInertiaA, inertiaA);
    loadMatrix(view, block.inverseInertiaB, inertiaB);
    a.linear = a.linear + negated(view(block.inverseMassA)) * impulse;
    a.angular = a.angular + negated(times(inertiaA, cross(load(view, block.armA), impulse)));
    b.linear = b.linear + view(block.inverseMassB) * impulse;
    b.angular = b.angular + times(inertiaB, cross(load(view, block.armB), impulse));
}

// How fast the row's C changes: J v.
template <class View, class T = typename View::Value>
STEPWISE_LANE_INLINE T rowRate(const View& view, const JointRowLanes& row, const Bodies<T>& a, const Bodies<T>& b) {
    return ((dot3(load(view, row.linearA), a.linear) + dot3(load(view, row.angularA), a.angular)) +
            dot3(load(view, row.linearB), b.linear)) +
           dot3(load(view, row.angularB), b.angular);
}

template <class View, class T = typename View::Value>
STEPWISE_LANE_INLINE void pushRow(const View& view, const JointRowLanes& row, const T& applied, Bodies<T>& a, Bodies<T>& b) {
    a.linear = a.linear + applied * load(view, row.moveLinearA);
    a.angular = a.angular + applied * load(view, row.moveAngularA);
    b.linear = b.linear + applied * load(view, row.moveLinearB);
    b.angular = b.angular + applied * load(view, row.moveAngularB);
}

// [ch11-joint-lane-solve]
// The block's impulse: the anchors' relative velocity to the bias, softened (chapter 8's
// solveJointRows); the relax pass takes the bias and softness out of the rows fed back.
template <class View, class T = typename View::Value>
STEPWISE_LANE_INLINE void solveBlock(const View& view, JointBlockLanes& block, bool relax, Bodies<T>& a, Bodies<T>& b) {
    const Vec<T> relative = anchorsRate(view, block, a, b);
    Vec<T> bias = load(view, block.bias);
    T massScale = view(block.massScale), impulseScale = view(block.impulseScale);
    if (relax) {
        const T zero = constant<T>(0);
        bias = {pick(view(block.fedBack[0]), zero, bias.x), pick(view(block.fedBack[1]), zero, bias.y),
                pick(view(block.fedBack[2]), zero, bias.z)};
        massScale = pick(view(block.fedBack[0]), constant<T>(1), massScale);
        impulseScale = pick(view(block.fedBack[0]), zero, impulseScale);
    }
    // Eigen makes s (K^-1 v) as (K^-1 s) v: the scale goes into the matrix first.
    T scaledMass[9];
    for (int k = 0; k < 9; ++k) scaledMass[k] = view(block.mass[k]) * massScale;
    const Vec<T> accumulated = load(view, block.impulse);
    const Vec<T> impulse = times(scaledMass, bias - relative) - impulseScale * accumulated;
    put(view, block.impulse, accumulated + impulse);
    pushBlock(view, block, impulse, a, b);
}

template <class View, class T = typename View::Value>
STEPWISE_LANE_INLINE void solveRow(const View& view, JointRowLanes& row, bool relax, Bodies<T>& a, Bodies<T>& b) {
    const T velocity = rowRate(view, row, a, b);
    T bias = view(row.bias), massScale = view(row.massScale), impulseScale = view(row.impulseScale);
    if (relax) {  // no bias, rigid
        const T fedBack = view(row.fedBack);
        bias = pick(fedBack, constant<T>(0), bias);
        massScale = pick(fedBack, constant<T>(1), massScale);
        impulseScale = pick(fedBack, constant<T>(0), impulseScale);
    }
    const T previous = view(row.impulse);
    const T increment = massScale * view(row.effectiveMass) * (bias - velocity) - impulseScale * previous;
    // std::clamp as libstdc++ writes it: min(max(value, lower), upper).
    const T impulse = least(view(row.upper), most(view(row.lower), previous + increment));
    view.put(row.impulse, impulse);
    pushRow(view, row, impulse - previous, a, b);
}
// [ch11-joint-lane-solve]

// One group's sweep (solve), warm start parts and errors' advance, over a view.
template <class View, class T = typename View::Value>
void sweepGroup(const View& view, JointLaneGroup& group, bool relax, Bodies<T>& a, Bodies<T>& b) {
    if (group.blocks) solveBlock(view, group.block, relax, a, b);
    for (int k = 0; k < group.rowsInUse; ++k) solveRow(view, group.rows[static_cast<std::size_t>(k)], relax, a, b);
}

template <class View, class T = typename View::Value>
void warmBlock(const View& view, const JointLaneGroup& group, Bodies<T>& a, Bodies<T>& b) {
    pushBlock(view, group.block, load(view, group.block.impulse), a, b);
}

template <class View, class T = typename View::Value>
void warmRows(const View& view, const JointLaneGroup& group, Bodies<T>& a, Bodies<T>& b) {
    for (int k = 0; k < group.rowsInUse; ++k) {
        const JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
        pushRow(view, row, view(row.impulse), a, b);
    }
}

template <class View, class T = typename View::Value>
void advanceGroup(const View& view, JointLaneGroup& group, const Bodies<T>& a, const Bodies<T>& b, Real h) {
    const T step = constant<T>(h);
    if (group.blocks) {
        JointBlockLanes& block = group.block;
        const Vec<T> error = load(view, block.error);
        const Vec<T> moved = error + step * anchorsRate(view, block, a, b);
        const T present = view(block.present);
        put(view, block.error, {pick(present, moved.x, error.x), pick(present, moved.y, error.y), pick(present, moved.z, error.z)});
    }
    for (int k = 0; k < group.rowsInUse; ++k) {
        JointRowLanes& row = group.rows[static_cast<std::size_t>(k)];
        const T error = view(row.error);
        view.put(row.error, pick(view(row.advances), error + step * rowRate(view, row, a, b), error));
    }
}

// Runs `work(view, a, b)` on a group's bodies, gathered from `in` and scattered back into `out`
// (none: read only): a group of one joint as plain numbers, any other all lanes at once.
template <class Work>
STEPWISE_LANE_INLINE void onGroup(const SolverBodyState* in, SolverBodyState* out, const JointLaneGroup& group, Work&& work) {
    if (group.lanes == 1) {
        Bodies<Real> a = gatherOne(in, group.slotA[0]), b = gatherOne(in, group.slotB[0]);
        work(OneLane{0}, a, b);
        if (out) {
            scatterOne(out, group.slotA[0], a);
            scatterOne(out, group.slotB[0], b);
        }
        return;
    }
    WideBodies a = gatherAll(in, group.slotA), b = gatherAll(in, group.slotB);
    work(AllLanes{}, a.side, b.side);
    if (out) {
        scatterAll(out, group.slotA, a);
        scatterAll(out, group.slotB, b);
    }
}

}  // namespace

void warmStartPacked(const PackedJointRows& packed, SolverBodyState* states) {
    // A group at a time, its blocks and then its rows, as the sweeps take it: every body meets its
    // joints' impulses in the groups' order, with one gather and one scatter a group.
    for (int g = 0; g < packed.groupCount; ++g) {
        const JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        if (!group.blocks && group.rowsInUse == 0) continue;
        onGroup(states, states, group, [&](const auto& view, auto& a, auto& b) {
            if (group.blocks) warmBlock(view, group, a, b);
            warmRows(view, group, a, b);
        });
    }
}

void solvePacked(PackedJointRows& packed, SolverBodyState* states, bool relax) {
    for (int g = 0; g < packed.groupCount; ++g) {
        JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        onGroup(states, states, group, [&](const auto& view, auto& a, auto& b) { sweepGroup(view, group, relax, a, b); });
    }
}

// [ch11-advance-errors]
void advancePackedErrors(PackedJointRows& packed, const SolverBodyState* states, Real h) {
    for (int g = 0; g < packed.groupCount; ++g) {
        JointLaneGroup& group = packed.groups[static_cast<std::size_t>(g)];
        if (group.keepableLanes == 0) continue;  // rows built every substep: their errors are measured
        onGroup(states, nullptr, group, [&](const auto& view, auto& a, auto& b) { advanceGroup(view, group, a, b, h); });
    }
}
// [ch11-advance-errors]

}  // namespace stepwise
