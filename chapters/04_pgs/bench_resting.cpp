// `stepwise bench resting`: bodies dropped from 1 cm onto the ground at the default 60 Hz and 10
// iterations. Per frame it records the penetration at the end of the frame, measured by chapter
// 3's narrowphase (independent of the stages), and the box's tilt. It shows what the page
// discusses: where each step order lets a resting ball settle, the jitter of a box held by one
// contact point, and how deep a 1 kg ball is pressed by a 10 kg ball on top of it.
#include "04_pgs/benches.h"

#include "04_pgs/resting_study.h"
#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace stepwise {

int runRestingBench(const BenchOptions& options) {
    if (!benchOutputsWritable(options, "resting")) return 2;
    std::ostream& out = options.out ? *options.out : std::cout;
    const Settings defaults;
    const int frames = static_cast<int>(std::lround((options.quick ? 3.0 : 10.0) / static_cast<double>(defaults.dt)));
    std::vector<RestingRun> runs;
    runs.push_back(runRestingStudy({RestingSubject::Ball, StepOrder::SplitIntegration}, frames));
    runs.push_back(runRestingStudy({RestingSubject::Ball, StepOrder::IntegrateFirst}, frames));
    runs.push_back(runRestingStudy({RestingSubject::Box, StepOrder::SplitIntegration}, frames));
    runs.push_back(runRestingStudy({RestingSubject::Stack, StepOrder::SplitIntegration}, frames));

    CsvTable series({"time_s", "ball_split_depth", "ball_first_depth", "box_depth", "stack_bottom_depth", "box_tilt"});
    for (int frame = 0; frame < frames; ++frame)
        series.addRow({formatNumber((frame + 1) * static_cast<double>(defaults.dt)), formatNumber(runs[0].depth[frame]),
                       formatNumber(runs[1].depth[frame]), formatNumber(runs[2].depth[frame]),
                       formatNumber(runs[3].depth[frame]), formatNumber(runs[2].tilt[frame])});

    // Summary over the second half of the run, when the body has settled (or keeps jittering).
    CsvTable summary({"run", "mean_depth_m", "min_depth_m", "max_depth_m", "max_tilt_rad", "drift_m"});
    for (const RestingRun& run : runs) {
        const auto begin = run.depth.begin() + frames / 2;
        double sum = 0;
        for (auto it = begin; it != run.depth.end(); ++it) sum += *it;
        const double count = static_cast<double>(run.depth.end() - begin);
        const double maxTilt = *std::max_element(run.tilt.begin() + frames / 2, run.tilt.end());
        summary.addRow({run.label, formatNumber(sum / count), formatNumber(run.minDepth(frames / 2)),
                        formatNumber(run.maxDepth(frames / 2)), formatNumber(maxTilt), formatNumber(run.drift(0))});
    }
    out << "slop " << defaults.slop << " m, baumgarte " << defaults.baumgarte << ", dt " << defaults.dt
        << " s; settled half of " << frames << " frames:\n"
        << summary.toText();

    PlotSpec plot;
    plot.title = "Resting on the ground at 60 Hz, 10 iterations: penetration after each frame";
    plot.xLabel = "time (s)";
    plot.yLabel = "penetration (m)";
    plot.logX = false;
    plot.logY = false;
    for (const RestingRun& run : runs) {
        PlotSeries line{run.label, {}, run.depth, false};
        for (int frame = 0; frame < frames; ++frame) line.x.push_back((frame + 1) * static_cast<double>(defaults.dt));
        plot.series.push_back(line);
    }
    plot.series.push_back(PlotSeries{"slop", {0.0, frames * static_cast<double>(defaults.dt)},
                                     {static_cast<double>(defaults.slop), static_cast<double>(defaults.slop)}, false});
    try {
        if (!options.csvPath.empty()) series.write(options.csvPath);
        if (!options.plotPath.empty()) writeSvgPlot(options.plotPath, plot);
    } catch (const std::runtime_error& error) {
        std::cerr << "error: bench resting: " << error.what() << "\n";
        return 2;
    }
    return 0;
}

}  // namespace stepwise
