#include "09_debug/history.h"
#include "world/heap_bytes.h"

#include <stdexcept>
#include <string>

namespace stepwise {

History::History(int capacity) : slots_(static_cast<std::size_t>(capacity > 0 ? capacity : 1)) {}

// [ch09-history-record]
void History::record(const World& world) {
    if (!base_ || !sameStructure(*base_, world)) base_ = std::make_shared<const World>(structureOf(world));
    const int slot = (first_ + count_) % capacity();
    Slot& target = slots_[static_cast<std::size_t>(slot)];
    saveSnapshot(world, target.snapshot);
    target.base = base_;
    if (count_ < capacity()) ++count_;
    else first_ = (first_ + 1) % capacity();
}
// [ch09-history-record]

void History::clear() {
    for (Slot& slot : slots_) slot.base.reset();
    base_.reset();
    first_ = 0;
    count_ = 0;
}

const History::Slot& History::slotAt(int k) const {
    if (k < 0 || k >= count_) throw std::out_of_range("History::at: frame " + std::to_string(k) + " of " + std::to_string(count_));
    return slots_[static_cast<std::size_t>((first_ + k) % capacity())];
}

const WorldSnapshot& History::snapshotAt(int k) const { return slotAt(k).snapshot; }

long History::oldestFrame() const { return count_ > 0 ? slotAt(0).snapshot.frame : -1; }
long History::newestFrame() const { return count_ > 0 ? slotAt(count_ - 1).snapshot.frame : -1; }

int History::slotOf(long frame) const {
    if (count_ == 0 || frame < oldestFrame() || frame > newestFrame()) return -1;
    // Frames are recorded in order but not always one apart (a session that rewound and resumed
    // records on from its newest frame), so look the frame up rather than compute its slot.
    for (int k = count_ - 1; k >= 0; --k)
        if (slotAt(k).snapshot.frame == frame) return k;
    return -1;
}

// [ch09-history-restore]
bool History::restore(long frame, World& world) const {
    const int k = slotOf(frame);
    if (k < 0) return false;
    const Slot& slot = slotAt(k);
    world = *slot.base;   // the structure, with every per-frame vector empty
    restoreSnapshot(slot.snapshot, world);
    return true;
}
// [ch09-history-restore]

std::optional<World> History::find(long frame) const {
    World world;
    if (!restore(frame, world)) return std::nullopt;
    return world;
}

World History::at(int k) const {
    const Slot& slot = slotAt(k);
    World world = *slot.base;
    restoreSnapshot(slot.snapshot, world);
    return world;
}

std::size_t History::snapshotBytes() const {
    std::size_t total = 0;
    for (int k = 0; k < count_; ++k) total += stepwise::snapshotBytes(slotAt(k).snapshot);
    return total;
}

std::size_t History::baseBytes() const {
    std::size_t total = 0;
    const World* last = nullptr;
    for (int k = 0; k < count_; ++k) {
        const World* base = slotAt(k).base.get();
        if (base != last) total += worldBytes(*base);   // frames of one base are recorded in a row
        last = base;
    }
    return total;
}

int History::baseCount() const {
    int bases = 0;
    const World* last = nullptr;
    for (int k = 0; k < count_; ++k) {
        if (slotAt(k).base.get() != last) ++bases;
        last = slotAt(k).base.get();
    }
    return bases;
}

std::size_t History::bytes() const { return snapshotBytes() + baseBytes(); }

World structureOf(const World& world) {
    // Copy what no step changes; leave every per-frame vector empty (a restore fills them).
    World base;
    base.name = world.name;
    base.settings = world.settings;
    base.bodies = world.bodies;
    base.motions = world.motions;
    base.springs = world.springs;
    base.dampings = world.dampings;
    base.joints = world.joints;
    base.kinematicPaths = world.kinematicPaths;
    base.broadphase.reason = world.broadphase.reason;
    base.broadphase.reasonSetting = world.broadphase.reasonSetting;
    base.broadphase.reasonBodyCount = world.broadphase.reasonBodyCount;
    return base;
}

std::size_t worldBytes(const World& world) {
    std::size_t bytes = sizeof(World);
    bytes += capacityBytes(world.bodies) + capacityBytes(world.motions) + capacityBytes(world.springs) +
             capacityBytes(world.dampings) + capacityBytes(world.joints) + capacityBytes(world.jointImpulses) +
             capacityBytes(world.kinematicPaths) + capacityBytes(world.candidatePairs) + capacityBytes(world.pairs) +
             capacityBytes(world.contacts) + capacityBytes(world.pairGaps);
    const StepState& step = world.step;
    bytes += capacityBytes(step.velocitiesBeforeForces) + capacityBytes(step.ccd.sweepStart) +
             capacityBytes(step.ccd.ghostBodies) + capacityBytes(step.ccd.ghostPoses) + capacityBytes(step.ccd.sweptBounds);
    const BroadphaseState& broadphase = world.broadphase;
    const SweepColumns& columns = broadphase.buffers.columns;
    bytes += capacityBytes(broadphase.endpoints) + capacityBytes(broadphase.bounds) + capacityBytes(broadphase.dynamic) +
             capacityBytes(columns.low) + capacityBytes(columns.high) + capacityBytes(columns.lowA) +
             capacityBytes(columns.highA) + capacityBytes(columns.lowB) + capacityBytes(columns.highB) +
             capacityBytes(columns.body) + capacityBytes(columns.dynamic) + capacityBytes(broadphase.buffers.pairs) +
             capacityBytes(broadphase.buffers.pairStarts) + capacityBytes(broadphase.enlargedBounds) +
             capacityBytes(broadphase.enlargedDynamic) + capacityBytes(broadphase.enlargedPairs);
    return bytes;
}

}  // namespace stepwise
