#include "09_debug/debug_session.h"

#include "world/enum_names.h"
#include "world/state_hash.h"

#include <algorithm>
#include <iterator>

namespace stepwise {

const char* toString(StopReason reason) {
    static const Names<StopReason> names = {
        {"none", StopReason::None}, {"new contact", StopReason::NewContact}, {"simulation disabled", StopReason::Disabled}};
    return nameOf(names, reason);
}

std::vector<BodyPair> pairsInContact(const World& world) {
    std::vector<BodyPair> pairs;
    for (const Contact& contact : world.contacts)
        if (contact.pointCount > 0) pairs.push_back(contact.pair());
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

DebugSession::DebugSession(World world, Pipeline pipeline, int historyFrames)
    : world_(std::move(world)), pipeline_(std::move(pipeline)), history_(historyFrames) {
    start_ = world_;
    history_.record(world_);
}

// [ch09-session-step]
StopReason DebugSession::step() {
    newContacts_.clear();
    if (!simulationEnabled) return lastStop_ = StopReason::Disabled;
    const std::vector<BodyPair> before = rules.stopOnNewContact ? pairsInContact(world_) : std::vector<BodyPair>{};
    pipeline_.step(world_);
    if (!rewound_) {
        history_.record(world_);
        frameHashes_.push_back(stateHash(world_));
    }
    lastStop_ = StopReason::None;
    if (rules.stopOnNewContact) {
        const std::vector<BodyPair> after = pairsInContact(world_);
        std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(newContacts_));
        if (!newContacts_.empty()) {
            paused = true;
            lastStop_ = StopReason::NewContact;
        }
    }
    return lastStop_;
}
// [ch09-session-step]

long DebugSession::liveFrame() const { return rewound_ ? live_.frame : world_.frame; }

bool DebugSession::rewindTo(long frame) {
    if (!history_.contains(frame)) return false;
    if (!rewound_) {
        live_ = world_;   // the live world as it is now, edits after its last frame included
        rewound_ = true;
    }
    history_.restore(frame, world_);
    return true;
}

bool DebugSession::rewindBy(int frames) {
    if (history_.empty()) return false;
    const long from = rewound_ ? world_.frame : history_.newestFrame();
    return rewindTo(std::max(history_.oldestFrame(), from - std::max(0, frames)));
}

void DebugSession::resume() {
    if (!rewound_) return;
    world_ = live_;
    rewound_ = false;
}

void DebugSession::edit(BodyEdit change) {
    change.frame = world_.frame;
    applyEdit(world_, change);
    if (!rewound_) edits_.push_back(change);
}

}  // namespace stepwise
