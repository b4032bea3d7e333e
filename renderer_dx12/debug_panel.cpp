#include "debug_panel.h"

#include "09_debug/recording.h"
#include "hit_tree_panel.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace stepwise::render {

namespace {

const char* const kDebuggerWindow = "Debugger";
constexpr float kDebuggerWidth = 350;
const char* const kSectionNames[DebugTools::kSectionCount] = {"session", "views", "hits", "inspector", "perf"};

std::string bodyName(const World& world, int body) {
    return body >= 0 && body < static_cast<int>(world.bodies.size()) ? world.bodies[static_cast<std::size_t>(body)].name : "?";
}

void sessionSection(DemoState& state, DebugTools& tools) {
    DebugSession& session = state.session();
    ImGui::Checkbox("simulation enabled", &session.simulationEnabled);
    ImGui::SameLine();
    ImGui::Checkbox("stop on new contact", &tools.stopOnNewContact);

    // Rows keep their places whatever the state (a button that came and went would move the
    // timeline under the mouse): run control and status, timeline, steps, resume and save.
    if (ImGui::Button(state.paused() ? "Continue (Alt)" : "Pause (P)")) state.setPaused(!state.paused());
    ImGui::SameLine();
    const History& history = session.history();
    const long frame = state.world().frame;
    if (!session.rewound())
        ImGui::TextColored(ImVec4(0.45f, 0.9f, 0.45f, 1), "LIVE frame %ld", frame);
    else if (state.speculativeSteps() > 0)
        ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "SPECULATIVE %ld (+%d), live %ld", frame, state.speculativeSteps(),
                           session.liveFrame());
    else
        ImGui::TextColored(ImVec4(0.5f, 0.75f, 1, 1), "REWOUND frame %ld (%ld..%ld)", frame, history.oldestFrame(),
                           history.newestFrame());

    // The timeline: every kept frame, the live one at the right end.
    int shown = static_cast<int>(std::clamp(frame, history.oldestFrame(), history.newestFrame()));
    ImGui::SetNextItemWidth(-1);
    if (!history.empty() && ImGui::SliderInt("##timeline", &shown, static_cast<int>(history.oldestFrame()),
                                             static_cast<int>(history.newestFrame()), "frame %d"))
        state.rewindTo(shown);
    if (ImGui::Button("<< back")) state.rewindTo(std::max(history.oldestFrame(), frame - 1));
    ImGui::SameLine();
    // Forward walks the kept frames; past the newest, or off a speculative branch, it has to step.
    if (ImGui::Button("forward >>")) {
        if (session.rewound() && state.speculativeSteps() == 0 && frame < history.newestFrame()) state.rewindTo(frame + 1);
        else {
            state.setPaused(true);
            state.step();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("speculative step")) {
        if (!session.rewound()) state.rewindTo(history.newestFrame());
        state.setPaused(true);
        state.step();
    }
    ImGui::BeginDisabled(!session.rewound());
    if (ImGui::Button("Resume live")) state.resume();
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Save recording")) {
        tools.recordingMessage = saveRecording(state);
        const std::string saved = recordingPathOf(state);  // what "Load recording" offers next
        std::snprintf(tools.recordingPath, sizeof tools.recordingPath, "%s", saved.c_str());
    }
    ImGui::SetNextItemWidth(220);
    ImGui::InputText("##recording", tools.recordingPath, sizeof tools.recordingPath);
    ImGui::SameLine();
    if (ImGui::Button("Load recording")) tools.recordingMessage = replayRecording(state, tools.recordingPath);
    ImGui::TextDisabled("history %d/%d frames, %.1f MB", history.size(), history.capacity(),
                        static_cast<double>(history.bytes()) / (1024.0 * 1024.0));
    if (!tools.recordingMessage.empty()) ImGui::TextWrapped("%s", tools.recordingMessage.c_str());
    if (session.lastStop() == StopReason::NewContact && state.paused()) {
        for (const BodyPair& pair : session.newContacts())
            ImGui::TextColored(ImVec4(1, 0.85f, 0.3f, 1), "stopped: new contact %s / %s", bodyName(state.world(), pair.bodyA).c_str(),
                               bodyName(state.world(), pair.bodyB).c_str());
    }
}

void viewsSection(DemoState& state, ViewOptions& view) {
    DebugViews& views = state.views;
    ImGui::Checkbox("colliders", &views.colliders);
    ImGui::SameLine(170);
    ImGui::Checkbox("selection wireframe", &views.wireframeSelection);
    ImGui::Checkbox("contact points", &views.contactPoints);
    ImGui::SameLine(170);
    ImGui::Checkbox("contact normals", &views.contactNormals);
    ImGui::Checkbox("EPA face", &views.epaFace);
    ImGui::SameLine(170);
    ImGui::Checkbox("GJK simplex", &views.gjkSimplex);
    ImGui::Checkbox("Minkowski A - B", &views.minkowski);
    ImGui::SameLine(170);
    ImGui::Checkbox("bounds", &views.bounds);
    ImGui::Checkbox("joints", &views.joints);
    ImGui::SameLine(170);
    ImGui::Checkbox("impulses", &view.showImpulses);
    ImGui::Checkbox("wireframe, all (Z)", &view.wireframe);
    ImGui::SliderFloat("line px", &view.lineWidth, 1.0f, 8.0f, "%.1f");
    if (view.showImpulses && views.contactNormals) ImGui::TextDisabled("normals: the impulse arrows take their place");
    for (DemoState::OverlayView& overlay : state.chapterViews) {
        ImGui::PushID(overlay.overlay->name.c_str());
        ImGui::Checkbox(overlay.overlay->name.c_str(), &overlay.on);
        if (overlay.on && overlay.overlay->levels > 0) {
            ImGui::SameLine(170);
            ImGui::SetNextItemWidth(120);
            ImGui::SliderInt("level", &overlay.level, 0, overlay.overlay->levels - 1);
        }
        if (overlay.on) ImGui::TextDisabled("%s", overlay.overlay->help.c_str());
        ImGui::PopID();
    }
    if (views.epaFace || views.gjkSimplex || views.minkowski) {
        const BodyPair pair = chosenPair(state.world(), state.hitTree(), state.hitSelection(), state.selectedBody);
        ImGui::TextDisabled("pair: %s / %s (click to choose)", bodyName(state.world(), pair.bodyA).c_str(),
                            bodyName(state.world(), pair.bodyB).c_str());
    }
}

void gizmoModeButtons(Gizmo& gizmo) {
    int mode = gizmo.mode == Gizmo::Mode::Translate ? 0 : 1;
    ImGui::TextUnformatted("gizmo");
    ImGui::SameLine();
    ImGui::RadioButton("move (W)", &mode, 0);
    ImGui::SameLine();
    ImGui::RadioButton("turn (E)", &mode, 1);
    gizmo.mode = mode == 0 ? Gizmo::Mode::Translate : Gizmo::Mode::Rotate;
}

bool header(const char* label, DebugTools& tools, DebugTools::Section section, bool defaultOpen) {
    if (tools.openRequest[section]) {
        ImGui::SetNextItemOpen(true);
        tools.openRequest[section] = false;
    }
    return ImGui::CollapsingHeader(label, defaultOpen ? ImGuiTreeNodeFlags_DefaultOpen : 0);
}

}  // namespace

int sectionByName(const std::string& name) {
    for (int i = 0; i < DebugTools::kSectionCount; ++i)
        if (name == kSectionNames[i]) return i;
    return -1;
}

// A recording from any build of the same precision (this one, the Linux `stepwise record`, another
// machine's demo) replays here frame by frame, as `stepwise replay` does: every hash met, or the
// first frame and body where the runs part.
std::string replayRecording(const DemoState& state, const std::string& path) {
    try {
        const Recording recording = readRecordingFile(path);
        const ReplayResult result = replay(state.registry(), recording);
        if (result.firstMismatch < 0)
            return "replayed " + std::to_string(result.frames) + " frames of " + path + ": every state hash met";
        std::string where = "frame " + std::to_string(result.firstMismatch);
        if (result.firstBody >= 0) {
            const World start = startingWorld(state.registry(), recording);
            where += ", body " + bodyName(start, result.firstBody);
        }
        return "the replay of " + path + " parts from the recording at " + where;
    } catch (const std::exception& error) {
        return std::string("could not replay: ") + error.what();
    }
}

std::string recordingPathOf(const DemoState& state) {
    std::string scene = state.scene() ? state.scene()->name : state.world().name;
    for (char& c : scene)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '-';
    return "out/recording-" + (scene.empty() ? std::string("scene") : scene) + ".json";
}

std::string saveRecording(const DemoState& state) {
    const std::string path = recordingPathOf(state);
    try {
        std::filesystem::create_directories("out");
        const Recording recording = recordingOf(state.session(), state.chapter());
        writeRecordingFile(path, recording);
        return "wrote " + path + " (" + std::to_string(recording.frameHashes.size()) + " frames, " +
               std::to_string(recording.edits.size()) + " edits)";
    } catch (const std::exception& error) {
        return std::string("could not save: ") + error.what();
    }
}

void drawDebugger(DemoState& state, ViewOptions& view, DebugTools& tools) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x - 8, 8), ImGuiCond_Always, ImVec2(1, 0));
    ImGui::SetNextWindowSizeConstraints(ImVec2(kDebuggerWidth, 0), ImVec2(kDebuggerWidth, std::max(display.y - 16, 100.0f)));
    ImGui::SetNextWindowCollapsed(!view.debuggerOpen, ImGuiCond_Once);
    if (state.revealSelection) {
        ImGui::SetNextWindowCollapsed(false);
        tools.openRequest[DebugTools::HitResults] = true;
    }
    // Not focused on appearing: the main panel keeps the focus (and its title-bar colour).
    const bool expanded = ImGui::Begin(kDebuggerWindow, nullptr,
                                       ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoMove);
    view.debuggerOpen = expanded;
    if (expanded) {
        if (header("Session and history", tools, DebugTools::Session, true)) sessionSection(state, tools);
        if (header("Views", tools, DebugTools::Views, true)) viewsSection(state, view);
        if (header("Hit results", tools, DebugTools::HitResults, false)) hitTreeSection(state);
        else state.revealSelection = false;
        if (state.selectedBody >= 0 && tools.inspector.body != state.selectedBody) tools.openRequest[DebugTools::InspectorSection] = true;
        if (header("Inspector", tools, DebugTools::InspectorSection, false)) {
            inspectorSection(tools.inspector, state);
            if (state.selectedBody >= 0) gizmoModeButtons(tools.gizmo);
        }
        else if (state.selectedBody != tools.inspector.body) tools.inspector.body = -1;
        if (header("Performance", tools, DebugTools::Performance, false)) perfSection(tools.perf, state);
    }
    ImGui::End();
}

bool debuggerRect(float rect[4]) {
    ImGuiWindow* window = ImGui::FindWindowByName(kDebuggerWindow);
    if (!window || !window->WasActive || window->Collapsed) return false;
    rect[0] = window->Pos.x;
    rect[1] = window->Pos.y;
    rect[2] = window->Pos.x + window->Size.x;
    rect[3] = window->Pos.y + window->Size.y;
    return true;
}

}  // namespace stepwise::render
