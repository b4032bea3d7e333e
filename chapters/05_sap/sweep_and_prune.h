#pragma once
// Sweep and prune, the pieces one at a time: bounds that cover a frame's motion, the axis with
// the largest spread, the intervals' lower ends sorted along it (from scratch, or from last
// step's order by insertion sort), and the sweep. After Baraff's sort and sweep (Dynamic
// Simulation of Non-Penetrating Rigid Bodies, PhD thesis, Cornell, 1992), Cohen, Lin, Manocha
// and Ponamgi (I-COLLIDE, I3D 1995), who keep the sorted lists from step to step, Ericson
// (Real-Time Collision Detection, 2005, section 7.5), and Terdiman's box pruning (2002), which
// sorts the lower ends only and scans forward from each. The stage that strings the pieces
// together is in broadphase.cpp.

#include "world/world.h"

#include <vector>

namespace stepwise {

// [ch05-needs-contact]
/// A contact is worth finding only when one of the two bodies is dynamic: static and kinematic
/// bodies follow their own paths whatever touches them, so a pair of them has nothing to solve
/// (Box2D v3 and Jolt skip such pairs in their broadphase too).
inline bool needsContact(bool aDynamic, bool bDynamic) { return aDynamic || bDynamic; }
// [ch05-needs-contact]

/// Added to every body's bounds on each side, m: a guard against round-off in the bounds, so a
/// contact the narrowphase would find is never lost to the last bit of a box.
constexpr Real kBoundsMargin = Real(1e-3);

/// An upper bound on how fast any point of the body moves, m/s: |v| + |w| times the lever arm
/// about the centre of mass (maxLeverArm: the shape's radius about its origin plus the centre's
/// offset |c|). 0 for a static body.
Real pointSpeedBound(const World& world, int bodyIndex);

/// How far the bounds of a body are grown on each side, m: its fastest point's speed
/// (pointSpeedBound) times dt plus what gravity adds over the frame, plus kBoundsMargin; at least
/// the body's share of chapter 3's speculative margin over the frame. A pair that can touch during
/// the frame overlaps.
Real boundsGrowth(const World& world, int bodyIndex);

/// Every body's world box grown by boundsGrowth (computed here in one pass per body, with the
/// same bound on the speed). A body whose pose is not finite gets an empty
/// box (min > max) that overlaps nothing. `dynamic` gets 1 per dynamic body, 0 per other: the
/// sweep reads it from a small array rather than from the bodies, which are large.
void computeBroadphaseBounds(const World& world, std::vector<Aabb>& bounds, std::vector<char>& dynamic);

/// Variance of the bounds' centres along x, y and z, m^2 (computed in double: bodies far from
/// the origin would lose it to cancellation in float).
Vec3 centreVariance(const std::vector<Aabb>& bounds);

/// An axis must spread the centres this much more than the current one to take over: without
/// the hysteresis, a square layout (equal variance on x and z) would flip axes on round-off and
/// lose the incremental sort every step.
constexpr Real kAxisSwitchRatio = Real(1.2);

/// The axis with the largest variance (ties: the lower index), kept from `previousAxis` unless
/// another exceeds it by kAxisSwitchRatio. `previousAxis` -1: no previous axis.
int chooseSweepAxis(const Vec3& variance, int previousAxis);

/// The axes of a sweep: along `sweep`; then `first`, the other axis along which the centres
/// spread more, is tested on every interval the sweep meets, and `second` only on the few that
/// pass (on a ground, `second` is the vertical, along which nearly every pair overlaps).
struct SweepAxes {
    int sweep = 0, first = 1, second = 2;
};

/// The sweep along `sweepAxis` with the other two ordered by `variance`.
SweepAxes sweepAxes(const Vec3& variance, int sweepAxis);

/// The sort order of the lower ends: by value, then by body. A total order.
inline bool endpointBefore(const SweepEndpoint& a, const SweepEndpoint& b) {
    return a.value < b.value || (a.value == b.value && a.body < b.body);
}

/// One lower end per body, in body order, with its value on `axis` (unsorted).
void makeEndpoints(const std::vector<Aabb>& bounds, int axis, std::vector<SweepEndpoint>& endpoints);

/// Sets each end's value from the bounds, keeping the order of the list.
void refreshEndpointValues(const std::vector<Aabb>& bounds, int axis, std::vector<SweepEndpoint>& endpoints);

/// Insertion sort from the list's current order: near O(n) when little moved since the last
/// step. Gives up once it has moved ends `moveBudget` times (the list is then only partly
/// sorted) and returns -1; else returns the number of moves.
long insertionSortEndpoints(std::vector<SweepEndpoint>& endpoints, long moveBudget);

/// A full sort, O(n log n) whatever the starting order.
void fullSortEndpoints(std::vector<SweepEndpoint>& endpoints);

/// Walks the bodies in the order of their sorted lower ends: each interval meets, on the axis,
/// the intervals that start after its lower end and no later than its upper end. Those whose
/// boxes also overlap on the other two axes, and that need a contact, are pairs. Appends them
/// (bodyA < bodyB, in sweep order) and returns how many pairs the sweep looked at: the pairs
/// that overlap on the axis and need a contact. `columns` is working memory.
long sweepEndpoints(const std::vector<SweepEndpoint>& endpoints, const std::vector<Aabb>& bounds,
                    const std::vector<char>& dynamic, const SweepAxes& axes, std::vector<BodyPair>& pairs,
                    SweepColumns& columns);

/// The same along `axis`, the other two in index order, with working memory of its own.
long sweepEndpoints(const std::vector<SweepEndpoint>& endpoints, const std::vector<Aabb>& bounds,
                    const std::vector<char>& dynamic, int axis, std::vector<BodyPair>& pairs);

/// Every pair whose boxes overlap and that needs a contact, tested one by one: O(n^2), in
/// canonical order. The reference sweep and prune must agree with.
void bruteForcePairs(const std::vector<Aabb>& bounds, const std::vector<char>& dynamic, std::vector<BodyPair>& pairs);

/// Sorts pairs into canonical order (by bodyA, then bodyB) in O(n + k): a counting sort by
/// bodyB, then a stable one by bodyA. `buffers` is working memory.
void sortPairsCanonical(std::vector<BodyPair>& pairs, int bodyCount, BroadphaseBuffers& buffers);

/// The same, with working memory of its own.
void sortPairsCanonical(std::vector<BodyPair>& pairs, int bodyCount);

}  // namespace stepwise
