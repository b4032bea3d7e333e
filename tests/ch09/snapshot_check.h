#pragma once
// The check behind the snapshot tests: run a world, keep compact snapshots at a few frames,
// restore each into a world of the same structure and step on; every frame's state hash must be
// the original run's. Shared by chapter 9's suite (its own pipeline) and the reliability suite
// (the latest chapter's, with sleeping, the contact cache, the planner and the world shapes).

#include "09_debug/history.h"
#include "09_debug/snapshot.h"
#include "world/pipeline.h"
#include "world/state_hash.h"

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

namespace stepwise::test {

template <class T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// Whether two snapshots hold the same state the next step reads, to the bit (every element is
/// value-initialised before it is filled, so padding compares equal). The sweep's order is left
/// out: chapter 10 skips sweeps whose pairs it knows, so the order it keeps may be older than a
/// restored run's, and the sort's total order makes the pairs the same either way.
inline bool sameState(const WorldSnapshot& a, const WorldSnapshot& b) {
    return a.frame == b.frame && std::memcmp(&a.time, &b.time, sizeof a.time) == 0 && sameBytes(a.poses, b.poses) &&
           sameBytes(a.motions, b.motions) && sameBytes(a.asleep, b.asleep) && sameBytes(a.pushes, b.pushes) &&
           sameBytes(a.contacts, b.contacts) && sameBytes(a.builtPoses, b.builtPoses) && sameBytes(a.points, b.points) &&
           sameBytes(a.pairs, b.pairs) && a.pairsWhole == b.pairsWhole && a.jointImpulses.size() == b.jointImpulses.size() &&
           (a.jointImpulses.empty() ||
            std::memcmp(a.jointImpulses.data(), b.jointImpulses.data(), a.jointImpulses.size() * sizeof(JointImpulses)) == 0) &&
           a.step.iterationPlan.iterations == b.step.iterationPlan.iterations &&
           a.settings.solverIterations == b.settings.solverIterations;
}

struct RestoreMismatch {
    long frame = -1;        // first frame whose hash differs after a restore; -1: none
    long restoredAt = -1;   // the snapshot's frame
    int restores = 0;       // restores compared
    std::string into;       // what the snapshot was restored into
};

/// Runs `start` for `frames` frames through make(start), snapshotting after each frame in `at`.
/// Each snapshot is restored twice, into the bare structure (structureOf the start) and into the
/// original world as it ended (every derived buffer full of another frame's values), and stepped
/// to `frames` through a fresh pipeline: every frame's state hash, and its whole snapshot
/// (sameState), must be the original's.
/// `poke`, when given, is called before every step with the frames stepped so far (an edit, a
/// wake): the original and every restored run get the same pokes.
using Poke = std::function<void(World& world, long framesStepped)>;
inline RestoreMismatch firstRestoreMismatch(const World& start, const std::function<Pipeline(const World&)>& make,
                                            long frames, const std::vector<long>& at, const Poke& poke = {}) {
    World world = start;
    Pipeline pipeline = make(start);
    std::vector<std::uint64_t> hashes;
    std::vector<WorldSnapshot> states;   // every frame's, to compare what the hash does not cover
    std::vector<std::pair<long, WorldSnapshot>> snapshots;   // (frames stepped, snapshot)
    for (long frame = 1; frame <= frames; ++frame) {
        if (poke) poke(world, frame - 1);
        pipeline.step(world);
        hashes.push_back(stateHash(world));
        states.emplace_back();
        saveSnapshot(world, states.back());
        for (long when : at)
            if (when == frame) {
                snapshots.emplace_back(frame, WorldSnapshot{});
                saveSnapshot(world, snapshots.back().second);
            }
    }
    RestoreMismatch result;
    const World bare = structureOf(start);
    for (const auto& [taken, snapshot] : snapshots) {
        for (int into = 0; into < 2; ++into) {
            World restored = into == 0 ? bare : world;
            restoreSnapshot(snapshot, restored);
            Pipeline again = make(start);
            ++result.restores;
            WorldSnapshot roundTrip;   // saving the restored world gives the snapshot back
            saveSnapshot(restored, roundTrip);
            if (stateHash(restored) != hashes[static_cast<std::size_t>(taken - 1)] || !sameState(roundTrip, snapshot)) {
                return {taken, taken, result.restores, into == 0 ? "the structure" : "the last frame"};
            }
            for (long frame = taken + 1; frame <= frames; ++frame) {
                if (poke) poke(restored, frame - 1);
                again.step(restored);
                WorldSnapshot state;
                saveSnapshot(restored, state);
                if (stateHash(restored) != hashes[static_cast<std::size_t>(frame - 1)] ||
                    !sameState(state, states[static_cast<std::size_t>(frame - 1)]))
                    return {frame, taken, result.restores, into == 0 ? "the structure" : "the last frame"};
            }
        }
    }
    return result;
}

}  // namespace stepwise::test
