// `stepwise bench broadphase`: what sweep and prune buys, measured on the stress scene.
//
//   crossover  small scenes (4 to 256 bodies), sparse and dense: the broadphase alone, brute
//              force against sweep and prune, median over many frames. The smallest count from
//              which sweep and prune wins at every larger count is the crossover `auto` uses.
//   scaling    100 to 100,000 bodies, sparse and dense: broadphase time of brute force, sweep and
//              prune with a full sort, and with the incremental sort, and the whole step.
//   settled    spheres resting on the ground: the sort alone, insertion sort from last step's
//              order against a full sort, and the whole broadphase with each.
//
// One simulation per scene runs chapter 5's pipeline (sweep and prune, incremental); each
// measured frame the other broadphases are timed on the same world before it steps. Every
// broadphase hands the narrowphase the same pairs, so the rest of the step is the same whichever
// ran: a method's whole step is the measured step with its broadphase time in place of the stage's.
// Times are the thread's CPU time (ThreadStopwatch): the machines this runs on are shared, and
// wall-clock time would count the other programs' turns.
#include "05_sap/benches.h"

#include "05_sap/chapter.h"
#include "05_sap/stress_scene.h"
#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace stepwise {

namespace {

enum class Method { Brute, SapFull, SapIncremental };
const char* methodName(Method method) {
    return method == Method::Brute ? "brute" : method == Method::SapFull ? "sap_full" : "sap_incremental";
}
const Method kMethods[] = {Method::Brute, Method::SapFull, Method::SapIncremental};

void runBroadphase(World& world, Method method) {
    if (method == Method::Brute)
        bruteForceBroadphase(world);
    else
        sweepAndPrune(world, method == Method::SapFull ? SortMode::Full : SortMode::Incremental);
}

/// Time of one broadphase call, ms: the mean of `repetitions` calls timed together (reading the
/// thread's CPU clock costs about a microsecond, as much as a whole call on a few bodies). The
/// calls after the first find the ends sorted already; the first one's moves are few in a
/// small scene. The world's broadphase state is left as `start`.
double timeBroadphase(World& world, const BroadphaseState& start, Method method, int repetitions) {
    world.broadphase = start;
    const ThreadStopwatch watch;
    for (int repetition = 0; repetition < repetitions; ++repetition) runBroadphase(world, method);
    const double ms = watch.seconds() * 1e3 / repetitions;
    world.broadphase = start;
    return ms;
}

struct SceneResult {
    std::map<Method, double> broadphaseMs;   // median per frame
    std::map<Method, double> stepMs;         // the rest of the step plus this broadphase
    double narrowphaseMs = 0, solveMs = 0;
    double candidates = 0, axisOverlaps = 0, contacts = 0;  // mean per measured frame
};

struct SceneRun {
    StressParams params;
    int warmupFrames = 10;
    int measuredFrames = 10;
    int repetitions = 1;        // per frame and method (small scenes: many, to beat the clock)
    bool brute = true;
    int bruteFrames = 1 << 30;  // brute force on at most this many of the measured frames
};

/// Wraps every stage so its CPU time adds up in cpuMs[group]: the pipeline's own stage timings
/// are wall-clock, which on a shared machine also count other programs' turns.
void timeStagesOnCpu(Pipeline& pipeline, std::map<std::string, double>& cpuMs) {
    for (Stage& stage : pipeline.stages()) {
        double* total = &cpuMs[stageGroup(stage.name)];
        stage.run = [run = stage.run, total](World& world, Real dt) {
            const ThreadStopwatch watch;
            run(world, dt);
            *total += watch.seconds() * 1e3;
        };
    }
}

SceneResult measureScene(const SceneRun& run) {
    World world = buildStressScene(run.params);
    world.settings.broadphase = BroadphaseMode::Sap;
    Pipeline pipeline = makeChapter05Pipeline(world);
    std::map<std::string, double> cpuMs;
    timeStagesOnCpu(pipeline, cpuMs);
    std::map<Method, std::vector<double>> broadphase, step;
    std::vector<double> narrowphase, solve;
    SceneResult result;
    for (int frame = 0; frame < run.warmupFrames + run.measuredFrames; ++frame) {
        const int measured = frame - run.warmupFrames;
        std::map<Method, double> sideMs;
        if (measured >= 0) {
            // The other broadphases, on the world as the stage will see it (the velocity stage
            // before it moves nothing the bounds depend on but the growth).
            const BroadphaseState start = world.broadphase;
            for (Method method : kMethods) {
                if (method == Method::SapIncremental) continue;  // the stage itself, below
                if (method == Method::Brute && (!run.brute || measured >= run.bruteFrames)) continue;
                sideMs[method] = timeBroadphase(world, start, method, run.repetitions);
            }
            if (run.repetitions > 1) sideMs[Method::SapIncremental] = timeBroadphase(world, start, Method::SapIncremental, run.repetitions);
        }
        for (auto& entry : cpuMs) entry.second = 0;
        pipeline.step(world);
        if (measured < 0) continue;
        double stepTime = 0;
        for (const auto& entry : cpuMs) stepTime += entry.second;
        const double stageTime = cpuMs[stage_group::kBroadphase];
        if (!sideMs.count(Method::SapIncremental)) sideMs[Method::SapIncremental] = stageTime;
        const double rest = std::max(0.0, stepTime - stageTime);
        for (const auto& [method, ms] : sideMs) {
            broadphase[method].push_back(ms);
            step[method].push_back(rest + ms);
        }
        narrowphase.push_back(cpuMs[stage_group::kNarrowphase]);
        solve.push_back(cpuMs[stage_group::kSolve]);
        result.candidates += static_cast<double>(world.candidatePairs.size()) / run.measuredFrames;
        result.axisOverlaps += static_cast<double>(world.broadphase.axisOverlaps) / run.measuredFrames;
        result.contacts += static_cast<double>(world.contacts.size()) / run.measuredFrames;
    }
    for (const auto& [method, samples] : broadphase) result.broadphaseMs[method] = median(samples);
    for (const auto& [method, samples] : step) result.stepMs[method] = median(samples);
    result.narrowphaseMs = median(narrowphase);
    result.solveMs = median(solve);
    return result;
}

struct SettledResult {
    double insertionSortMs = 0, fullSortMs = 0;           // the sort alone
    double incrementalMs = 0, fullMs = 0;                 // the whole broadphase
    double moves = 0;                                     // insertion-sort moves per frame
};

// [ch05-bench-settled]
/// Spheres resting on the ground: the sort from last step's order against a full sort, timed
/// apart from the rest of the broadphase, and the whole broadphase with each.
SettledResult measureSettled(int count, int settleFrames, int measuredFrames) {
    StressParams params;
    params.count = count;
    params.shape = StressShape::Sphere;
    params.dropHeight = 0;
    World world = buildStressScene(params);
    world.settings.broadphase = BroadphaseMode::Sap;
    Pipeline pipeline = makeChapter05Pipeline(world);
    for (int frame = 0; frame < settleFrames; ++frame) pipeline.step(world);
    std::vector<double> insertion, full, incremental, whole, moves;
    std::vector<Aabb> bounds;
    std::vector<char> dynamic;
    for (int frame = 0; frame < measuredFrames; ++frame) {
        const BroadphaseState start = world.broadphase;
        computeBroadphaseBounds(world, bounds, dynamic);
        std::vector<SweepEndpoint> ends = start.endpoints;
        ThreadStopwatch watch;
        refreshEndpointValues(bounds, start.axis, ends);
        const long moved = insertionSortEndpoints(ends, static_cast<long>(ends.size()) * 64);
        insertion.push_back(watch.seconds() * 1e3);
        moves.push_back(static_cast<double>(moved));
        watch.restart();
        makeEndpoints(bounds, start.axis, ends);
        fullSortEndpoints(ends);
        full.push_back(watch.seconds() * 1e3);
        whole.push_back(timeBroadphase(world, start, Method::SapFull, 1));
        incremental.push_back(timeBroadphase(world, start, Method::SapIncremental, 1));
        pipeline.step(world);
    }
    return SettledResult{median(insertion), median(full), median(incremental), median(whole), median(moves)};
}
// [ch05-bench-settled]

std::string cell(double value) { return std::isfinite(value) ? formatNumber(value) : ""; }

struct Series {
    std::map<std::string, PlotSeries> byName;
    void add(const std::string& name, double x, double y) {
        PlotSeries& series = byName[name];
        series.title = name;
        series.x.push_back(x);
        series.y.push_back(y);
    }
};

/// Pairs the sweep looks at, and its time, along each axis: what the variance's choice saves.
struct AxisComparison {
    int chosen = -1;
    long looked[3] = {0, 0, 0};
    double sweepMs[3] = {0, 0, 0};
};

/// A stress scene of `count` bodies dropped from no height, after five frames of sweep and prune:
/// the broadphase state (bounds, kept order, axis) of a scene that has landed, for timing its parts.
World landedStressScene(StressDensity density, int count) {
    StressParams params;
    params.count = count;
    params.density = density;
    params.dropHeight = 0;
    World world = buildStressScene(params);
    world.settings.broadphase = BroadphaseMode::Sap;
    Pipeline pipeline = makeChapter05Pipeline(world);
    for (int frame = 0; frame < 5; ++frame) pipeline.step(world);
    return world;
}

AxisComparison compareAxes(StressDensity density, int count) {
    World world = landedStressScene(density, count);
    AxisComparison comparison;
    comparison.chosen = world.broadphase.axis;
    std::vector<SweepEndpoint> ends;
    std::vector<BodyPair> pairs;
    for (int axis = 0; axis < 3; ++axis) {
        makeEndpoints(world.broadphase.bounds, axis, ends);
        fullSortEndpoints(ends);
        pairs.clear();
        const ThreadStopwatch watch;
        comparison.looked[axis] = sweepEndpoints(ends, world.broadphase.bounds, world.broadphase.dynamic, axis, pairs);
        comparison.sweepMs[axis] = watch.seconds() * 1e3;
    }
    return comparison;
}

/// Where sweep and prune's time goes, per body, ns: each phase of sweepAndPrune timed alone over
/// `repetitions` runs on a scene that has landed, and brute force's time per pair.
struct PhaseCosts {
    double bounds = 0, variance = 0, sort = 0, sweep = 0, pairSort = 0, brutePerPair = 0;
};

PhaseCosts measurePhases(int count, int repetitions) {
    World world = landedStressScene(StressParams{}.density, count);
    std::vector<double> bounds, variance, sort, sweep, pairSort;
    for (int repetition = 0; repetition < repetitions; ++repetition) {
        BroadphaseState state = world.broadphase;
        ThreadStopwatch watch;
        computeBroadphaseBounds(world, state.bounds, state.dynamic);
        bounds.push_back(watch.seconds());
        watch.restart();
        const Vec3 spread = centreVariance(state.bounds);
        const int axis = chooseSweepAxis(spread, state.axis);
        variance.push_back(watch.seconds());
        watch.restart();
        refreshEndpointValues(state.bounds, axis, state.endpoints);
        insertionSortEndpoints(state.endpoints, static_cast<long>(state.endpoints.size()) * 64);
        sort.push_back(watch.seconds());
        // As the stage does: into a list that kept its capacity, with the state's working memory.
        std::vector<BodyPair>& pairs = world.candidatePairs;
        pairs.clear();
        watch.restart();
        sweepEndpoints(state.endpoints, state.bounds, state.dynamic, sweepAxes(spread, axis), pairs, state.buffers.columns);
        sweep.push_back(watch.seconds());
        watch.restart();
        sortPairsCanonical(pairs, static_cast<int>(world.bodies.size()), state.buffers);
        pairSort.push_back(watch.seconds());
    }
    const double perBody = 1e9 / static_cast<double>(world.bodies.size());
    PhaseCosts costs{median(bounds) * perBody, median(variance) * perBody, median(sort) * perBody,
                     median(sweep) * perBody, median(pairSort) * perBody, 0};
    const ThreadStopwatch watch;
    bruteForceBroadphase(world);
    const double n = static_cast<double>(world.bodies.size());
    costs.brutePerPair = watch.seconds() * 1e9 / (n * (n - 1) / 2);
    return costs;
}

/// The smallest count from which sweep and prune's broadphase is faster at every measured count.
int crossoverCount(const std::vector<std::pair<int, double>>& bruteOverSap) {
    int crossover = -1;
    for (auto it = bruteOverSap.rbegin(); it != bruteOverSap.rend(); ++it) {
        if (it->second <= 1) break;
        crossover = it->first;
    }
    return crossover;
}

void measureBroadphase(BenchRun& bench) {
    std::ostream& out = bench.out();
    const bool quick = bench.quick();
    CsvTable table({"part", "density", "shape", "bodies", "method", "broadphase_ms", "step_ms", "sort_ms",
                    "candidates", "axis_overlaps", "contacts", "narrowphase_ms", "solve_ms"});
    Series broadphasePlot, stepPlot;
    const StressDensity densities[] = {StressDensity::Sparse, StressDensity::Dense};

    // Crossover: small scenes, many frames, many repetitions.
    std::map<StressDensity, int> crossover;
    const std::vector<int> smallCounts = {8, 16, 24, 32, 48, 64, 96, 128, 192, 256};
    for (StressDensity density : densities) {
        bench.progress().stage(std::string("crossover, ") + toString(density), long(smallCounts.size()));
        std::vector<std::pair<int, double>> ratios;
        for (int count : smallCounts) {
            bench.progress().advance();
            SceneRun run;
            run.params.count = count;
            run.params.density = density;
            run.params.dropHeight = 0;
            run.warmupFrames = 20;
            run.measuredFrames = quick ? 40 : 200;
            run.repetitions = std::max(1, 4000 / (count * count) + 5);
            const SceneResult result = measureScene(run);
            ratios.emplace_back(count + 1, result.broadphaseMs.at(Method::Brute) / result.broadphaseMs.at(Method::SapIncremental));
            for (Method method : kMethods) {
                table.addRow({"crossover", toString(density), "mixed", std::to_string(count + 1), methodName(method),
                              cell(result.broadphaseMs.at(method)), "", "", cell(result.candidates), "", "", "", ""});
            }
        }
        crossover[density] = crossoverCount(ratios);
    }

    // Scaling: 100 to 100,000 bodies.
    const std::vector<int> counts = quick ? std::vector<int>{100, 1000, 10000, 100000}
                                          : std::vector<int>{100, 300, 1000, 3000, 10000, 30000, 100000};
    std::map<std::pair<StressDensity, int>, SceneResult> scaling;
    for (StressDensity density : densities) {
        bench.progress().stage(std::string("scaling, ") + toString(density), long(counts.size()));
        for (int count : counts) {
            bench.progress().advance();
            // Dense scenes pile up: their step grows fast, so quick runs stop at 10,000.
            if (quick && density == StressDensity::Dense && count > 10000) continue;
            SceneRun run;
            run.params.count = count;
            run.params.density = density;
            run.params.dropHeight = 0;
            // Dense blocks are measured once they have collapsed into a pile (a second), sparse
            // layers once the bodies have landed.
            run.warmupFrames = density == StressDensity::Dense ? (quick ? 60 : 120) : (quick ? 5 : 20);
            run.measuredFrames = count >= 30000 ? 5 : quick ? 8 : 20;
            run.repetitions = count <= 300 ? 10 : 1;
            // Brute force grows as n^2: one frame at 30,000 and up, none at 100,000 in quick runs.
            run.brute = !(quick && count > 10000);
            run.bruteFrames = count >= 30000 ? 1 : run.measuredFrames;
            const SceneResult result = measureScene(run);
            scaling[{density, count}] = result;
            const int bodies = count + 1;
            for (Method method : kMethods) {
                if (!result.broadphaseMs.count(method)) continue;
                table.addRow({"scaling", toString(density), "mixed", std::to_string(bodies), methodName(method),
                              cell(result.broadphaseMs.at(method)), cell(result.stepMs.at(method)), "",
                              cell(result.candidates), method == Method::Brute ? "" : cell(result.axisOverlaps),
                              cell(result.contacts), cell(result.narrowphaseMs), cell(result.solveMs)});
                const std::string label = std::string(toString(density)) + ", " +
                                          (method == Method::Brute ? "brute force" : method == Method::SapFull ? "SAP full sort" : "SAP incremental");
                broadphasePlot.add(label, bodies, result.broadphaseMs.at(method));
                if (method != Method::SapFull) stepPlot.add(label, bodies, result.stepMs.at(method));
            }
            stepPlot.add(std::string(toString(density)) + ", narrow+solve", bodies, result.narrowphaseMs + result.solveMs);
        }
    }

    // Settled: incremental against full sort.
    std::map<int, SettledResult> settled;
    const std::vector<int> settledCounts = quick ? std::vector<int>{10000} : std::vector<int>{10000, 100000};
    bench.progress().stage("settled spheres, incremental and full sort", long(settledCounts.size()) + 2);
    for (int count : settledCounts) {
        bench.progress().advance();
        const SettledResult result = measureSettled(count, quick ? 40 : 60, quick ? 10 : 30);
        settled[count] = result;
        table.addRow({"settled", "sparse", "sphere", std::to_string(count + 1), "sap_incremental", cell(result.incrementalMs),
                      "", cell(result.insertionSortMs), "", "", "", "", ""});
        table.addRow({"settled", "sparse", "sphere", std::to_string(count + 1), "sap_full", cell(result.fullMs), "",
                      cell(result.fullSortMs), "", "", "", "", ""});
    }

    out << table.toText();
    std::ostringstream summary;
    summary << "crossover: sweep and prune's broadphase is faster from " << crossover[StressDensity::Sparse]
            << " bodies (sparse) and " << crossover[StressDensity::Dense] << " bodies (dense); auto uses "
            << kAutoSapMinBodies << " (kAutoSapMinBodies)\n";
    const AxisComparison axes = compareAxes(StressDensity::Sparse, 10000);
    bench.progress().advance();
    const char* const axisNames[] = {"x", "y", "z"};
    summary << "axis choice, sparse 10,001 bodies on the ground: pairs the sweep looks at along";
    for (int axis = 0; axis < 3; ++axis)
        summary << (axis ? "," : "") << " " << axisNames[axis] << " " << axes.looked[axis] << " ("
                << formatNumber(axes.sweepMs[axis], 3) << " ms)";
    summary << "; the variance picks " << axisNames[axes.chosen] << "\n";
    const SceneResult& sparse10k = scaling[{StressDensity::Sparse, 10000}];
    const double sap10k = sparse10k.broadphaseMs.at(Method::SapIncremental);
    const double speedup10k = sparse10k.broadphaseMs.at(Method::Brute) / sap10k;
    const double sap100k = scaling[{StressDensity::Sparse, 100000}].broadphaseMs.at(Method::SapIncremental);
    const SettledResult& rest = settled[10000];
    auto verdict = [](bool met) { return met ? "met" : "MISSED"; };
    summary << "targets (one thread, CPU time):\n"
            << "  sparse 10,001 bodies: SAP " << formatNumber(sap10k, 3) << " ms, " << formatNumber(speedup10k, 3)
            << "x faster than brute force (target: at least 100x, under 2 ms): "
            << verdict(speedup10k >= 100 && sap10k < 2) << "\n"
            << "  sparse 100,001 bodies: SAP " << formatNumber(sap100k, 3) << " ms (target: under 25 ms): "
            << verdict(sap100k < 25) << "\n"
            << "  settled 10,001 spheres: insertion sort " << formatNumber(rest.insertionSortMs, 3) << " ms ("
            << formatNumber(rest.moves, 3) << " moves), full sort " << formatNumber(rest.fullSortMs, 3) << " ms: "
            << formatNumber(rest.fullSortMs / rest.insertionSortMs, 3) << "x (target: at least 3x): "
            << verdict(rest.fullSortMs >= 3 * rest.insertionSortMs) << "; whole broadphase "
            << formatNumber(rest.incrementalMs, 3) << " against " << formatNumber(rest.fullMs, 3) << " ms\n";
    const PhaseCosts phases = measurePhases(10000, quick ? 30 : 100);
    bench.progress().endStage();
    const double perBody = phases.bounds + phases.variance + phases.sort + phases.sweep + phases.pairSort;
    summary << "where the time goes, sparse 10,001 bodies, ns per body: bounds " << formatNumber(phases.bounds, 3)
            << ", variance " << formatNumber(phases.variance, 3) << ", sort " << formatNumber(phases.sort, 3)
            << ", sweep " << formatNumber(phases.sweep, 3) << ", pair sort " << formatNumber(phases.pairSort, 3)
            << ": " << formatNumber(perBody, 3) << " in all; brute force " << formatNumber(phases.brutePerPair, 3)
            << " ns per pair, so 100x faster would take under "
            << formatNumber(phases.brutePerPair * 10000 / 2 / 100, 3) << " ns per body\n";
    summary << "dense against sparse, 10,001 bodies (SAP incremental; dense measured once it has piled up):\n";
    for (StressDensity density : densities) {
        const SceneResult& result = scaling[{density, 10000}];
        const double stepTime = result.stepMs.at(Method::SapIncremental);
        const double bruteStep = result.stepMs.at(Method::Brute);
        summary << "  " << toString(density) << ": " << formatNumber(result.candidates / 10001, 3)
                << " candidate pairs and " << formatNumber(result.axisOverlaps / 10001, 3)
                << " pairs looked at per body; broadphase " << formatNumber(result.broadphaseMs.at(Method::SapIncremental), 3)
                << " ms (brute force " << formatNumber(result.broadphaseMs.at(Method::Brute), 3) << " ms), narrowphase "
                << formatNumber(result.narrowphaseMs, 3) << " ms, solve " << formatNumber(result.solveMs, 3) << " ms; step "
                << formatNumber(stepTime, 3) << " ms against " << formatNumber(bruteStep, 3) << " ms with brute force ("
                << formatNumber(100 * (bruteStep - stepTime) / bruteStep, 3) << "% saved)\n";
    }
    out << "\n" << summary.str();

    CsvTable targets({"target (one thread, CPU time)", "asked", "measured", ""});
    targets.addRow({"sparse 10,001 bodies: SAP against brute force", "at least 100x",
                    formatNumber(speedup10k, 3) + "x", verdict(speedup10k >= 100)});
    targets.addRow({"sparse 10,001 bodies: SAP broadphase", "under 2 ms", formatNumber(sap10k, 3) + " ms", verdict(sap10k < 2)});
    targets.addRow({"sparse 100,001 bodies: SAP broadphase", "under 25 ms", formatNumber(sap100k, 3) + " ms", verdict(sap100k < 25)});
    targets.addRow({"settled 10,001 spheres: full sort against insertion sort", "at least 3x",
                    formatNumber(rest.fullSortMs / rest.insertionSortMs, 3) + "x", verdict(rest.fullSortMs >= 3 * rest.insertionSortMs)});
    const auto ms = [](double value) { return formatNumber(value, 3) + " ms"; };
    std::vector<std::string> notes = {
        "crossover: sweep and prune's broadphase is faster from " + std::to_string(crossover[StressDensity::Sparse]) +
            " bodies (sparse) and " + std::to_string(crossover[StressDensity::Dense]) + " (dense); auto uses " +
            std::to_string(kAutoSapMinBodies),
        "axis choice, 10,001 bodies on the ground: pairs the sweep looks at along x " + std::to_string(axes.looked[0]) +
            ", y " + std::to_string(axes.looked[1]) + ", z " + std::to_string(axes.looked[2]),
        "    its time along x " + ms(axes.sweepMs[0]) + ", y " + ms(axes.sweepMs[1]) + ", z " + ms(axes.sweepMs[2]) +
            "; the variance picks " + axisNames[axes.chosen],
        "where the time goes, sparse 10,001 bodies, ns per body: bounds " + formatNumber(phases.bounds, 3) +
            ", variance " + formatNumber(phases.variance, 3) + ", sort " + formatNumber(phases.sort, 3) + ", sweep " +
            formatNumber(phases.sweep, 3) + ", pair sort " + formatNumber(phases.pairSort, 3),
        "    " + formatNumber(perBody, 3) + " in all; brute force takes " + formatNumber(phases.brutePerPair, 3) +
            " ns a pair, so 100x faster needs under " + formatNumber(phases.brutePerPair * 10000 / 2 / 100, 3) +
            " ns per body"};
    CsvTable denseAgainstSparse({"10,001 bodies", "candidates / body", "looked at / body", "broadphase", "brute force",
                        "narrowphase", "solve", "step", "step, brute force"});
    for (StressDensity density : {StressDensity::Sparse, StressDensity::Dense}) {
        const SceneResult& result = scaling[{density, 10000}];
        denseAgainstSparse.addRow({toString(density), formatNumber(result.candidates / 10001, 3),
                          formatNumber(result.axisOverlaps / 10001, 3), ms(result.broadphaseMs.at(Method::SapIncremental)),
                          ms(result.broadphaseMs.at(Method::Brute)), ms(result.narrowphaseMs), ms(result.solveMs),
                          ms(result.stepMs.at(Method::SapIncremental)), ms(result.stepMs.at(Method::Brute))});
    }

    bench.writeCsv(table);
    PlotSpec plot("Broadphase time against body count (stress scene, one thread)", "bodies", "broadphase ms per step (median)");
    plot.integerX = true;
    plot.caption = "The stress scene (mixed spheres, diamonds and boxes on one ground), sparse (one layer, 4 m apart) and "
                   "dense (a block of 1 m cells, measured once it has piled up). Each point: the median over the measured "
                   "frames of the broadphase's CPU time; every method found the same pairs. Brute force tests all pairs "
                   "against the same grown boxes; SAP full sort sorts the interval ends from scratch every step.";
    for (auto& [name, series] : broadphasePlot.byName) plot.series.push_back(series);
    bench.writePlot(plot);
    PlotSpec stepSpec("Whole step against body count: where the time goes", "bodies", "ms per step (median)");
    stepSpec.integerX = true;
    stepSpec.caption = "The whole step with each broadphase (the rest of the step is the same, since every broadphase "
                       "hands the narrowphase the same pairs), and its narrowphase and solve alone (narrow+solve).";
    for (auto& [name, series] : stepPlot.byName) stepSpec.series.push_back(series);
    bench.writePlot(stepSpec, "-step");
    bench.writeTables({FigureTable{notes, &targets},
                       FigureTable{{"dense against sparse: sweep and prune (incremental), dense measured once it has piled up"},
                                   &denseAgainstSparse}},
                      "-summary");
}

}  // namespace

BenchEntry broadphaseBench() {
    return benchEntry(5, measureBroadphase, R"(
        broadphase: chapter 5: broadphase and step time against body count (100 to 100,000),
            sparse and dense, brute force vs sweep and prune (full sort, incremental); the
            crossover auto uses
        broadphase.csv          per part, density, body count and method: broadphase, step,
                                sort, narrowphase and solve ms, candidate pairs, pairs looked at
        broadphase.svg          plot: broadphase time against body count
        broadphase-step.svg     plot: whole step, and narrowphase + solve, against body count
        broadphase-summary.svg  table: the targets, the crossover, the axis choice, dense
                                against sparse)");
}

}  // namespace stepwise
