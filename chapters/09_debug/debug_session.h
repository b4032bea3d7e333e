#pragma once
// A run under the debugger: the world and its pipeline, the last 120 frames, the stop rules, and
// the log of hand edits. Live frames are recorded; after a rewind the frames stepped are
// speculative, and resuming throws them away and puts back the live state exactly as it was.
// The demo shell drives one of these; so do the tests, headless.

#include "09_debug/body_edit.h"
#include "09_debug/history.h"
#include "world/pipeline.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stepwise {

// [ch09-stop-rules]
/// When a running session stops by itself. A "contact debug mode": stop the
/// moment a new contact appears, so the frame that made it can be looked at (and rewound).
struct StopRules {
    bool stopOnNewContact = false;
};

enum class StopReason {
    None,         // stepped, nothing stopped it
    NewContact,   // a pair gained a contact this frame; the session paused
    Disabled,     // the simulation switch is off: nothing was stepped
};
const char* toString(StopReason reason);
// [ch09-stop-rules]

/// The pairs that hold a contact record with at least one point (what the solver acts on), sorted.
std::vector<BodyPair> pairsInContact(const World& world);

class DebugSession {
public:
    DebugSession(World world, Pipeline pipeline, int historyFrames = kHistoryFrames);

    World& world() { return world_; }
    const World& world() const { return world_; }
    Pipeline& pipeline() { return pipeline_; }
    const History& history() const { return history_; }

    // Running. A paused session steps only when asked (single step); the switch stops even that
    // (nothing integrates, nothing solves).
    bool paused = false;
    bool simulationEnabled = true;
    StopRules rules;

    /// One frame: live (recorded in the history and the frame hashes) or, while rewound,
    /// speculative (recorded nowhere). Checks the stop rules; a rule that fires pauses the session.
    StopReason step();
    /// The pairs whose new contacts stopped the last step (empty otherwise).
    const std::vector<BodyPair>& newContacts() const { return newContacts_; }
    StopReason lastStop() const { return lastStop_; }

    // Rewinding. rewindTo() shows a kept frame; stepping from there is speculative; resume()
    // discards it and restores the live world, bit for bit, including edits made after its
    // last frame.
    bool rewound() const { return rewound_; }
    /// False (and nothing changes) when the frame is not in the history.
    bool rewindTo(long frame);
    /// rewindTo(newest kept frame - frames), clamped to the oldest.
    bool rewindBy(int frames);
    void resume();
    /// The newest live frame number (the history's newest, or the world's frame before any step).
    long liveFrame() const;

    // Editing. Applies the edit to the world shown now (throws std::invalid_argument on a bad
    // edit, see validateEdit); a live edit is logged for recordings, a speculative one is not.
    void edit(BodyEdit change);
    const std::vector<BodyEdit>& edits() const { return edits_; }

    /// stateHash of the world after each live frame since the session began, in order: what a
    /// recording stores per frame and a replay checks.
    const std::vector<std::uint64_t>& frameHashes() const { return frameHashes_; }
    /// The world as the session began (what a recording starts from).
    const World& startWorld() const { return start_; }

private:
    World world_;
    World live_;          // the live world while rewound
    World start_;
    Pipeline pipeline_;
    History history_;
    bool rewound_ = false;
    std::vector<BodyPair> newContacts_;
    StopReason lastStop_ = StopReason::None;
    std::vector<BodyEdit> edits_;
    std::vector<std::uint64_t> frameHashes_;
};

}  // namespace stepwise
