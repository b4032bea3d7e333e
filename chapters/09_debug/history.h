#pragma once
// The last frames of a run, kept whole so any of them can be stepped on again. Chapter 9's rewind
// rests on one property the earlier chapters kept on purpose: all simulation state lives in the
// World (poses, velocities, the contact cache with its warm-start impulses, the broadphase's sorted
// axes, the joints' impulses, the step state), so a copy of it is a snapshot, and a copy stepped
// through the same pipeline gives the same bits as the original did.

#include "world/world.h"

#include <cstddef>
#include <vector>

namespace stepwise {

/// Frames of history the demo keeps: two seconds at 60 Hz, enough to step back through a
/// fast impact frame by frame.
constexpr int kHistoryFrames = 120;

// [ch09-history]
/// A ring buffer of whole worlds, one per recorded frame. Recording into a full ring overwrites
/// the oldest slot by assignment, so a run of steady size reuses the slots' storage instead of
/// allocating a new world every frame.
class History {
public:
    explicit History(int capacity = kHistoryFrames);

    /// Keeps a copy of the world as it is now (after a live frame); the oldest falls out when full.
    void record(const World& world);
    void clear();

    int size() const { return count_; }
    int capacity() const { return static_cast<int>(slots_.size()); }
    bool empty() const { return count_ == 0; }
    /// World::frame of the oldest and newest kept frames; -1 when empty.
    long oldestFrame() const;
    long newestFrame() const;
    /// The kept world of that frame, or nullptr.
    const World* find(long frame) const;
    /// The k-th kept frame, 0 the oldest.
    const World& at(int k) const;
    /// Memory the kept worlds hold (their vectors' capacities), bytes: what the bench reports.
    std::size_t bytes() const;

private:
    std::vector<World> slots_;
    int first_ = 0;    // slot of the oldest frame
    int count_ = 0;
};
// [ch09-history]

/// Memory a world's state takes, bytes (vector capacities and the fixed parts; strings and
/// shared hulls not counted).
std::size_t worldBytes(const World& world);

}  // namespace stepwise
