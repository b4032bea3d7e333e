#pragma once
// The last frames of a run, kept so any of them can be stepped on again. Chapter 9's rewind rests
// on one property the earlier chapters kept on purpose: all simulation state lives in the World
// (poses, velocities, the contact cache with its warm-start impulses, the broadphase's sorted
// axis, the joints' impulses, the step state), so a world put back in that state and stepped
// through the same pipeline gives the same bits as the original did. The ring keeps the world's
// structure once (a base) and, per frame, only the state the next step reads back (snapshot.h).

#include "09_debug/snapshot.h"
#include "world/world.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace stepwise {

/// Frames of history the demo keeps: two seconds at 60 Hz, enough to step back through a
/// fast impact frame by frame.
constexpr int kHistoryFrames = 120;

// [ch09-history]
/// A ring of compact snapshots, one per recorded frame, each with the base world whose structure
/// it was taken from. Recording a world whose structure differs from the current base (an edit
/// changed a mass, a body was added) takes a new base; the frames recorded before keep theirs
/// until they fall out of the ring, so every kept frame restores exactly. Recording into a full
/// ring overwrites the oldest slot, reusing its vectors' storage.
class History {
public:
    explicit History(int capacity = kHistoryFrames);

    /// Keeps the world's state as it is now (after a live frame); the oldest falls out when full.
    void record(const World& world);
    /// The next record() takes a new base whatever it compares: for code that changes what
    /// sameStructure does not look at (a shape, a material, a joint's definition) in a live world.
    /// The frames kept so far keep their base.
    void rebase() { base_.reset(); }
    void clear();

    int size() const { return count_; }
    int capacity() const { return static_cast<int>(slots_.size()); }
    bool empty() const { return count_ == 0; }
    /// World::frame of the oldest and newest kept frames; -1 when empty.
    long oldestFrame() const;
    long newestFrame() const;
    /// Whether that frame is kept.
    bool contains(long frame) const { return slotOf(frame) >= 0; }
    /// Puts the kept frame into `world` (its base, then its snapshot); false, and `world`
    /// untouched, when the frame is not kept.
    bool restore(long frame, World& world) const;
    /// The kept world of that frame, rebuilt; empty when the frame is not kept.
    std::optional<World> find(long frame) const;
    /// The k-th kept frame, 0 the oldest, rebuilt.
    World at(int k) const;
    /// The k-th kept frame's snapshot.
    const WorldSnapshot& snapshotAt(int k) const;
    /// Memory the ring holds, bytes: the snapshots (their vectors' capacities) and each distinct
    /// base world once. What the bench reports.
    std::size_t bytes() const;
    /// The snapshots alone, and the distinct bases alone.
    std::size_t snapshotBytes() const;
    std::size_t baseBytes() const;
    /// Distinct base worlds the kept frames refer to (1 unless the structure changed).
    int baseCount() const;

private:
    struct Slot {
        WorldSnapshot snapshot;
        std::shared_ptr<const World> base;
    };
    const Slot& slotAt(int k) const;
    int slotOf(long frame) const;   // k of the kept frame, -1 when absent

    std::vector<Slot> slots_;
    std::shared_ptr<const World> base_;   // the structure frames are recorded against now
    int first_ = 0;    // slot of the oldest frame
    int count_ = 0;
};
// [ch09-history]

/// The world's structure without its per-frame state: what a History keeps once per structure.
World structureOf(const World& world);

/// Memory a world's state takes, bytes (vector capacities and the fixed parts; strings and
/// shared hulls not counted): what a whole copy per frame would cost.
std::size_t worldBytes(const World& world);

}  // namespace stepwise
