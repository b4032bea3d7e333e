#include "09_debug/history.h"

#include <stdexcept>

namespace stepwise {

History::History(int capacity) : slots_(static_cast<std::size_t>(capacity > 0 ? capacity : 1)) {}

void History::record(const World& world) {
    const int slot = (first_ + count_) % capacity();
    slots_[static_cast<std::size_t>(slot)] = world;
    if (count_ < capacity()) ++count_;
    else first_ = (first_ + 1) % capacity();
}

void History::clear() {
    first_ = 0;
    count_ = 0;
}

const World& History::at(int k) const {
    if (k < 0 || k >= count_) throw std::out_of_range("History::at: frame " + std::to_string(k) + " of " + std::to_string(count_));
    return slots_[static_cast<std::size_t>((first_ + k) % capacity())];
}

long History::oldestFrame() const { return count_ > 0 ? at(0).frame : -1; }
long History::newestFrame() const { return count_ > 0 ? at(count_ - 1).frame : -1; }

const World* History::find(long frame) const {
    if (count_ == 0 || frame < oldestFrame() || frame > newestFrame()) return nullptr;
    // Frames are recorded in order but not always one apart (a session that rewound and resumed
    // records on from its newest frame), so look the frame up rather than compute its slot.
    for (int k = count_ - 1; k >= 0; --k)
        if (at(k).frame == frame) return &at(k);
    return nullptr;
}

template <class T>
static std::size_t vectorBytes(const std::vector<T>& values) {
    return values.capacity() * sizeof(T);
}

std::size_t worldBytes(const World& world) {
    std::size_t bytes = sizeof(World);
    bytes += vectorBytes(world.bodies) + vectorBytes(world.motions) + vectorBytes(world.springs) +
             vectorBytes(world.dampings) + vectorBytes(world.joints) + vectorBytes(world.jointImpulses) +
             vectorBytes(world.kinematicPaths) + vectorBytes(world.candidatePairs) + vectorBytes(world.pairs) +
             vectorBytes(world.contacts) + vectorBytes(world.pairGaps);
    const StepState& step = world.step;
    bytes += vectorBytes(step.velocitiesBeforeForces) + vectorBytes(step.ccd.sweepStart) +
             vectorBytes(step.ccd.ghostBodies) + vectorBytes(step.ccd.ghostPoses) + vectorBytes(step.ccd.sweptBounds);
    const BroadphaseState& broadphase = world.broadphase;
    const SweepColumns& columns = broadphase.buffers.columns;
    bytes += vectorBytes(broadphase.endpoints) + vectorBytes(broadphase.bounds) + vectorBytes(broadphase.dynamic) +
             vectorBytes(columns.low) + vectorBytes(columns.high) + vectorBytes(columns.lowA) +
             vectorBytes(columns.highA) + vectorBytes(columns.lowB) + vectorBytes(columns.highB) +
             vectorBytes(columns.body) + vectorBytes(columns.dynamic) + vectorBytes(broadphase.buffers.pairs) +
             vectorBytes(broadphase.buffers.pairStarts) + vectorBytes(broadphase.enlargedBounds) +
             vectorBytes(broadphase.enlargedDynamic) + vectorBytes(broadphase.enlargedPairs);
    return bytes;
}

std::size_t History::bytes() const {
    std::size_t total = 0;
    for (int k = 0; k < count_; ++k) total += worldBytes(at(k));
    return total;
}

}  // namespace stepwise
