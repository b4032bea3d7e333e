#include "perf_panel.h"

#include "dx_common.h"
#include "ui_shell.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace stepwise::render {

namespace {

/// CPU time the whole process has used so far (kernel and user, all threads), seconds.
double processCpuSeconds() {
    FILETIME created, exited, kernel, user;
    if (!GetProcessTimes(GetCurrentProcess(), &created, &exited, &kernel, &user)) return -1;
    const auto seconds = [](const FILETIME& time) {
        const ULONGLONG ticks = (ULONGLONG(time.dwHighDateTime) << 32) | time.dwLowDateTime;
        return double(ticks) * 1e-7;   // FILETIME counts 100 ns ticks
    };
    return seconds(kernel) + seconds(user);
}

void push(std::deque<float>& history, float value) {
    history.push_back(value);
    if (history.size() > PerfMonitor::kSamples) history.pop_front();
}

double mean(const std::deque<float>& history) {
    double sum = 0;
    for (float value : history) sum += double(value);
    return history.empty() ? 0.0 : sum / double(history.size());
}

}  // namespace

void PerfMonitor::sample(double wallSeconds) {
    if (!(wallSeconds > 0)) return;
    push(frameMs_, float(1000.0 * wallSeconds));
    push(fps_, float(1.0 / wallSeconds));
    const double cpu = processCpuSeconds();
    if (cpu < 0) return;
    cpuSeconds_.push_back(cpu);
    if (cpuSeconds_.size() > kCpuWindow + 1) cpuSeconds_.pop_front();
    if (cpuSeconds_.size() > 1)
        push(cpuMs_, float(1000.0 * (cpuSeconds_.back() - cpuSeconds_.front()) / double(cpuSeconds_.size() - 1)));
}

namespace {

/// Physics time per step, stacked by stage: one column per step, a colour per stage, so the
/// stage that grows (the solver of a tall stack, the narrowphase of a pile) shows at a glance.
void stackedStages(DemoState& state, float height) {
    struct Series {
        const std::string* name;
        const std::deque<float>* history;
        ImU32 color;
    };
    static const ImU32 kPalette[] = {IM_COL32(90, 160, 240, 255), IM_COL32(240, 170, 60, 255), IM_COL32(120, 210, 110, 255),
                                     IM_COL32(230, 90, 90, 255),  IM_COL32(190, 120, 230, 255), IM_COL32(90, 210, 210, 255),
                                     IM_COL32(220, 220, 110, 255), IM_COL32(200, 200, 200, 255)};
    std::vector<Series> series;
    std::size_t samples = 0;
    for (const Stage& stage : state.pipeline().stages()) {
        const auto found = state.stageHistory.find(stage.name);
        if (found == state.stageHistory.end() || found->second.empty()) continue;
        series.push_back({&stage.name, &found->second, kPalette[series.size() % (sizeof kPalette / sizeof kPalette[0])]});
        samples = std::max(samples, found->second.size());
    }
    if (series.empty()) return;
    // Full scale: the 95th percentile of the step totals, as historyGraph does, so one slow step
    // does not flatten the rest.
    std::vector<float> totals(samples, 0.0f);
    for (const Series& s : series)
        for (std::size_t i = 0; i < s.history->size(); ++i) totals[samples - s.history->size() + i] += (*s.history)[i];
    std::vector<float> sorted = totals;
    std::sort(sorted.begin(), sorted.end());
    const float top = std::max(sorted[(sorted.size() - 1) * 95 / 100], 1e-6f);

    const float width = std::max(ImGui::GetContentRegionAvail().x, 200.0f);
    const ImVec2 corner = ImGui::GetCursorScreenPos();
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(corner, ImVec2(corner.x + width, corner.y + height), ImGui::GetColorU32(ImGuiCol_FrameBg));
    const float column = width / float(samples);
    for (std::size_t i = 0; i < samples; ++i) {
        float base = 0;
        for (const Series& s : series) {
            const std::size_t offset = samples - s.history->size();
            if (i < offset) continue;
            const float value = (*s.history)[i - offset];
            const float y0 = corner.y + height * (1 - std::min(base / top, 1.0f));
            base += value;
            const float y1 = corner.y + height * (1 - std::min(base / top, 1.0f));
            if (y0 - y1 >= 0.5f)
                draw->AddRectFilled(ImVec2(corner.x + column * float(i), y1), ImVec2(corner.x + column * float(i + 1), y0), s.color);
        }
    }
    ImGui::Dummy(ImVec2(width, height));
    char full[24], mean[24];
    formatDuration(full, sizeof full, double(top));
    ImGui::TextDisabled("full scale %s; mean per step:", full);
    for (const Series& s : series) {
        double sum = 0;
        for (float value : *s.history) sum += double(value);
        formatDuration(mean, sizeof mean, sum / double(s.history->size()));
        const ImVec2 at = ImGui::GetCursorScreenPos();
        const float box = ImGui::GetTextLineHeight() - 4;
        draw->AddRectFilled(ImVec2(at.x, at.y + 2), ImVec2(at.x + box, at.y + 2 + box), s.color);
        ImGui::Dummy(ImVec2(box + 2, box));
        ImGui::SameLine();
        ImGui::Text("%s %s", s.name->c_str(), mean);
    }
}

}  // namespace

void perfSection(const PerfMonitor& monitor, DemoState& state) {
    char caption[80], duration[24];
    if (monitor.frameMs().empty()) {
        ImGui::TextDisabled("no frames measured yet");
        return;
    }
    // Captions above the graphs: the graphs print their own scale in the corner.
    formatDuration(duration, sizeof duration, mean(monitor.frameMs()));
    ImGui::Text("frame time, mean %s", duration);
    historyGraph("##frame", monitor.frameMs(), 30);
    ImGui::Text("frames per second, mean %.1f", mean(monitor.framesPerSecond()));
    historyGraph("##fps", monitor.framesPerSecond(), 30, nullptr, false);
    if (!monitor.cpuMs().empty()) {
        formatDuration(duration, sizeof duration, mean(monitor.cpuMs()));
        std::snprintf(caption, sizeof caption, "process CPU / frame %s (%d-frame mean)", duration, int(PerfMonitor::kCpuWindow));
        ImGui::TextUnformatted(caption);
        historyGraph("##cpu", monitor.cpuMs(), 30);
    }
    if (!state.frameHistory.empty()) {
        formatDuration(duration, sizeof duration, mean(state.frameHistory));
        ImGui::Text("physics per step, mean %s, by stage:", duration);
        stackedStages(state, 40);
    }
}

}  // namespace stepwise::render
