// `stepwise bench resting`: a ball and a box set down on the ground (just touching, at rest), run
// with both step orders. Per frame it records the penetration at the end of the frame (measured
// by chapter 3's narrowphase, independent of the stages) and the box's tilt. It shows two things
// the page discusses: where each step order lets a resting body settle, and the jitter of a box
// held by one contact point.
#include "04_pgs/benches.h"

#include "03_epa/narrowphase.h"
#include "04_pgs/chapter.h"
#include "04_pgs/scenes.h"
#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

namespace stepwise {

namespace {

struct RestingRun {
    std::string label;
    std::vector<double> depth;      // m, per frame
    std::vector<double> tilt;       // rad between the body's up axis and +Y, per frame
    double drift = 0;               // m, horizontal distance from the start after the run
};

RestingRun runResting(bool box, StepOrder order, int frames) {
    World world;
    world.name = "resting";
    addGroundPlane(world);
    const Vec3 start(0, Real(0.5), 0);
    const int body = box ? addCrate(world, "box", start, Vec3(Real(0.5), Real(0.5), Real(0.5)), 1, Material{})
                         : addBall(world, "ball", start, Real(0.5), 1, Material{});
    Pipeline pipeline = makeChapter04Pipeline(world, order);
    RestingRun run;
    run.label = std::string(box ? "box" : "ball") + ", " +
                (order == StepOrder::SplitIntegration ? "split integration" : "integrate first");
    for (int frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        const Body& ground = world.bodies[0];
        const Body& moving = world.bodies[body];
        const ContactQuery query = collideShapes(ground.shape, ground.transform, moving.shape, moving.transform);
        run.depth.push_back(query.intersect ? static_cast<double>(query.depth) : 0.0);
        const Vec3 up = moving.transform.rotate(Vec3::UnitY());
        run.tilt.push_back(std::acos(std::clamp(static_cast<double>(up.y()), -1.0, 1.0)));
    }
    const Vec3 offset = world.bodies[body].transform.position - start;
    run.drift = std::hypot(static_cast<double>(offset.x()), static_cast<double>(offset.z()));
    return run;
}

}  // namespace

int runRestingBench(const BenchOptions& options) {
    if (!benchOutputsWritable(options, "resting")) return 2;
    std::ostream& out = options.out ? *options.out : std::cout;
    const Settings defaults;
    const int frames = static_cast<int>(std::lround((options.quick ? 3.0 : 10.0) / static_cast<double>(defaults.dt)));
    std::vector<RestingRun> runs;
    for (bool box : {false, true})
        for (StepOrder order : {StepOrder::SplitIntegration, StepOrder::IntegrateFirst})
            runs.push_back(runResting(box, order, frames));

    CsvTable series({"time_s", "ball_split_depth", "ball_first_depth", "box_split_depth", "box_first_depth",
                     "box_split_tilt", "box_first_tilt"});
    for (int frame = 0; frame < frames; ++frame)
        series.addRow({formatNumber((frame + 1) * static_cast<double>(defaults.dt)), formatNumber(runs[0].depth[frame]),
                       formatNumber(runs[1].depth[frame]), formatNumber(runs[2].depth[frame]),
                       formatNumber(runs[3].depth[frame]), formatNumber(runs[2].tilt[frame]),
                       formatNumber(runs[3].tilt[frame])});

    // Summary over the second half of the run, when the body has settled (or keeps jittering).
    CsvTable summary({"run", "mean_depth_m", "min_depth_m", "max_depth_m", "max_tilt_rad", "drift_m"});
    for (const RestingRun& run : runs) {
        const auto begin = run.depth.begin() + frames / 2;
        double sum = 0;
        for (auto it = begin; it != run.depth.end(); ++it) sum += *it;
        const double count = static_cast<double>(run.depth.end() - begin);
        const double maxTilt = *std::max_element(run.tilt.begin() + frames / 2, run.tilt.end());
        summary.addRow({run.label, formatNumber(sum / count), formatNumber(*std::min_element(begin, run.depth.end())),
                        formatNumber(*std::max_element(begin, run.depth.end())), formatNumber(maxTilt),
                        formatNumber(run.drift)});
    }
    out << "slop " << defaults.slop << " m, baumgarte " << defaults.baumgarte << ", dt " << defaults.dt
        << " s; settled half of " << frames << " frames:\n"
        << summary.toText();

    PlotSpec plot;
    plot.title = "Resting on the ground: penetration at the end of each frame";
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
