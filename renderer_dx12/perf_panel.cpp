#include "perf_panel.h"

#include "dx_common.h"
#include "ui_shell.h"

#include <imgui.h>

#include <cstdio>

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
    if (cpu >= 0 && lastCpuSeconds_ >= 0) push(cpuMs_, float(1000.0 * (cpu - lastCpuSeconds_)));
    lastCpuSeconds_ = cpu;
}

void perfSection(const PerfMonitor& monitor, DemoState& state) {
    char caption[64], duration[24];
    if (monitor.frameMs().empty()) {
        ImGui::TextDisabled("no frames measured yet");
        return;
    }
    formatDuration(duration, sizeof duration, mean(monitor.frameMs()));
    std::snprintf(caption, sizeof caption, "frame time, mean %s", duration);
    historyGraph("##frame", monitor.frameMs(), 36, caption);
    std::snprintf(caption, sizeof caption, "frames per second, mean %.1f", mean(monitor.framesPerSecond()));
    historyGraph("##fps", monitor.framesPerSecond(), 36, caption, false);
    if (!monitor.cpuMs().empty()) {
        formatDuration(duration, sizeof duration, mean(monitor.cpuMs()));
        std::snprintf(caption, sizeof caption, "process CPU per frame, mean %s", duration);
        historyGraph("##cpu", monitor.cpuMs(), 36, caption);
    }
    ImGui::TextDisabled("physics, per step and per stage:");
    if (!state.frameHistory.empty()) {
        formatDuration(duration, sizeof duration, mean(state.frameHistory));
        std::snprintf(caption, sizeof caption, "whole step, mean %s", duration);
        historyGraph("##step", state.frameHistory, 28, caption);
    }
    for (const Stage& stage : state.pipeline().stages()) {
        const auto found = state.stageHistory.find(stage.name);
        if (found == state.stageHistory.end()) continue;
        formatDuration(duration, sizeof duration, mean(found->second));
        std::snprintf(caption, sizeof caption, "%s, mean %s", stage.name.c_str(), duration);
        historyGraph(stage.name.c_str(), found->second, 20, caption);
    }
}

}  // namespace stepwise::render
