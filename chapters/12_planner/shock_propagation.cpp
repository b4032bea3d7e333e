#include "12_planner/shock_propagation.h"

#include <algorithm>

namespace stepwise {

// [ch12-shock-order]
void orderShockSweep(const std::vector<int>& slotA, const std::vector<int>& slotB, const std::vector<int>& slotDepth,
                     ShockOrder& order) {
    const std::size_t contacts = slotA.size();
    const auto depthOf = [&](int slot) { return slotDepth[static_cast<std::size_t>(slot)]; };
    const auto lowerIsA = [&](std::size_t i) { return depthOf(slotA[i]) < depthOf(slotB[i]); };
    // A contact's layer is its lower body's depth; -1 when it is not swept (a body that does not
    // move, or two of one depth).
    const auto layerOf = [&](std::size_t i) {
        if (slotA[i] == 0 || slotB[i] == 0 || depthOf(slotA[i]) == depthOf(slotB[i])) return -1;
        return std::min(depthOf(slotA[i]), depthOf(slotB[i]));
    };
    // Counting sort by layer.
    int deepest = 0;
    for (std::size_t i = 0; i < contacts; ++i) deepest = std::max(deepest, layerOf(i));
    std::vector<int>& next = order.groupCount;  // each layer's next place, then each group's
    order.layerStart.assign(static_cast<std::size_t>(deepest) + 2, 0);
    for (std::size_t i = 0; i < contacts; ++i)
        if (const int layer = layerOf(i); layer >= 0) ++order.layerStart[static_cast<std::size_t>(layer) + 1];
    for (std::size_t layer = 1; layer < order.layerStart.size(); ++layer)
        order.layerStart[layer] += order.layerStart[layer - 1];
    order.layered.resize(static_cast<std::size_t>(order.layerStart.back()));
    next.assign(order.layerStart.begin(), order.layerStart.end() - 1);
    for (std::size_t i = 0; i < contacts; ++i)
        if (const int layer = layerOf(i); layer >= 0)
            order.layered[static_cast<std::size_t>(next[static_cast<std::size_t>(layer)]++)] = static_cast<int>(i);

    // Within a layer, a contact's group is how many earlier contacts of the layer share its upper
    // body: a box on two boxes has one contact in group 0 and one in group 1.
    order.entries.resize(order.layered.size());
    order.lowerIsA.resize(order.layered.size());
    order.colour.resize(order.layered.size());
    order.seen.assign(slotDepth.size(), 0);
    order.groupStart.assign(1, 0);
    const auto upperSlot = [&](int k) {
        const std::size_t i = static_cast<std::size_t>(order.layered[static_cast<std::size_t>(k)]);
        return static_cast<std::size_t>(lowerIsA(i) ? slotB[i] : slotA[i]);
    };
    for (std::size_t layer = 0; layer + 1 < order.layerStart.size(); ++layer) {
        const int begin = order.layerStart[layer], end = order.layerStart[layer + 1];
        int groups = 0;
        for (int k = begin; k < end; ++k) {
            order.colour[static_cast<std::size_t>(k)] = order.seen[upperSlot(k)]++;
            groups = std::max(groups, order.seen[upperSlot(k)]);
        }
        for (int k = begin; k < end; ++k) order.seen[upperSlot(k)] = 0;
        // Counting sort by group, stable: the layer's groups in turn, each in contact order.
        next.assign(static_cast<std::size_t>(groups) + 1, begin);
        for (int k = begin; k < end; ++k) ++next[static_cast<std::size_t>(order.colour[static_cast<std::size_t>(k)]) + 1];
        for (std::size_t group = 1; group < next.size(); ++group) next[group] += next[group - 1] - begin;
        for (std::size_t group = 1; group < next.size(); ++group) order.groupStart.push_back(next[group]);
        for (int k = begin; k < end; ++k) {
            const std::size_t at = static_cast<std::size_t>(next[static_cast<std::size_t>(order.colour[static_cast<std::size_t>(k)])]++);
            const std::size_t i = static_cast<std::size_t>(order.layered[static_cast<std::size_t>(k)]);
            order.entries[at] = static_cast<int>(i);
            order.lowerIsA[at] = lowerIsA(i) ? 1 : 0;
        }
    }
}
// [ch12-shock-order]

}  // namespace stepwise
