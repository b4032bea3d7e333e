#pragma once
// Graph colouring of the contacts: contacts of one colour share no moving body, so they can be
// solved at the same time (one per SIMD lane) without two lanes writing the same body's
// velocity. Gauss-Seidel still holds between colours: each colour sees what the ones before it did.

#include <cstdint>
#include <vector>

namespace stepwise {

/// Colours tried before a contact goes to the overflow, solved one at a time after the colours
/// (Box3D uses 24 the same way). A pyramid needs 4; a pile a few more.
constexpr int kMaxColours = 24;

/// The colour of each contact (greedy, in the given order, lowest free colour first: the same input
/// always gives the same colours), or -1 for the overflow. `slotA`/`slotB` are the contacts'
/// solver slots; a slot below `firstColoured` (slot 0: static and asleep; then the kinematic bodies)
/// never blocks a colour: no row changes its velocity, so any number of contacts may share it.
/// `usedScratch` keeps the per-colour bit sets between calls, so a steady scene allocates nothing.
void colourContacts(const std::vector<int>& slotA, const std::vector<int>& slotB, int slotCount,
                    std::vector<int>& colours, std::vector<std::uint64_t>& usedScratch, int firstColoured = 1);

}  // namespace stepwise
