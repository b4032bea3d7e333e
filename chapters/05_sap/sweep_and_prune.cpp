// Sweep and prune, piece by piece (sweep_and_prune.h); broadphase.cpp strings the pieces into
// the stage.
#include "05_sap/sweep_and_prune.h"

#include "03_epa/chapter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace stepwise {

// [ch05-bounds]
Real boundsGrowth(const World& world, int bodyIndex) {
    // Chapter 3's speculative margin of a body with itself, over every substep of the frame, is
    // twice this body's share: speed bound times the frame, plus gravity's gain.
    const int wholeFrame = std::max(1, world.settings.substeps);
    return speculativeMargin(world, bodyIndex, bodyIndex, wholeFrame) / 2 + kBoundsMargin;
}
// [ch05-bounds]

namespace {

/// A placed shape's world box, and the radius of the smallest ball about the body's origin that
/// holds the shape (chapter 2's shapeScale), in one pass over the shape: one rotation matrix,
/// each hull vertex turned once.
struct PlacedShape {
    Aabb box;
    Real radius = 0;
};

PlacedShape placeShape(const Shape& shape, const Transform& pose) {
    PlacedShape placed;
    if (shape.type == ShapeType::Sphere) {  // turning changes nothing
        placed.box.min = pose.position - Vec3::Constant(shape.radius);
        placed.box.max = pose.position + Vec3::Constant(shape.radius);
        placed.radius = shape.radius;
        return placed;
    }
    const Mat3 rotation = pose.rotation.toRotationMatrix();
    Vec3 reach = Vec3::Zero();
    switch (shape.type) {
        case ShapeType::Box:
            reach = rotation.cwiseAbs() * shape.halfExtents;
            placed.radius = shape.halfExtents.norm();
            break;
        case ShapeType::Sphere: break;  // above
        case ShapeType::Capsule:
            reach = rotation.col(1).cwiseAbs() * shape.halfHeight + Vec3::Constant(shape.radius);
            placed.radius = shape.halfHeight + shape.radius;
            break;
        case ShapeType::Convex: {
            if (!shape.hull) break;
            Real radiusSquared = 0;
            for (const Vec3& vertex : shape.hull->vertices) {
                placed.box.grow(pose.position + rotation * vertex);
                radiusSquared = std::max(radiusSquared, vertex.squaredNorm());
            }
            placed.radius = std::sqrt(radiusSquared);
            return placed;
        }
    }
    placed.box.min = pose.position - reach;
    placed.box.max = pose.position + reach;
    return placed;
}

}  // namespace

// [ch05-bounds-pass]
void computeBroadphaseBounds(const World& world, std::vector<Aabb>& bounds, std::vector<char>& dynamic) {
    bounds.resize(world.bodies.size());
    dynamic.resize(world.bodies.size());
    // boundsGrowth, with the shape's radius from the same pass as its box.
    const Real dt = world.settings.dt;
    const Real gravityGain = world.settings.gravity.norm() * dt;
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        dynamic[i] = body.type == BodyType::Dynamic ? 1 : 0;
        const PlacedShape placed = placeShape(body.shape, body.transform);
        Real speed = 0;  // bound on the speed of the body's points, m/s
        if (const Motion* motion = world.motionOf(static_cast<int>(i)))
            speed = motion->linearVelocity.norm() +
                    motion->angularVelocity.norm() * std::max(placed.radius, std::numeric_limits<Real>::min());
        const Real grow = dt * (speed + gravityGain) + kBoundsMargin;
        Aabb box = placed.box;
        box.min.array() -= grow;
        box.max.array() += grow;
        // A NaN would break the sort's order; an empty box overlaps nothing and sorts last.
        if (!box.min.allFinite() || !box.max.allFinite()) box = Aabb{};
        bounds[i] = box;
    }
}
// [ch05-bounds-pass]

// [ch05-axis]
Vec3 centreVariance(const std::vector<Aabb>& bounds) {
    double mean[3] = {0, 0, 0};
    long count = 0;
    for (const Aabb& box : bounds) {
        if ((box.min.array() > box.max.array()).any()) continue;  // empty: no place to count
        const Vec3 centre = box.center();
        for (int axis = 0; axis < 3; ++axis) mean[axis] += static_cast<double>(centre[axis]);
        ++count;
    }
    if (count == 0) return Vec3::Zero();
    for (double& m : mean) m /= static_cast<double>(count);
    // Two passes: the squares of deviations, not the difference of large squares.
    double spread[3] = {0, 0, 0};
    for (const Aabb& box : bounds) {
        if ((box.min.array() > box.max.array()).any()) continue;
        const Vec3 centre = box.center();
        for (int axis = 0; axis < 3; ++axis) {
            const double deviation = static_cast<double>(centre[axis]) - mean[axis];
            spread[axis] += deviation * deviation;
        }
    }
    const double n = static_cast<double>(count);
    return Vec3(static_cast<Real>(spread[0] / n), static_cast<Real>(spread[1] / n), static_cast<Real>(spread[2] / n));
}

int chooseSweepAxis(const Vec3& variance, int previousAxis) {
    int widest = 0;
    for (int axis = 1; axis < 3; ++axis)
        if (variance[axis] > variance[widest]) widest = axis;
    if (previousAxis < 0 || previousAxis > 2) return widest;
    return variance[widest] > kAxisSwitchRatio * variance[previousAxis] ? widest : previousAxis;
}
// [ch05-axis]

void makeEndpoints(const std::vector<Aabb>& bounds, int axis, std::vector<SweepEndpoint>& endpoints) {
    endpoints.resize(2 * bounds.size());
    for (std::size_t i = 0; i < bounds.size(); ++i) {
        endpoints[2 * i] = SweepEndpoint{bounds[i].min[axis], static_cast<int>(i), false};
        endpoints[2 * i + 1] = SweepEndpoint{bounds[i].max[axis], static_cast<int>(i), true};
    }
}

void refreshEndpointValues(const std::vector<Aabb>& bounds, int axis, std::vector<SweepEndpoint>& endpoints) {
    for (SweepEndpoint& end : endpoints) {
        const Aabb& box = bounds[static_cast<std::size_t>(end.body)];
        end.value = end.isUpper ? box.max[axis] : box.min[axis];
    }
}

// [ch05-insertion-sort]
long insertionSortEndpoints(std::vector<SweepEndpoint>& endpoints, long moveBudget) {
    long moves = 0;
    for (std::size_t i = 1; i < endpoints.size(); ++i) {
        const SweepEndpoint end = endpoints[i];
        std::size_t j = i;
        // Bodies that moved little since the last step are already in place: one comparison.
        while (j > 0 && endpointBefore(end, endpoints[j - 1])) {
            endpoints[j] = endpoints[j - 1];
            --j;
        }
        endpoints[j] = end;
        moves += static_cast<long>(i - j);
        if (moves > moveBudget) return -1;  // too much moved: a full sort is cheaper from here
    }
    return moves;
}
// [ch05-insertion-sort]

void fullSortEndpoints(std::vector<SweepEndpoint>& endpoints) {
    std::sort(endpoints.begin(), endpoints.end(), endpointBefore);
}

namespace {

/// An active list of the sweep: intervals open at this point of the sweep, with their boxes on
/// the two other axes. Each opening interval scans the whole list, so the list keeps what that
/// scan reads in four plain arrays, one per bound, read straight through: the compiler tests
/// several entries per instruction (SIMD), where looking each body's box up in the large bounds
/// array would wait on memory for every entry.
struct ActiveList {
    std::vector<Real> lowA, highA, lowB, highB;  // the boxes on the first and second other axis
    std::vector<int> body;

    std::size_t size() const { return body.size(); }
    void reserve(std::size_t capacity) {
        for (std::vector<Real>* bound : {&lowA, &highA, &lowB, &highB}) bound->reserve(capacity);
        body.reserve(capacity);
    }
    void add(Real boxLowA, Real boxHighA, Real boxLowB, Real boxHighB, int bodyIndex) {
        lowA.push_back(boxLowA), highA.push_back(boxHighA), lowB.push_back(boxLowB), highB.push_back(boxHighB);
        body.push_back(bodyIndex);
    }
    /// Removes entry `at`: the last entry takes its place. Returns the body that moved, or -1.
    int removeAt(std::size_t at) {
        const std::size_t last = size() - 1;
        lowA[at] = lowA[last], highA[at] = highA[last], lowB[at] = lowB[last], highB[at] = highB[last];
        body[at] = body[last];
        lowA.pop_back(), highA.pop_back(), lowB.pop_back(), highB.pop_back(), body.pop_back();
        return at < last ? body[at] : -1;
    }
};

/// Calls hit(j) for every entry j of the list whose box overlaps [lowA, highA] x [lowB, highB].
/// Few entries do, so blocks of 16 are tested first with one branch-free loop the compiler turns
/// into SIMD instructions, and only a block with an overlap is looked at entry by entry.
template <class Hit>
void scanActiveList(const ActiveList& active, Real lowA, Real highA, Real lowB, Real highB, Hit hit) {
    const Real* lowsA = active.lowA.data();
    const Real* highsA = active.highA.data();
    const Real* lowsB = active.lowB.data();
    const Real* highsB = active.highB.data();
    constexpr std::size_t kBlock = 16;
    for (std::size_t first = 0; first < active.size(); first += kBlock) {
        const std::size_t last = std::min(first + kBlock, active.size());
        const auto overlaps = [&](std::size_t j) {
            return (lowsA[j] <= highA) & (lowA <= highsA[j]) & (lowsB[j] <= highB) & (lowB <= highsB[j]);
        };
        int any = 0;
        for (std::size_t j = first; j < last; ++j) any |= overlaps(j);
        if (!any) continue;
        for (std::size_t j = first; j < last; ++j)
            if (overlaps(j)) hit(active.body[j]);
    }
}

}  // namespace

// [ch05-sweep]
long sweepEndpoints(const std::vector<SweepEndpoint>& endpoints, const std::vector<Aabb>& bounds,
                    const std::vector<char>& dynamicBodies, int axis, std::vector<BodyPair>& pairs) {
    const int axisA = (axis + 1) % 3, axisB = (axis + 2) % 3;
    // Two active lists: a pair needs a dynamic body (needsContact), so an opening static or
    // kinematic interval only scans the dynamic list, and a large static ground, open over the
    // whole sweep, sits in a short list of its own.
    ActiveList dynamicList, otherList;
    dynamicList.reserve(256);
    otherList.reserve(16);
    std::vector<int> slot(bounds.size(), -1);  // where each body sits in its list, -1 when closed
    long scanned = 0;
    for (const SweepEndpoint& end : endpoints) {
        const std::size_t body = static_cast<std::size_t>(end.body);
        const bool dynamic = dynamicBodies[body] != 0;
        ActiveList& ownList = dynamic ? dynamicList : otherList;
        if (end.isUpper) {
            // The interval closes: the last entry of its list takes its place, O(1).
            const int at = slot[body];
            if (at < 0) continue;
            const int moved = ownList.removeAt(static_cast<std::size_t>(at));
            if (moved >= 0) slot[static_cast<std::size_t>(moved)] = at;
            slot[body] = -1;
            continue;
        }
        const Aabb& box = bounds[body];
        if (box.min[axis] > box.max[axis]) continue;  // an empty box (non-finite body) opens nothing
        const Real lowA = box.min[axisA], highA = box.max[axisA], lowB = box.min[axisB], highB = box.max[axisB];
        // The interval opens: on this axis it overlaps every interval still open. Those whose
        // boxes overlap on the other two axes as well are candidate pairs.
        const auto addPair = [&](int other) {
            pairs.push_back(BodyPair{std::min(end.body, other), std::max(end.body, other)});
        };
        scanned += static_cast<long>(dynamicList.size());
        scanActiveList(dynamicList, lowA, highA, lowB, highB, addPair);
        if (dynamic) {
            scanned += static_cast<long>(otherList.size());
            scanActiveList(otherList, lowA, highA, lowB, highB, addPair);
        }
        slot[body] = static_cast<int>(ownList.size());
        ownList.add(lowA, highA, lowB, highB, end.body);
    }
    return scanned;
}
// [ch05-sweep]

void bruteForcePairs(const std::vector<Aabb>& bounds, const std::vector<char>& dynamic, std::vector<BodyPair>& pairs) {
    const int bodyCount = static_cast<int>(bounds.size());
    for (int i = 0; i < bodyCount; ++i) {
        const Aabb& box = bounds[static_cast<std::size_t>(i)];
        const bool iDynamic = dynamic[static_cast<std::size_t>(i)] != 0;
        for (int j = i + 1; j < bodyCount; ++j) {
            if (box.overlaps(bounds[static_cast<std::size_t>(j)]) && needsContact(iDynamic, dynamic[static_cast<std::size_t>(j)] != 0))
                pairs.push_back(BodyPair{i, j});
        }
    }
}

void sortPairsCanonical(std::vector<BodyPair>& pairs, int bodyCount) {
    if (std::is_sorted(pairs.begin(), pairs.end())) return;
    if (pairs.size() < 1024) {
        std::sort(pairs.begin(), pairs.end());
        return;
    }
    // Least significant digit radix sort of the key bodyA * n + bodyB, 11 bits a pass: a few
    // passes over the list in order, where a comparison sort would jump around it k log k times.
    const std::uint64_t n = static_cast<std::uint64_t>(std::max(bodyCount, 1));
    std::vector<std::uint64_t> keys(pairs.size()), sorted(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i)
        keys[i] = static_cast<std::uint64_t>(pairs[i].bodyA) * n + static_cast<std::uint64_t>(pairs[i].bodyB);
    const std::uint64_t largest = n * n;
    constexpr int kDigitBits = 11;
    constexpr std::size_t kBuckets = std::size_t(1) << kDigitBits;
    for (int shift = 0; shift < 64 && (largest >> shift) > 0; shift += kDigitBits) {
        std::size_t start[kBuckets + 1] = {};
        for (const std::uint64_t key : keys) ++start[((key >> shift) & (kBuckets - 1)) + 1];
        for (std::size_t bucket = 1; bucket <= kBuckets; ++bucket) start[bucket] += start[bucket - 1];
        for (const std::uint64_t key : keys) sorted[start[(key >> shift) & (kBuckets - 1)]++] = key;
        keys.swap(sorted);
    }
    for (std::size_t i = 0; i < pairs.size(); ++i)
        pairs[i] = BodyPair{static_cast<int>(keys[i] / n), static_cast<int>(keys[i] % n)};
}

}  // namespace stepwise
