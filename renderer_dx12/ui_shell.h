#pragma once
// The Dear ImGui shell every chapter demo shares: scene picker, run/pause/step and time
// scale, pipeline stage toggles with a timing graph, world settings, counts, the scene's
// observe line and its own panel, an F1 hotkey overlay; plus mouse/keyboard camera control.

#include "app/panel.h"
#include "camera.h"
#include "demo_state.h"

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

/// Builds the whole ImGui frame content (between ImGui::NewFrame and ImGui::Render).
void drawShell(DemoState& state, ViewOptions& view, Camera& camera, const ShellInfo& info);
/// Hotkeys and mouse camera control; skipped where ImGui wants the input. Returns true when
/// the camera should be re-framed (new scene, F key).
bool handleInput(DemoState& state, ViewOptions& view, Camera& camera, float viewportHeight, float seconds);
/// DebugDraw::text labels, drawn over the 3D view.
void drawLabels(const DrawList& list, const Camera& camera, float width, float height);
/// The rectangle the shell's main window covers (x0, y0, x1, y1), after ImGui::Render.
bool shellRect(float rect[4]);
/// Frames the scene in the part of a width x height view the panel leaves free (all of it
/// when the panel is hidden; before the panel's first layout, its usual width is assumed),
/// narrowing that part until the framing's labels end inside the image.
void frameScene(Camera& camera, const Framing& framing, const ViewOptions& view, float width, float height);

}  // namespace stepwise::render
