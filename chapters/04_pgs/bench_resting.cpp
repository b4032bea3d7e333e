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

namespace stepwise {

namespace {

void measureResting(BenchRun& run) {
    const Settings defaults;
    const int frames = static_cast<int>(std::lround((run.quick() ? 3.0 : 10.0) / static_cast<double>(defaults.dt)));
    run.progress().stage("4 resting runs of " + std::to_string(frames) + " frames", 4);
    std::vector<RestingRun> runs;
    const std::pair<RestingSubject, StepOrder> cases[] = {{RestingSubject::Ball, StepOrder::SplitIntegration},
                                                          {RestingSubject::Ball, StepOrder::IntegrateFirst},
                                                          {RestingSubject::Box, StepOrder::SplitIntegration},
                                                          {RestingSubject::Stack, StepOrder::SplitIntegration}};
    for (const auto& [subject, order] : cases) {
        runs.push_back(runRestingStudy({subject, order}, frames));
        run.progress().advance();
    }
    run.progress().endStage();

    CsvTable series({"time_s", "ball_split_depth", "ball_first_depth", "box_depth", "stack_bottom_depth", "box_tilt"});
    for (int frame = 0; frame < frames; ++frame)
        series.addRow({formatNumber((frame + 1) * static_cast<double>(defaults.dt)), formatNumber(runs[0].depth[frame]),
                       formatNumber(runs[1].depth[frame]), formatNumber(runs[2].depth[frame]),
                       formatNumber(runs[3].depth[frame]), formatNumber(runs[2].tilt[frame])});

    // Summary over the second half of the run, when the body has settled (or keeps jittering).
    CsvTable summary({"run", "mean_depth_m", "min_depth_m", "max_depth_m", "max_tilt_rad", "drift_m"});
    for (const RestingRun& resting : runs) {
        const auto begin = resting.depth.begin() + frames / 2;
        double sum = 0;
        for (auto it = begin; it != resting.depth.end(); ++it) sum += *it;
        const double count = static_cast<double>(resting.depth.end() - begin);
        const double maxTilt = *std::max_element(resting.tilt.begin() + frames / 2, resting.tilt.end());
        summary.addRow({resting.label, formatNumber(sum / count), formatNumber(resting.minDepth(frames / 2)),
                        formatNumber(resting.maxDepth(frames / 2)), formatNumber(maxTilt),
                        formatNumber(resting.drift(0))});
    }
    run.out() << "slop " << defaults.slop << " m, baumgarte " << defaults.baumgarte << ", dt " << defaults.dt
              << " s; settled half of " << frames << " frames:\n"
              << summary.toText();

    PlotSpec plot("Resting on the ground at 60 Hz, 10 iterations: penetration after each frame", "time (s)",
                  "penetration (m)", false, false);
    plot.caption = "Bodies dropped from 1 cm onto the ground; the overlap with what is below them at the end of "
                   "each frame, measured by chapter 3's narrowphase. The ball settles at the slop when integration "
                   "is split around the solve and deeper when it integrates first; the box, held by one contact "
                   "point at a time, keeps rocking; a 1 kg ball under a 10 kg one is pressed deeper than the slop.";
    for (const RestingRun& resting : runs) {
        PlotSeries line(resting.label);
        line.lineOnly = true;
        line.y = resting.depth;
        for (int frame = 0; frame < frames; ++frame) line.x.push_back((frame + 1) * static_cast<double>(defaults.dt));
        plot.series.push_back(line);
    }
    PlotSeries slop("slop");
    slop.lineOnly = true;
    slop.dashed = true;
    slop.x = {0.0, frames * static_cast<double>(defaults.dt)};
    slop.y = {static_cast<double>(defaults.slop), static_cast<double>(defaults.slop)};
    plot.series.push_back(slop);
    run.writeCsv(series);
    run.writePlot(plot);
}

}  // namespace

BenchEntry restingBench() {
    return benchEntry(4, measureResting, R"(
        resting: chapter 4: penetration of a resting ball and box over time, split vs
            integrate-first step order (one-point box jitter)
        resting.csv  per frame: penetration of each run and the box's tilt
        resting.svg  plot: penetration over time, with the slop)");
}

}  // namespace stepwise
