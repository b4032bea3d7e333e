#pragma once
// Another engine the benches can run beside this one, when the program was built with it (the
// Bullet peer of bench/peers/, docs/peers.md). The engine's libraries never link a peer: the
// program that does registers it here at start-up, and a bench asks for it by this plain
// interface, skipping the comparison (and saying so) when there is none.

#include "world/world.h"

#include <functional>
#include <string>
#include <vector>

namespace stepwise {

struct PeerRun {
    std::vector<double> stepMs;            // one per frame
    std::vector<Transform> finalPoses;     // per World body
    /// One per frame when the peer measures it (else empty): the deepest penetration of a contact
    /// with a static body after the frame, m, as the peer measures its contacts.
    std::vector<double> staticPenetration;
};

/// Called after each of the peer's frames, outside its timed region (frame: 0, 1, ...), with every
/// World body's pose (of the shape's origin) after it.
using BetweenPeerFrames = std::function<void(long frame, const std::vector<Transform>& poses)>;

struct PeerEngine {
    std::string name;                      // "bullet 3.24"
    /// Steps a copy of `world` for `frames` frames at the world's settings, calling `between`
    /// (when set) after each; throws std::runtime_error naming what it cannot map.
    std::function<PeerRun(const World& world, long frames, const BetweenPeerFrames& between)> run;
};

void setPeerEngine(PeerEngine engine);
/// The registered peer; its `run` is empty when the program has none.
const PeerEngine& peerEngine();

}  // namespace stepwise
