// Reduction of a manifold to four points.
#include "06_manifolds/reduction.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

// [ch06-reduction-hysteresis]
/// A candidate replaces the best so far only when it beats it clearly: scores within 5% (Box3D's
/// 0.95 factor) or within round-off of the deepest depth keep the earlier point. Candidates come in
/// the incident face's order, which a small motion does not change, so the same corners stay
/// chosen step after step and keep their warm-start impulses.
constexpr Real kScoreHysteresis = Real(0.95);
constexpr Real kDepthTolerance = Real(1e-4);  // m: corners of a face resting flat are equally deep

bool clearlyBetter(Real score, Real best) { return kScoreHysteresis * score > best; }
// [ch06-reduction-hysteresis]

/// Twice the signed area of triangle (a, b, c) seen along the normal.
Real signedArea(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal) {
    return (b - a).cross(c - a).dot(normal);
}

}  // namespace

// [ch06-reduce]
namespace {

/// The points on A are used for the geometry: they lie in one plane (the reference face or the
/// incident face projected on it), so areas are measured in that plane.
struct Candidates {
    const std::vector<ManifoldPoint>& points;
    const Vec3& normal;
    const int* chosen;

    int count() const { return static_cast<int>(points.size()); }
    const Vec3& at(int i) const { return points[static_cast<std::size_t>(i)].pointA; }
    Real depth(int i) const { return points[static_cast<std::size_t>(i)].depth; }
    Vec3 planar(const Vec3& v) const { return v - normal.dot(v) * normal; }
    bool isChosen(int i, int used) const {
        for (int k = 0; k < used; ++k)
            if (chosen[k] == i) return true;
        return false;
    }
    // Rules 2 to 4 look at the touching points first and at the speculative ones (above the
    // reference face) only when the touching ones leave the rule without an answer. A body lying
    // on an edge touches at the edge's two ends; a speculative corner farther away, kept in place
    // of one end, leaves the body on one point and a gap, and it rocks over the edge for ever.
    bool touching(int i) const { return depth(i) >= -kDepthTolerance; }

    /// The candidate not among the first `used` chosen with the best score, replacing the best so
    /// far only when clearly better; from the touching points first, from all when no touching one
    /// scores above `floor`. -1 when none does.
    template <typename Score>
    int pick(int used, const Score& score, Real floor, Real& best) const {
        for (const bool touchingOnly : {true, false}) {
            int picked = -1;
            best = 0;
            for (int i = 0; i < count(); ++i) {
                if (isChosen(i, used) || (touchingOnly && !touching(i))) continue;
                const Real value = score(i);
                if (picked < 0 ? value > 0 : clearlyBetter(value, best)) {
                    picked = i;
                    best = value;
                }
            }
            if (picked >= 0 && best > floor) return picked;
        }
        return -1;
    }
};

/// 1. The deepest point: it carries the most load and must never be dropped. When several are
/// equally deep (a face resting flat), the one farthest from the patch's centre: a corner of the
/// patch. Clipping two nearly coincident faces leaves points part way along the patch's edges (an
/// edge lying within round-off of a side plane crosses it anywhere); the first of the tied points
/// may be one of them, and taken as a manifold corner it would leave the real corner out and carry
/// its load part way along an edge.
int deepestCorner(const Candidates& set) {
    Real deepestDepth = set.depth(0);
    Vec3 centre = Vec3::Zero();
    for (int i = 0; i < set.count(); ++i) {
        deepestDepth = std::max(deepestDepth, set.depth(i));
        centre += set.at(i);
    }
    centre /= static_cast<Real>(set.count());
    int deepest = -1;
    Real deepestReach = 0;
    for (int i = 0; i < set.count(); ++i) {
        if (!(set.depth(i) >= deepestDepth - kDepthTolerance)) continue;
        const Real reach = set.planar(set.at(i) - centre).squaredNorm();
        if (deepest < 0 || clearlyBetter(reach, deepestReach)) {
            deepest = i;
            deepestReach = reach;
        }
    }
    return deepest < 0 ? 0 : deepest;  // NaN depths: any point
}

}  // namespace

int reduceManifold(const std::vector<ManifoldPoint>& points, const Vec3& normal, int chosen[kMaxManifoldPoints]) {
    const int count = static_cast<int>(points.size());
    if (count <= 0) return 0;
    const Candidates set{points, normal, chosen};
    const auto at = [&](int i) -> const Vec3& { return set.at(i); };
    const int deepest = deepestCorner(set);
    chosen[0] = deepest;
    if (count == 1) return 1;

    // 2. The point farthest from it in the contact plane: the longest lever against tipping.
    // Every point at the same place: one point says it all.
    Real scale = 0;
    const int farthest =
        set.pick(1, [&](int i) { return set.planar(at(i) - at(deepest)).squaredNorm(); }, kEpsilon * kEpsilon, scale);
    if (farthest < 0) return 1;
    chosen[1] = farthest;
    if (count == 2) return 2;

    // 3. The point making the largest triangle with the first two, on either side.
    // Collinear points: the segment's two ends are the manifold.
    Real bestArea = 0;
    const int third = set.pick(2, [&](int i) { return std::abs(signedArea(at(deepest), at(farthest), at(i), normal)); },
                               Real(1e-6) * scale, bestArea);
    if (third < 0) return 2;
    chosen[2] = third;
    if (count == 3) return 3;

    // 4. The point adding the most area to the triangle: it lies beyond one of its edges.
    // Orient the triangle counter-clockwise about the normal first.
    int a = deepest, b = farthest, c = third;
    if (signedArea(at(deepest), at(farthest), at(third), normal) < 0) std::swap(a, b);
    const auto added = [&](int i) {
        return std::max(Real(0), -signedArea(at(a), at(b), at(i), normal)) +
               std::max(Real(0), -signedArea(at(b), at(c), at(i), normal)) +
               std::max(Real(0), -signedArea(at(c), at(a), at(i), normal));
    };
    Real bestAdded = 0;
    const int fourth = set.pick(3, added, Real(1e-6) * bestArea, bestAdded);
    if (fourth < 0) return 3;
    chosen[3] = fourth;
    return 4;
}
// [ch06-reduce]

}  // namespace stepwise
