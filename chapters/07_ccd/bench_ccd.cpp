// `stepwise bench ccd`: tunnel rate and step cost against speed, CCD against substeps.
#include "07_ccd/benches.h"

#include "07_ccd/chapter.h"
#include "07_ccd/shots.h"
#include "app/bench_util.h"

#include <algorithm>
#include <map>
#include <ostream>

namespace stepwise {

namespace {

/// One way to step the shots: CCD on or off, and the substeps per frame.
struct Method {
    std::string name;
    CcdMode ccd = CcdMode::Off;
    int substeps = 1;
};

std::vector<Method> methods() {
    std::vector<Method> all = {{"ccd off", CcdMode::Off, 1}, {"ccd on", CcdMode::Auto, 1}};
    for (int substeps : {2, 4, 8, 16}) all.push_back({std::to_string(substeps) + " substeps", CcdMode::Off, substeps});
    return all;
}

struct Outcome {
    int shots = 0;
    int tunnelled = 0;
    double stepSeconds = 0;   // CPU time of every step of every shot
    long steps = 0;
    long impacts = 0;
    long queries = 0;         // distance queries of the impacts found
    double timeLost = 0;      // step fractions the stopped bodies waited, over the impacts
};

// [ch07-bench-shot]
/// The same shots (one seed per speed) through one method: how many crossed the wall, and
/// what the steps cost.
Outcome shoot(const Method& method, Real speed, int shots) {
    Outcome outcome;
    Random random(7000 + static_cast<std::uint32_t>(speed));
    for (int i = 0; i < shots; ++i) {
        World world = buildShot(randomShot(random, speed), method.ccd);
        world.settings.substeps = method.substeps;
        Pipeline pipeline = makeChapter07Pipeline(world);
        bool crossed = false;
        ThreadStopwatch clock;
        for (int step = 0; step < kShotSteps; ++step) {
            pipeline.step(world);
            crossed = crossed || tunnelled(world);
            outcome.queries += world.step.ccd.rootIterations;
            outcome.timeLost += double(world.step.ccd.timeLost);
        }
        outcome.stepSeconds += clock.seconds();
        outcome.steps += kShotSteps;
        outcome.tunnelled += crossed ? 1 : 0;
        outcome.impacts += world.step.ccd.totalToiEvents;
        ++outcome.shots;
    }
    return outcome;
}
// [ch07-bench-shot]

void measureCcd(BenchRun& bench) {
    const bool quick = bench.quick();
    const std::vector<Real> speeds = quick ? std::vector<Real>{50, 200, 500} : std::vector<Real>{25, 50, 100, 200, 300, 400, 500};
    const int shots = quick ? 30 : 400;
    CsvTable table({"method", "speed_mps", "shots", "tunnelled", "tunnel_rate", "step_us", "impacts_per_shot"});
    std::map<std::string, PlotSeries> rate, cost;
    std::map<std::string, Outcome> total;  // per method, over every speed
    bench.progress().stage("shots", long(speeds.size() * methods().size()));
    for (const Method& method : methods()) {
        for (Real speed : speeds) {
            const Outcome outcome = shoot(method, speed, shots);
            Outcome& sum = total[method.name];
            sum.shots += outcome.shots;
            sum.tunnelled += outcome.tunnelled;
            sum.stepSeconds += outcome.stepSeconds;
            sum.steps += outcome.steps;
            sum.impacts += outcome.impacts;
            sum.queries += outcome.queries;
            sum.timeLost += outcome.timeLost;
            const double tunnelRate = double(outcome.tunnelled) / outcome.shots;
            const double stepMicroseconds = 1e6 * outcome.stepSeconds / double(outcome.steps);
            table.addRow({method.name, formatNumber(double(speed)), std::to_string(outcome.shots),
                          std::to_string(outcome.tunnelled), formatNumber(tunnelRate), formatNumber(stepMicroseconds),
                          formatNumber(double(outcome.impacts) / outcome.shots)});
            rate[method.name].title = method.name;
            rate[method.name].x.push_back(double(speed));
            rate[method.name].y.push_back(tunnelRate);
            cost[method.name].title = method.name;
            cost[method.name].x.push_back(double(speed));
            cost[method.name].y.push_back(stepMicroseconds);
            bench.progress().advance();
        }
    }
    bench.progress().endStage();
    bench.writeCsv(table);
    const std::string runs = std::to_string(shots) + " shots per point, " + realTypeName();
    PlotSpec ratePlot("Shots through a 5 cm wall against speed (" + runs + ")", "speed (m/s)", "fraction tunnelled", false, false);
    ratePlot.caption = "Spheres, boxes and hulls of 1 to 5 cm shot at a static wall 5 cm thick, up to 30 degrees off its "
                       "normal, spinning up to 50 rad/s, at 60 Hz; a shot tunnels when its centre ends a step past the wall.";
    PlotSpec costPlot("Cost of a step against speed (" + runs + ")", "speed (m/s)", "step time (microseconds, CPU)", false, true);
    costPlot.caption = "CPU time per 1/60 s step of the same shots, wall and one body, mean over every step.";
    for (const Method& method : methods()) {
        ratePlot.series.push_back(rate[method.name]);
        costPlot.series.push_back(cost[method.name]);
    }
    bench.writePlot(ratePlot);
    bench.writePlot(costPlot, "-cost");
    bench.out() << table.toText();

    // [ch07-bench-summary]
    // Every speed together: how often each method let a shot through, what its step cost
    // against CCD off, and for CCD the impacts and the distance queries each took.
    CsvTable summary({"method", "shots", "tunnelled", "tunnel rate", "step (us)", "cost vs ccd off", "impacts", "queries per impact",
                      "step lost per impact"});
    const Outcome& off = total["ccd off"];
    const double offMicroseconds = 1e6 * off.stepSeconds / double(std::max(1L, off.steps));
    for (const Method& method : methods()) {
        const Outcome& sum = total[method.name];
        const double microseconds = 1e6 * sum.stepSeconds / double(std::max(1L, sum.steps));
        summary.addRow({method.name, std::to_string(sum.shots), std::to_string(sum.tunnelled),
                        formatNumber(double(sum.tunnelled) / std::max(1, sum.shots)), formatNumber(microseconds),
                        formatNumber(microseconds / offMicroseconds) + "x", std::to_string(sum.impacts),
                        sum.impacts > 0 ? formatNumber(double(sum.queries) / double(sum.impacts)) : "-",
                        sum.impacts > 0 ? formatNumber(sum.timeLost / double(sum.impacts)) : "-"});
    }
    // [ch07-bench-summary]
    bench.out() << "\nall speeds together (" << runs << "):\n" << summary.toText();
    bench.writeTables({FigureTable{{"all speeds together (" + runs + ", one thread, CPU time)"}, &summary}}, "-summary");
}

}  // namespace

BenchEntry ccdBench() {
    BenchEntry entry;
    entry.name = "ccd";
    entry.chapter = 7;
    entry.description = "tunnel rate and step cost against speed: CCD off, CCD on, 2 to 16 substeps";
    entry.measure = measureCcd;
    entry.files = {{BenchFile::Kind::Csv, "", "tunnel rate and step cost per method and speed"},
                   {BenchFile::Kind::Plot, "", "fraction of shots through the wall against speed"},
                   {BenchFile::Kind::Plot, "-cost", "step time against speed"},
                   {BenchFile::Kind::Plot, "-summary", "every speed together: tunnels, cost against CCD off, queries per impact"}};
    return entry;
}

}  // namespace stepwise
