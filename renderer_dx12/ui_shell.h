#pragma once
// The Dear ImGui shell every chapter demo shares: scene picker, run/pause/step and time
// scale, pipeline stage toggles with a timing graph, world settings, counts, the scene's
// observe line and its own panel, an F1 hotkey overlay; plus mouse/keyboard camera control.

#include "app/panel.h"
#include "camera.h"
#include "debug_panel.h"
#include "demo_state.h"

#include <cstddef>
#include <deque>
#include <string>

namespace stepwise::render {

/// Panel (common/app/panel.h) on top of Dear ImGui, for SceneEntry::panel hooks.
class ImGuiPanel final : public Panel {
public:
    void text(const std::string& line) override;
    bool checkbox(const std::string& label, bool& value) override;
    bool sliderFloat(const std::string& label, float& value, float min, float max) override;
    bool sliderInt(const std::string& label, int& value, int min, int max) override;
    bool button(const std::string& label) override;
    bool combo(const std::string& label, int& index, const char* const* items, int count) override;
};

struct ShellInfo {
    std::string title;      // "Stepwise chapter 4"
    std::string adapter;    // GPU name
    float framesPerSecond = 0;
};

/// Durations readable at a glance: "850 ns", "4.2 us", "1.25 ms", "2.5 s".
void formatDuration(char* out, size_t size, double ms);
/// A history graph scaled to its recent maximum so that sub-millisecond curves fill its height;
/// its corner prints the full scale (as durations of milliseconds, or plain numbers).
void historyGraph(const char* id, const std::deque<float>& history, float height, const char* caption = nullptr,
                  bool durations = true);

/// Builds the whole ImGui frame content (between ImGui::NewFrame and ImGui::Render): the main
/// panel on the left and the debugger on the right.
void drawShell(DemoState& state, ViewOptions& view, Camera& camera, const ShellInfo& info, DebugTools& tools);
/// Hotkeys and mouse camera control; skipped where ImGui wants the input. Returns true when
/// the camera should be re-framed (new scene, F key).
bool handleInput(DemoState& state, ViewOptions& view, Camera& camera, DebugTools& tools, float viewportHeight, float seconds);
/// DebugDraw::text labels, drawn over the 3D view.
void drawLabels(const DrawList& list, const Camera& camera, float width, float height);
/// The rectangle the shell's main window covers (x0, y0, x1, y1), after ImGui::Render.
bool shellRect(float rect[4]);
/// Frames the scene in the part of a width x height view the panel and the debugger leave free
/// (all of it when the shell is hidden; before their first layout, their usual widths are assumed),
/// narrowing that part until the framing's labels end inside the image.
void frameScene(Camera& camera, const Framing& framing, const ViewOptions& view, float width, float height);

}  // namespace stepwise::render
