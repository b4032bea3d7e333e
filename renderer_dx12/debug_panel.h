#pragma once
// The debugger window (chapter 9), docked on the right of every chapter's demo: the session's
// switches and stop rule, the history timeline (rewind, speculative steps, resume), saving a
// recording, the debug views, the hit result tree, the inspector and the performance monitor.

#include "demo_state.h"
#include "gizmo.h"
#include "inspector_panel.h"
#include "perf_panel.h"

#include <string>

namespace stepwise::render {

/// What the debugger's tools keep between frames.
struct DebugTools {
    Gizmo gizmo;
    Inspector inspector;
    PerfMonitor perf;
    /// The panel's "stop on new contact" switch; holding Space turns the rule on while held.
    bool stopOnNewContact = false;
    std::string recordingMessage;
    char recordingPath[260] = "out/recording.json";  // what "Load recording" replays

    enum Section { Session, Views, HitResults, InspectorSection, Performance, kSectionCount };
    /// Sections to open at the next frame (scripted runs, a contact clicked in the scene).
    bool openRequest[kSectionCount] = {};
};

/// The section named `name` (session, views, hits, inspector, perf), or -1.
int sectionByName(const std::string& name);

/// The debugger window, pinned to the right edge; collapsed unless view.debuggerOpen.
void drawDebugger(DemoState& state, ViewOptions& view, DebugTools& tools);

/// The rectangle (x0, y0, x1, y1) the debugger window covered in the last frame; false when it
/// was not drawn or is collapsed to its title bar.
bool debuggerRect(float rect[4]);

/// out/recording-<scene>.json, where "Save recording" writes.
std::string recordingPathOf(const DemoState& state);

/// Writes the session's live run so far to out/recording-<scene>.json (stepwise replay reads
/// it); returns the message the panel shows.
std::string saveRecording(const DemoState& state);

/// "Load recording": replays the recording at `path` through this program's engine and says
/// whether every frame met its hash, or where the runs part.
std::string replayRecording(const DemoState& state, const std::string& path);

}  // namespace stepwise::render
