#include "ui_shell.h"

#include "dx_common.h"
#include "world/settings.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

// Dear ImGui 1.86 (Debian, the mingw build) names keys by their native (VK_) codes; 1.87+
// (vcpkg on Windows) has named ImGuiKey values. The shell works with both.
#if IMGUI_VERSION_NUM >= 18700
#define STEPWISE_KEY(vk, named) named
#else
#define STEPWISE_KEY(vk, named) vk
#endif

namespace stepwise::render {

namespace {

const char* const kMainWindow = "Stepwise";

bool pressed(int key) { return ImGui::IsKeyPressed(static_cast<decltype(ImGuiKey_Tab)>(key), false); }
bool down(int key) { return ImGui::IsKeyDown(static_cast<decltype(ImGuiKey_Tab)>(key)); }

template <class Enum>
bool enumCombo(const char* label, Enum& value, std::initializer_list<Enum> options) {
    std::vector<const char*> names;
    int index = 0, i = 0;
    for (Enum option : options) {
        names.push_back(toString(option));
        if (option == value) index = i;
        ++i;
    }
    if (!ImGui::Combo(label, &index, names.data(), static_cast<int>(names.size()))) return false;
    value = *(options.begin() + index);
    return true;
}

// Shows only the settings some stage of this demo's chapters reads; the rest are named, with
// the chapter that will read them, so a learner never moves a slider that does nothing.
void settingsSection(World& world, int chapter, int lastChapter) {
    if (!ImGui::CollapsingHeader("Solver and integrator")) return;
    Settings& s = world.settings;
    const auto reads = [&](const char* key) { return chapterReading(key) <= chapter; };
    if (reads("integrator"))
        enumCombo("integrator", s.integrator, {IntegratorKind::SemiImplicitEuler, IntegratorKind::Rk4, IntegratorKind::Verlet});
    if (reads("solver")) enumCombo("solver", s.solver, {SolverKind::GaussSeidel, SolverKind::Jacobi});
    if (reads("gyroscopic"))
        enumCombo("gyroscopic", s.gyroscopic, {GyroscopicMode::Off, GyroscopicMode::Explicit, GyroscopicMode::Implicit});
    if (reads("broadphase")) enumCombo("broadphase", s.broadphase, {BroadphaseMode::Auto, BroadphaseMode::Sap, BroadphaseMode::Brute});
    if (reads("ccd")) enumCombo("ccd", s.ccd, {CcdMode::Auto, CcdMode::On, CcdMode::Off});
    if (reads("solver_iterations")) ImGui::SliderInt("iterations", &s.solverIterations, 1, 100);
    if (reads("substeps")) ImGui::SliderInt("substeps", &s.substeps, 1, 16);
    float dtMs = static_cast<float>(s.dt) * 1000.0f;
    if (reads("dt") && ImGui::SliderFloat("dt (ms)", &dtMs, 1.0f, 50.0f, "%.2f")) s.dt = static_cast<Real>(dtMs / 1000.0f);
    float baumgarte = static_cast<float>(s.baumgarte), slop = static_cast<float>(s.slop);
    if (reads("baumgarte") && ImGui::SliderFloat("baumgarte", &baumgarte, 0.0f, 1.0f)) s.baumgarte = static_cast<Real>(baumgarte);
    if (reads("slop") && ImGui::SliderFloat("slop (m)", &slop, 0.0f, 0.05f, "%.4f")) s.slop = static_cast<Real>(slop);
    if (reads("warm_starting")) ImGui::Checkbox("warm starting", &s.warmStarting);
    if (reads("active_edges")) ImGui::Checkbox("active edges (no bump at triangle seams)", &s.activeEdges);
    float jointHertz = static_cast<float>(s.jointHertz);
    if (reads("joint_hertz") && ImGui::SliderFloat("joint hertz", &jointHertz, 5.0f, 600.0f, "%.0f"))
        s.jointHertz = static_cast<Real>(jointHertz);
    float gravity = static_cast<float>(s.gravity.y());
    if (reads("gravity") && ImGui::SliderFloat("gravity y", &gravity, -30.0f, 30.0f)) s.gravity.y() = static_cast<Real>(gravity);
    for (const SettingUse& use : settingUses())
        if (use.chapter > chapter)
            ImGui::TextDisabled("%s: not used until chapter %d%s", use.key, use.chapter,
                                use.chapter > lastChapter ? " (to come)" : "");
}

void pipelineSection(DemoState& state) {
    if (!ImGui::CollapsingHeader("Pipeline", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (!state.pipelineError.empty()) ImGui::TextColored(ImVec4(1, 0.5f, 0.3f, 1), "%s", state.pipelineError.c_str());
    char duration[32];
    for (Stage& stage : state.pipeline().stages()) {
        ImGui::Checkbox(stage.name.c_str(), &stage.enabled);
        // A long stage name pushes the time right instead of running into it.
        ImGui::SameLine();
        ImGui::SetCursorPosX(std::max(ImGui::GetCursorPosX() + 8, 270.0f));
        formatDuration(duration, sizeof duration, stage.lastMs);
        ImGui::TextUnformatted(duration);
        auto found = state.stageHistory.find(stage.name);
        if (found != state.stageHistory.end()) historyGraph(stage.name.c_str(), found->second, 20);
    }
    if (!state.frameHistory.empty()) {
        char caption[48];
        formatDuration(duration, sizeof duration, static_cast<double>(state.frameHistory.back()));
        std::snprintf(caption, sizeof caption, "whole step %s", duration);
        historyGraph("##step", state.frameHistory, 32, caption);
    }
}

void helpOverlay() {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * size.x, 0.5f * size.y), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Hotkeys (F1)", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    const char* const rows[][2] = {{"F1", "this help"}, {"F2", "hide / show the panel"}, {"P", "run / pause"},
                                   {"Space (hold)", "stop at the next new contact"}, {"Left Alt", "continue (unpause)"},
                                   {"N or Right", "single step (paused)"}, {"Left", "one frame back in the history"},
                                   {"Left click", "select a body or a contact point"}, {"W / E (selected)", "move / turn gizmo"},
                                   {"Esc", "deselect"}, {"R", "restart the scene"},
                                   {"PgUp / PgDn", "previous / next scene"}, {"F", "frame the scene"},
                                   {"C", "orbit / fly camera"}, {"Z", "wireframe"}, {"G", "ground grid"},
                                   {"W A S D Q E", "fly (nothing selected)"},
                                   {"Right mouse drag", "orbit / look"}, {"Middle drag", "pan"}, {"Wheel", "zoom"}};
    for (const auto& row : rows) {
        ImGui::TextUnformatted(row[0]);
        ImGui::SameLine(150);
        ImGui::TextUnformatted(row[1]);
    }
    ImGui::End();
}

}  // namespace

void formatDuration(char* out, size_t size, double ms) {
    if (ms < 0.001) std::snprintf(out, size, "%.0f ns", ms * 1e6);
    else if (ms < 1.0) std::snprintf(out, size, "%.3g us", ms * 1e3);
    else if (ms < 1000.0) std::snprintf(out, size, "%.3g ms", ms);
    else std::snprintf(out, size, "%.3g s", ms * 1e-3);
}

namespace {

/// The smallest 1, 2 or 5 times a power of ten at or above `value`: a graph's full scale.
double niceCeiling(double value) {
    if (!(value > 0)) return 0;
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (double step : {1.0, 2.0, 5.0, 10.0})
        if (step * decade >= value * (1 - 1e-9)) return step * decade;
    return 10 * decade;
}

}  // namespace

// "Maximum" leaves out the top 5% of the samples: one slow step (often the very first) would
// otherwise flatten the rest into the baseline. Those few clip at the top, and the graph's
// corner prints the full scale and, when it is higher, the peak.
void historyGraph(const char* id, const std::deque<float>& history, float height, const char* caption, bool durations) {
    if (history.empty()) return;
    std::vector<float> samples(history.begin(), history.end());
    std::vector<float> sorted = samples;
    std::sort(sorted.begin(), sorted.end());
    const double peak = static_cast<double>(sorted.back());
    const double typicalMax = static_cast<double>(sorted[(sorted.size() - 1) * 95 / 100]);
    const double top = niceCeiling(typicalMax > 0 ? typicalMax : peak);
    // Auto-resized windows give a negative width only a few pixels: size the graph explicitly.
    const float width = std::max(ImGui::GetContentRegionAvail().x, 300.0f);
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    ImGui::PushID(id);
    ImGui::PlotLines("##history", samples.data(), static_cast<int>(samples.size()), 0, nullptr, 0.0f,
                     top > 0 ? static_cast<float>(top) : 1.0f, ImVec2(width, height));
    ImGui::PopID();
    char scale[64] = "0";
    if (top > 0) {
        char full[24], highest[24];
        if (durations) {
            formatDuration(full, sizeof full, top);
            formatDuration(highest, sizeof highest, peak);
        } else {
            std::snprintf(full, sizeof full, "%.4g", top);
            std::snprintf(highest, sizeof highest, "%.4g", peak);
        }
        if (peak > top) std::snprintf(scale, sizeof scale, "0..%s, peak %s", full, highest);
        else std::snprintf(scale, sizeof scale, "0..%s", full);
    }
    // Captions on a dark backing, so the curve under them does not garble them.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 backing = ImGui::GetColorU32(ImGuiCol_WindowBg, 0.8f);
    const ImVec2 scaleSize = ImGui::CalcTextSize(scale);
    const ImVec2 scaleAt(corner.x + width - scaleSize.x - 3, corner.y + 1);
    draw->AddRectFilled(ImVec2(scaleAt.x - 2, scaleAt.y), ImVec2(scaleAt.x + scaleSize.x + 1, scaleAt.y + scaleSize.y), backing);
    draw->AddText(scaleAt, ImGui::GetColorU32(ImGuiCol_TextDisabled), scale);
    if (caption) {
        const ImVec2 captionSize = ImGui::CalcTextSize(caption);
        const ImVec2 captionAt(corner.x + 3, corner.y + 1);
        draw->AddRectFilled(ImVec2(captionAt.x - 1, captionAt.y), ImVec2(captionAt.x + captionSize.x + 2, captionAt.y + captionSize.y),
                            backing);
        draw->AddText(captionAt, ImGui::GetColorU32(ImGuiCol_Text), caption);
    }
}

void ImGuiPanel::text(const std::string& line) { ImGui::TextWrapped("%s", line.c_str()); }
bool ImGuiPanel::checkbox(const std::string& label, bool& value) { return ImGui::Checkbox(label.c_str(), &value); }
bool ImGuiPanel::sliderFloat(const std::string& label, float& value, float min, float max) {
    return ImGui::SliderFloat(label.c_str(), &value, min, max);
}
bool ImGuiPanel::sliderInt(const std::string& label, int& value, int min, int max) {
    return ImGui::SliderInt(label.c_str(), &value, min, max);
}
bool ImGuiPanel::button(const std::string& label) { return ImGui::Button(label.c_str()); }
bool ImGuiPanel::combo(const std::string& label, int& index, const char* const* items, int count) {
    return ImGui::Combo(label.c_str(), &index, items, count);
}

void drawShell(DemoState& state, ViewOptions& view, Camera& camera, const ShellInfo& info, DebugTools& tools) {
    if (view.showHelp) helpOverlay();
    if (!view.showPanel) return;
    World& world = state.world();
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(370, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin(kMainWindow, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(info.title.c_str());
    ImGui::TextDisabled("%s  %.0f fps  (F1: hotkeys)", info.adapter.c_str(), static_cast<double>(info.framesPerSecond));

    const auto& scenes = state.scenes();
    const SceneEntry* current = state.scene();
    if (ImGui::BeginCombo("scene", current ? current->name.c_str() : world.name.c_str())) {
        std::string category;
        for (size_t i = 0; i < scenes.size(); ++i) {
            if (scenes[i]->category != category) {
                category = scenes[i]->category;
                ImGui::TextDisabled("%s", category.c_str());
            }
            if (ImGui::Selectable(scenes[i]->name.c_str(), static_cast<int>(i) == state.sceneIndex())) {
                state.loadScene(static_cast<int>(i));
                frameScene(camera, state.initialFraming(), view, ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
            }
        }
        ImGui::EndCombo();
    }
    if (current && !current->observe.empty()) ImGui::TextWrapped("Observe: %s", current->observe.c_str());
    if (!state.loadError.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", state.loadError.c_str());

    if (ImGui::Button(state.paused() ? "Run" : "Pause")) state.setPaused(!state.paused());
    ImGui::SameLine();
    if (ImGui::Button("Step")) {
        state.setPaused(true);
        state.step();
    }
    ImGui::SameLine();
    if (ImGui::Button("Restart")) state.reload();
    ImGui::SliderFloat("time scale", &state.timeScale, 0.05f, 4.0f, "%.2fx");
    ImGui::Text("t = %.2f s  frame %ld  bodies %d (%d dynamic)  contacts %d", static_cast<double>(world.time), world.frame,
                static_cast<int>(world.bodies.size()), world.dynamicBodyCount(), static_cast<int>(world.contacts.size()));

    pipelineSection(state);
    settingsSection(world, state.chapter(), state.registry().lastChapter());
    if (ImGui::CollapsingHeader("View")) {
        ImGui::Checkbox("wireframe (Z)", &view.wireframe);
        ImGui::SliderFloat("line width (px)", &view.lineWidth, 1.0f, 8.0f, "%.1f");
        ImGui::Checkbox("grid (G)", &view.showGrid);
        ImGui::SameLine();
        bool contacts = state.views.contactPoints || state.views.contactNormals;
        if (ImGui::Checkbox("contacts", &contacts)) state.views.contactPoints = state.views.contactNormals = contacts;
        if (chapterReading("solver") <= state.chapter()) {
            ImGui::SameLine();
            ImGui::Checkbox("impulses", &view.showImpulses);
        }
        ImGui::SameLine();
        ImGui::Checkbox("labels", &view.showLabels);
        int mode = camera.mode == Camera::Mode::Orbit ? 0 : 1;
        const char* const modes[] = {"orbit", "fly"};
        if (ImGui::Combo("camera (C)", &mode, modes, 2)) camera.setMode(mode == 0 ? Camera::Mode::Orbit : Camera::Mode::Fly);
    }
    if (SceneView* sceneView = state.view();
        sceneView && sceneView->hasPanel() && ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) {
        ImGuiPanel panel;
        sceneView->panel(world, panel);
    }
    ImGui::End();
    drawDebugger(state, view, tools);
}

bool handleInput(DemoState& state, ViewOptions& view, Camera& camera, DebugTools& tools, float viewportHeight, float seconds) {
    ImGuiIO& io = ImGui::GetIO();
    bool reframe = false;
    // Contact debug mode: hold Space while the scene runs and it stops at the
    // first new contact; Left Alt lets it go on. 1.86 has no left/right Alt codes: either Alt.
    const bool holdToStop = !io.WantCaptureKeyboard && down(STEPWISE_KEY(VK_SPACE, ImGuiKey_Space));
    state.session().rules.stopOnNewContact = tools.stopOnNewContact || holdToStop;
    if (!io.WantCaptureKeyboard) {
        if (pressed(STEPWISE_KEY(VK_F1, ImGuiKey_F1))) view.showHelp = !view.showHelp;
        if (pressed(STEPWISE_KEY(VK_F2, ImGuiKey_F2))) view.showPanel = !view.showPanel;
        if (pressed(STEPWISE_KEY('P', ImGuiKey_P))) state.setPaused(!state.paused());
        if (pressed(STEPWISE_KEY(VK_MENU, ImGuiKey_LeftAlt))) state.setPaused(false);
        if (pressed(STEPWISE_KEY('N', ImGuiKey_N)) || pressed(STEPWISE_KEY(VK_RIGHT, ImGuiKey_RightArrow))) {
            state.setPaused(true);
            state.step();
        }
        if (pressed(STEPWISE_KEY(VK_LEFT, ImGuiKey_LeftArrow)) && !state.session().history().empty())
            state.rewindTo(std::max(state.session().history().oldestFrame(), state.world().frame - 1));
        // With a body selected, W and E are the editors' gizmo keys; the fly keys wait for a deselect.
        const bool selected = state.selectedBody >= 0;
        if (selected && pressed(STEPWISE_KEY('W', ImGuiKey_W))) tools.gizmo.mode = Gizmo::Mode::Translate;
        if (selected && pressed(STEPWISE_KEY('E', ImGuiKey_E))) tools.gizmo.mode = Gizmo::Mode::Rotate;
        if (pressed(STEPWISE_KEY(VK_ESCAPE, ImGuiKey_Escape))) {
            state.selectedBody = -1;
            state.selectHit(HitSelection());
        }
        if (pressed(STEPWISE_KEY('R', ImGuiKey_R))) state.reload();
        const int count = static_cast<int>(state.scenes().size());
        if (count > 0 && pressed(STEPWISE_KEY(VK_NEXT, ImGuiKey_PageDown))) {
            state.loadScene((state.sceneIndex() + 1) % count);
            reframe = true;
        }
        if (count > 0 && pressed(STEPWISE_KEY(VK_PRIOR, ImGuiKey_PageUp))) {
            state.loadScene((state.sceneIndex() + count - 1) % count);
            reframe = true;
        }
        if (pressed(STEPWISE_KEY('F', ImGuiKey_F))) reframe = true;
        if (pressed(STEPWISE_KEY('C', ImGuiKey_C))) {
            camera.setMode(camera.mode == Camera::Mode::Orbit ? Camera::Mode::Fly : Camera::Mode::Orbit);
        }
        if (pressed(STEPWISE_KEY('Z', ImGuiKey_Z))) view.wireframe = !view.wireframe;
        if (pressed(STEPWISE_KEY('G', ImGuiKey_G))) view.showGrid = !view.showGrid;
        const float speed = std::max(2.0f, 0.5f * camera.distance) * seconds * (io.KeyShift ? 4.0f : 1.0f);
        const auto key = [&](int code) { return !selected && down(code); };
        const float forward = (key(STEPWISE_KEY('W', ImGuiKey_W)) ? 1.0f : 0.0f) - (key(STEPWISE_KEY('S', ImGuiKey_S)) ? 1.0f : 0.0f);
        const float right = (key(STEPWISE_KEY('D', ImGuiKey_D)) ? 1.0f : 0.0f) - (key(STEPWISE_KEY('A', ImGuiKey_A)) ? 1.0f : 0.0f);
        const float up = (key(STEPWISE_KEY('E', ImGuiKey_E)) ? 1.0f : 0.0f) - (key(STEPWISE_KEY('Q', ImGuiKey_Q)) ? 1.0f : 0.0f);
        if (forward != 0 || right != 0 || up != 0) camera.move(forward * speed, right * speed, up * speed);
    }
    if (!io.WantCaptureMouse) {
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f)) camera.orbit(-io.MouseDelta.x * 0.006f, io.MouseDelta.y * 0.006f);
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f)) camera.pan(io.MouseDelta.x, io.MouseDelta.y, viewportHeight);
        if (io.MouseWheel != 0) camera.zoom(io.MouseWheel);
    }
    return reframe;
}

void drawLabels(const DrawList& list, const Camera& camera, float width, float height) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    for (const TextLabel& label : list.labels) {
        float x = 0, y = 0;
        if (!camera.project(label.at.cast<float>(), width, height, x, y)) continue;
        draw->AddText(ImVec2(x, y), ImGui::GetColorU32(ImVec4(label.color.r, label.color.g, label.color.b, label.color.a)),
                      label.message.c_str());
    }
}

bool shellRect(float rect[4]) {
    ImGuiWindow* window = ImGui::FindWindowByName(kMainWindow);
    if (!window || !window->WasActive) return false;
    rect[0] = window->Pos.x;
    rect[1] = window->Pos.y;
    rect[2] = window->Pos.x + window->Size.x;
    rect[3] = window->Pos.y + window->Size.y;
    return true;
}

namespace {

/// A label's width in pixels. The window path frames the scene once before its first ImGui frame,
/// when ImGui has no current font yet (CalcTextSize would read through a null font): then the
/// atlas's first font measures it, or, before the atlas has one, 7 px a character.
float labelWidth(const char* text) {
    if (ImGui::GetCurrentContext() && ImGui::GetFont()) return ImGui::CalcTextSize(text).x;
    if (ImGui::GetCurrentContext() && !ImGui::GetIO().Fonts->Fonts.empty()) {
        ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
        return font->CalcTextSizeA(font->FontSize, 1e30f, 0.0f, text).x;
    }
    return 7.0f * static_cast<float>(std::strlen(text));
}

}  // namespace

void frameScene(Camera& camera, const Framing& framing, const ViewOptions& view, float width, float height) {
    // The panel's right edge (it sits at the left) and the debugger's left edge (it sits at the
    // right); 8 px of air between them and the scene.
    constexpr float kUsualPanelRight = 405, kUsualDebuggerWidth = 366;
    const float viewWidth = std::max(width, 1.0f), aspect = viewWidth / std::max(height, 1.0f);
    float left = 0, right = viewWidth;
    if (view.showPanel) {
        float rect[4];
        left = (shellRect(rect) ? rect[2] : kUsualPanelRight) + 8;
        if (debuggerRect(rect)) right = rect[0] - 8;
        else if (view.debuggerOpen && !ImGui::FindWindowByName("Debugger")) right = viewWidth - kUsualDebuggerWidth;
    }
    // In a window too narrow for all three, frame for the whole view: F2 hides the shell.
    const float leftFraction = left < 0.6f * viewWidth ? left / viewWidth : 0.0f;
    float rightFraction = right - left > 0.3f * viewWidth ? right / viewWidth : 1.0f;
    camera.frame(framing.bounds, aspect, leftFraction, rightFraction);
    // Labels run right from their anchors: while one ends past the right edge, give the
    // scene that much less room and frame again (a few rounds settle it).
    for (int round = 0; round < 4; ++round) {
        float overflow = 0;
        for (const TextLabel& label : framing.labels) {
            float x = 0, y = 0;
            if (!camera.project(label.at.cast<float>(), viewWidth, height, x, y)) continue;
            overflow = std::max(overflow, x + labelWidth(label.message.c_str()) + 8 - right);
        }
        const float narrower = std::max(rightFraction - 1.1f * overflow / viewWidth, leftFraction + 0.25f);
        if (overflow <= 0 || narrower >= rightFraction) break;
        rightFraction = narrower;
        camera.frame(framing.bounds, aspect, leftFraction, rightFraction);
    }
}

}  // namespace stepwise::render
