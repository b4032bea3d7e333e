#include "app/peer.h"

namespace stepwise {

namespace {
PeerEngine& registeredPeer() {
    static PeerEngine peer;
    return peer;
}
}  // namespace

void setPeerEngine(PeerEngine engine) { registeredPeer() = std::move(engine); }
const PeerEngine& peerEngine() { return registeredPeer(); }

}  // namespace stepwise
