// `stepwise bench ccd`: tunnel rate and step cost against speed, CCD against substeps.
#include "07_ccd/benches.h"

#include "01_integrators/rotation.h"
#include "07_ccd/chapter.h"
#include "07_ccd/separation_root.h"
#include "07_ccd/shots.h"
#include "app/bench_util.h"

#include <algorithm>
#include <map>
#include <ostream>
#include <utility>
#include <vector>

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

/// What one time-of-impact method did on a set of sweeps.
struct ToiTally {
    int hits = 0;
    long queries = 0;         // GJK queries (conservative advancement), GJK queries and root steps (roots)
    double seconds = 0;       // CPU time of all the queries
    std::vector<double> times;  // TOI of each sweep, 2 for none
};

// [ch07-bench-toi-methods]
/// Conservative advancement against root finding on the same sweeps: each shot's first step,
/// against the wall, with the engine's target and tolerance.
CsvTable compareToiMethods(int shotsPerSpeed, const std::vector<Real>& speeds) {
    std::vector<std::pair<World, Sweep>> cases;
    for (Real speed : speeds) {
        Random random(9000 + static_cast<std::uint32_t>(speed));
        for (int i = 0; i < shotsPerSpeed; ++i) {
            const Shot shot = randomShot(random, speed);
            World world = buildShot(shot, CcdMode::Off);
            const Body& body = world.bodies[1];
            const Motion& motion = *world.motionOf(1);
            Transform end = body.transform;
            const Real dt = world.settings.dt;
            end.rotation = rotateExactly(body.transform.rotation, motion.angularVelocity, dt);
            end.position = body.transform.apply(motion.localCenter) + motion.linearVelocity * dt - end.rotation * motion.localCenter;
            const Sweep sweep = sweepBetween(body.transform, end, motion.localCenter);
            cases.emplace_back(std::move(world), sweep);
        }
    }
    const auto run = [&](bool roots) {
        ToiTally tally;
        ThreadStopwatch clock;
        for (const auto& [world, sweep] : cases) {
            const Sweep wall = stillSweep(world.bodies[0].transform, Vec3::Zero());
            const ToiOptions options = toiOptionsFor(world.settings);
            const ToiResult toi = roots ? timeOfImpactByRoots(world.bodies[1].shape, sweep, world.bodies[0].shape, wall, options)
                                        : timeOfImpact(world.bodies[1].shape, sweep, world.bodies[0].shape, wall, options);
            const bool hit = toi.state == ToiState::Hit || toi.state == ToiState::Stalled;
            tally.hits += hit ? 1 : 0;
            tally.queries += toi.iterations;
            tally.times.push_back(hit ? double(toi.time) : 2.0);
        }
        tally.seconds = clock.seconds();
        return tally;
    };
    const ToiTally advancement = run(false), roots = run(true);
    double largestGap = 0;  // s: the two methods' times of impact apart, where both hit
    for (std::size_t i = 0; i < cases.size(); ++i)
        if (advancement.times[i] <= 1 && roots.times[i] <= 1)
            largestGap = std::max(largestGap, std::abs(advancement.times[i] - roots.times[i]) * double(cases[i].first.settings.dt));
    CsvTable table({"toi method", "sweeps", "impacts", "queries per sweep", "us per sweep", "largest TOI difference (s)"});
    for (const auto& [name, tally] : {std::pair{"conservative advancement", &advancement}, std::pair{"separation roots", &roots}})
        table.addRow({name, std::to_string(cases.size()), std::to_string(tally->hits),
                      formatNumber(double(tally->queries) / double(cases.size())),
                      formatNumber(1e6 * tally->seconds / double(cases.size())), formatNumber(largestGap)});
    return table;
}
// [ch07-bench-toi-methods]

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
    const CsvTable methods = compareToiMethods(shots, speeds);
    bench.out() << "\ntime of impact, two ways, on the first step of the same kind of shots:\n" << methods.toText();
    bench.writeCsv(methods, "-toi");
    bench.writeTables({FigureTable{{"all speeds together (" + runs + ", one thread, CPU time)"}, &summary},
                       FigureTable{{"time of impact, two ways, on each shot's first step (CPU time)"}, &methods}},
                      "-summary");
}

}  // namespace

BenchEntry ccdBench() {
    return benchEntry(7, measureCcd, R"(
        ccd: tunnel rate and step cost against speed: CCD off, CCD on, 2 to 16 substeps
        ccd.csv          tunnel rate and step cost per method and speed
        ccd-toi.csv      conservative advancement against separation roots on the same sweeps
        ccd.svg          fraction of shots through the wall against speed
        ccd-cost.svg     step time against speed
        ccd-summary.svg  every speed together: tunnels, cost against CCD off, queries per
                         impact; the two TOI methods)");
}

}  // namespace stepwise
