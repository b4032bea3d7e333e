#include "11_wide_solve/colouring.h"

namespace stepwise {

// [ch11-colouring]
void colourContacts(const std::vector<int>& slotA, const std::vector<int>& slotB, int slotCount,
                    std::vector<int>& colours, std::vector<std::uint64_t>& usedScratch, int firstColoured) {
    // One bit per (colour, slot): colour c holds slot s when bit s of row c is set.
    const std::size_t words = (static_cast<std::size_t>(slotCount) + 63) / 64;
    usedScratch.assign(words * kMaxColours, 0);
    colours.resize(slotA.size());
    auto used = [&](int colour, int slot) {
        return slot >= firstColoured && (usedScratch[colour * words + slot / 64] >> (slot % 64)) & 1u;
    };
    auto take = [&](int colour, int slot) {
        if (slot >= firstColoured) usedScratch[colour * words + slot / 64] |= std::uint64_t(1) << (slot % 64);
    };
    for (std::size_t i = 0; i < slotA.size(); ++i) {
        colours[i] = -1;
        for (int colour = 0; colour < kMaxColours; ++colour) {
            if (used(colour, slotA[i]) || used(colour, slotB[i])) continue;
            take(colour, slotA[i]);
            take(colour, slotB[i]);
            colours[i] = colour;
            break;
        }
    }
}
// [ch11-colouring]

}  // namespace stepwise
