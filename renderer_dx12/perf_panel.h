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
    /// The OS counts process CPU time in scheduler ticks (15.6 ms on Windows, 10 ms under wine),
    /// coarser than a frame: per frame it reads 0 or a whole tick. Its mean over this many frames
    /// is what the graph shows.
    static constexpr std::size_t kCpuWindow = 30;

    /// One displayed frame that took `wallSeconds`; reads the process CPU time since the last call.
    void sample(double wallSeconds);

    const std::deque<float>& frameMs() const { return frameMs_; }
    const std::deque<float>& framesPerSecond() const { return fps_; }
    const std::deque<float>& cpuMs() const { return cpuMs_; }

private:
    std::deque<float> frameMs_, fps_, cpuMs_;
    std::deque<double> cpuSeconds_;   // the process's CPU time at the last kCpuWindow + 1 frames
};

/// The monitor's section of the debugger window: one graph per measure and per pipeline stage.
void perfSection(const PerfMonitor& monitor, DemoState& state);

}  // namespace stepwise::render
