// The sweep of sweep and prune (sweep_and_prune.h) over the sorted lower ends, in columns the
// compiler reads as SIMD blocks; brute force, the reference it must agree with; and the pairs' sort
// into canonical order.
#include "05_sap/sweep_and_prune.h"

#include <algorithm>
#include <limits>

namespace stepwise {

namespace {

/// The sweep reads the columns in blocks of this many entries (see scanForward). On a layer a
/// body meets a few dozen intervals: smaller blocks pay more for the loop around them, larger
/// ones test more entries past the interval's end.
constexpr std::size_t kBlock = 16;

/// Resizes every column to `size` entries.
void resizeColumns(SweepColumns& columns, std::size_t size) {
    for (std::vector<Real>* bound : {&columns.low, &columns.high, &columns.lowA, &columns.highA, &columns.lowB, &columns.highB})
        bound->resize(size);
    columns.body.resize(size);
    columns.dynamic.resize(size);
}

/// Copies the boxes into the columns in the order of the sorted lower ends, skipping empty
/// boxes (a non-finite body), then kBlock sentinels: boxes that start at +infinity and overlap
/// nothing.
void layOutColumns(const std::vector<SweepEndpoint>& endpoints, const std::vector<Aabb>& bounds,
                   const std::vector<char>& dynamic, const SweepAxes& axes, SweepColumns& columns) {
    resizeColumns(columns, endpoints.size() + kBlock);
    std::size_t count = 0;
    for (const SweepEndpoint& end : endpoints) {
        const std::size_t body = static_cast<std::size_t>(end.body);
        const Aabb& box = bounds[body];
        if (box.min[axes.sweep] > box.max[axes.sweep]) continue;  // an empty box overlaps nothing
        columns.low[count] = box.min[axes.sweep], columns.high[count] = box.max[axes.sweep];
        columns.lowA[count] = box.min[axes.first], columns.highA[count] = box.max[axes.first];
        columns.lowB[count] = box.min[axes.second], columns.highB[count] = box.max[axes.second];
        columns.body[count] = end.body;
        columns.dynamic[count] = dynamic[body];
        ++count;
    }
    constexpr Real kInfinity = std::numeric_limits<Real>::infinity();
    for (std::size_t i = count; i < count + kBlock; ++i) {
        columns.low[i] = columns.lowA[i] = columns.lowB[i] = kInfinity;
        columns.high[i] = columns.highA[i] = columns.highB[i] = -kInfinity;
        columns.body[i] = -1;
        columns.dynamic[i] = 0;
    }
    columns.count = count;
}

/// What the scan reads of the columns, as plain pointers taken once per sweep: the compiler
/// then keeps them in registers, where it would reload them from the vectors after every pair
/// written.
struct ColumnView {
    const Real *low, *high, *lowA, *highA, *lowB, *highB;
};

/// Entry i's box, as the scan compares the others with it.
struct Interval {
    Real high, lowA, highA, lowB, highB;
};

Interval intervalAt(const ColumnView& columns, std::size_t i) {
    return Interval{columns.high[i], columns.lowA[i], columns.highA[i], columns.lowB[i], columns.highB[i]};
}

/// Whether entry j, which starts after the interval on the sweep axis, overlaps its box: five
/// comparisons joined with & rather than &&, so they compile without branches.
inline int overlaps(const ColumnView& columns, std::size_t j, const Interval& box) {
    return (columns.low[j] <= box.high) & (columns.lowA[j] <= box.highA) & (box.lowA <= columns.highA[j]) &
           (columns.lowB[j] <= box.highB) & (box.lowB <= columns.highB[j]);
}

/// A block of kBlock entries tested against one interval: how many meet it on the sweep axis,
/// and how many of those overlap it on the first other axis too.
struct BlockTest {
    int onAxis = 0;
    int passed = 0;
};

/// One branch-free loop over contiguous columns, which the compiler turns into SIMD
/// instructions (a few for the whole block).
inline BlockTest testBlock(const ColumnView& columns, std::size_t first, const Interval& box) {
    BlockTest test;
    for (std::size_t j = first; j < first + kBlock; ++j) {
        const int meets = columns.low[j] <= box.high;
        test.onAxis += meets;
        test.passed += meets & (columns.lowA[j] <= box.highA) & (box.lowA <= columns.highA[j]);
    }
    return test;
}

/// How many entries of a block overlap the interval's box: the same kind of loop, all five
/// comparisons.
inline int countOverlaps(const ColumnView& columns, std::size_t first, const Interval& box) {
    int hits = 0;
    for (std::size_t j = first; j < first + kBlock; ++j) hits += overlaps(columns, j, box);
    return hits;
}

/// Calls hit(j) for every entry j after the interval's entry i whose box overlaps its box (or
/// hitBlock(first) for a whole block of them starting at entry `first`), and
/// returns how many entries after i meet it on the sweep axis. The lower ends are sorted, so
/// those are the entries from i + 1 up to the first that starts past the interval's upper end:
/// the scan stops at the first block that holds one. A block is tested first on the sweep axis
/// and the first other axis only, which on a spread layer rejects nearly every block; a block
/// that passes is tested on all three (in a pile, many do), and only a block with a hit is
/// looked at entry by entry.
template <class Hit, class HitBlock>
std::size_t scanForward(const ColumnView& columns, std::size_t i, const Interval& box, Hit hit, HitBlock hitBlock) {
    std::size_t met = 0;
    for (std::size_t first = i + 1;; first += kBlock) {
        const BlockTest block = testBlock(columns, first, box);
        const int hits = block.passed > 0 ? countOverlaps(columns, first, box) : 0;
        if (hits == static_cast<int>(kBlock)) {  // a large box (a ground) meets whole blocks
            hitBlock(first);
        } else if (hits > 0) {
            for (std::size_t j = first; j < first + kBlock; ++j)
                if (overlaps(columns, j, box)) hit(j);
        }
        met += static_cast<std::size_t>(block.onAxis);
        if (block.onAxis < static_cast<int>(kBlock)) return met;  // the rest start past the interval
    }
}

}  // namespace

// [ch05-sweep]
long sweepEndpoints(const std::vector<SweepEndpoint>& endpoints, const std::vector<Aabb>& bounds,
                    const std::vector<char>& dynamicBodies, const SweepAxes& axes, std::vector<BodyPair>& pairs,
                    SweepColumns& columns) {
    layOutColumns(endpoints, bounds, dynamicBodies, axes, columns);
    const ColumnView view{columns.low.data(),  columns.high.data(), columns.lowA.data(),
                          columns.highA.data(), columns.lowB.data(), columns.highB.data()};
    long looked = 0;
    for (std::size_t i = 0; i < columns.count; ++i) {
        const int body = columns.body[i];
        const bool dynamic = columns.dynamic[i] != 0;
        const auto addPair = [&](std::size_t j) {
            if (!needsContact(dynamic, columns.dynamic[j] != 0)) return;
            const int other = columns.body[j];
            pairs.push_back(BodyPair{std::min(body, other), std::max(body, other)});
        };
        // A whole block overlaps (the ground meets every body above it): its pairs are written
        // without a branch each, and those that need no contact are written over.
        const auto addBlock = [&](std::size_t first) {
            const std::size_t size = pairs.size();
            pairs.resize(size + kBlock);
            BodyPair* out = pairs.data() + size;
            for (std::size_t j = first; j < first + kBlock; ++j) {
                const int other = columns.body[j];
                *out = BodyPair{std::min(body, other), std::max(body, other)};
                out += needsContact(dynamic, columns.dynamic[j] != 0) ? 1 : 0;
            }
            pairs.resize(static_cast<std::size_t>(out - pairs.data()));
        };
        const std::size_t met = scanForward(view, i, intervalAt(view, i), addPair, addBlock);
        if (dynamic) {
            looked += static_cast<long>(met);
        } else {  // only the dynamic ones need a contact with this body
            for (std::size_t j = i + 1; j <= i + met; ++j) looked += columns.dynamic[j];
        }
    }
    return looked;
}
// [ch05-sweep]

long sweepEndpoints(const std::vector<SweepEndpoint>& endpoints, const std::vector<Aabb>& bounds,
                    const std::vector<char>& dynamic, int axis, std::vector<BodyPair>& pairs) {
    SweepColumns columns;
    return sweepEndpoints(endpoints, bounds, dynamic, SweepAxes{axis, (axis + 1) % 3, (axis + 2) % 3}, pairs, columns);
}

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

namespace {

/// Stable counting sort of `from` into `to` by key(pair), a body index below bodyCount.
template <class Key>
void countingSortPairs(const std::vector<BodyPair>& from, std::vector<BodyPair>& to, int bodyCount,
                       std::vector<int>& starts, Key key) {
    starts.assign(static_cast<std::size_t>(bodyCount) + 1, 0);
    for (const BodyPair& pair : from) ++starts[static_cast<std::size_t>(key(pair)) + 1];
    for (std::size_t body = 1; body < starts.size(); ++body) starts[body] += starts[body - 1];
    to.resize(from.size());
    for (const BodyPair& pair : from) to[static_cast<std::size_t>(starts[static_cast<std::size_t>(key(pair))]++)] = pair;
}

}  // namespace

void sortPairsCanonical(std::vector<BodyPair>& pairs, int bodyCount, BroadphaseBuffers& buffers) {
    if (std::is_sorted(pairs.begin(), pairs.end())) return;
    // The counting sorts cost two passes over the n bodies; few pairs are cheaper to compare.
    if (pairs.size() < 1024 || pairs.size() < static_cast<std::size_t>(bodyCount) / 8) {
        std::sort(pairs.begin(), pairs.end());
        return;
    }
    // Least significant key first: by bodyB, then stably by bodyA, which keeps bodyB's order
    // within each bodyA.
    countingSortPairs(pairs, buffers.pairs, bodyCount, buffers.pairStarts, [](const BodyPair& pair) { return pair.bodyB; });
    countingSortPairs(buffers.pairs, pairs, bodyCount, buffers.pairStarts, [](const BodyPair& pair) { return pair.bodyA; });
}

void sortPairsCanonical(std::vector<BodyPair>& pairs, int bodyCount) {
    BroadphaseBuffers buffers;
    sortPairsCanonical(pairs, bodyCount, buffers);
}

}  // namespace stepwise
