#pragma once
// The performance monitor: what each displayed frame cost. Wall time and frames per second say
// how smooth the demo is; the process's CPU time per frame (all its threads, from the OS) says
// how much of that the program itself burned, as opposed to waiting on the GPU or the vsync;
// the pipeline's stage timings say where the physics part went.

#include "demo_state.h"

#include <deque>

namespace stepwise::render {

class PerfMonitor {
public:
    static constexpr std::size_t kSamples = 240;   // four seconds at 60 frames per second

    /// One displayed frame that took `wallSeconds`; reads the process CPU time since the last call.
    void sample(double wallSeconds);

    const std::deque<float>& frameMs() const { return frameMs_; }
    const std::deque<float>& framesPerSecond() const { return fps_; }
    const std::deque<float>& cpuMs() const { return cpuMs_; }

private:
    std::deque<float> frameMs_, fps_, cpuMs_;
    double lastCpuSeconds_ = -1;
};

/// The monitor's section of the debugger window: one graph per measure and per pipeline stage.
void perfSection(const PerfMonitor& monitor, DemoState& state);

}  // namespace stepwise::render
