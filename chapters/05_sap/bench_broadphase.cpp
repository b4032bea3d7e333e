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

#include "05_sap/broadphase_runs.h"
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

namespace broadphase_bench {
namespace {

struct Series {
    std::map<std::string, PlotSeries> byName;
    void add(const std::string& name, double x, double y) {
        PlotSeries& series = byName[name];
        series.title = name;
        series.x.push_back(x);
        series.y.push_back(y);
    }
};

const StressDensity kDensities[] = {StressDensity::Sparse, StressDensity::Dense};
using Scaling = std::map<std::pair<StressDensity, int>, SceneResult>;

/// What the suite measured, for its summary and its files.
struct Findings {
    std::map<StressDensity, int> crossover;
    Scaling scaling;
    std::map<int, SettledResult> settled;
    AxisComparison axes;
    PhaseCosts phases;
};

/// Crossover: small scenes, many frames, many repetitions.
std::map<StressDensity, int> measureCrossover(BenchRun& bench, CsvTable& table) {
    const bool quick = bench.quick();
    std::map<StressDensity, int> crossover;
    const std::vector<int> smallCounts = {8, 16, 24, 32, 48, 64, 96, 128, 192, 256};
    for (StressDensity density : kDensities) {
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

    return crossover;
}

/// Scaling: 100 to 100,000 bodies, into the table and the two plots' series.
Scaling measureScaling(BenchRun& bench, CsvTable& table, Series& broadphasePlot, Series& stepPlot) {
    const bool quick = bench.quick();
    const std::vector<int> counts = quick ? std::vector<int>{100, 1000, 10000, 100000}
                                          : std::vector<int>{100, 300, 1000, 3000, 10000, 30000, 100000};
    std::map<std::pair<StressDensity, int>, SceneResult> scaling;
    for (StressDensity density : kDensities) {
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

    return scaling;
}

/// Settled: incremental against full sort; then the axis comparison and the phases, in the same
/// progress stage.
std::map<int, SettledResult> measureSettledSorts(BenchRun& bench, CsvTable& table) {
    const bool quick = bench.quick();
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

    return settled;
}

constexpr const char* kAxisNames[] = {"x", "y", "z"};

const char* verdict(bool met) { return met ? "met" : "MISSED"; }

/// The chapter's targets, read off what was measured.
struct TargetFigures {
    double sap10k = 0, speedup10k = 0, sap100k = 0;  // ms, x, ms
    SettledResult rest;                              // 10,001 settled spheres
};
TargetFigures targetFigures(const Findings& found) {
    const SceneResult& sparse10k = found.scaling.at({StressDensity::Sparse, 10000});
    TargetFigures figures;
    figures.sap10k = sparse10k.broadphaseMs.at(Method::SapIncremental);
    figures.speedup10k = sparse10k.broadphaseMs.at(Method::Brute) / figures.sap10k;
    figures.sap100k = found.scaling.at({StressDensity::Sparse, 100000}).broadphaseMs.at(Method::SapIncremental);
    figures.rest = found.settled.at(10000);
    return figures;
}

double phasesPerBody(const PhaseCosts& phases) {
    return phases.bounds + phases.variance + phases.sort + phases.sweep + phases.pairSort;
}

/// The summary printed after the table: the crossover, the axis choice, the targets, the phases,
/// dense against sparse.
std::string summaryText(const Findings& found) {
    const auto& crossover = found.crossover;
    const AxisComparison& axes = found.axes;
    const PhaseCosts& phases = found.phases;
    const TargetFigures figures = targetFigures(found);
    const SettledResult& rest = figures.rest;
    std::ostringstream summary;
    summary << "crossover: sweep and prune's broadphase is faster from " << crossover.at(StressDensity::Sparse)
            << " bodies (sparse) and " << crossover.at(StressDensity::Dense) << " bodies (dense); auto uses "
            << kAutoSapMinBodies << " (kAutoSapMinBodies)\n";
    summary << "axis choice, sparse 10,001 bodies on the ground: pairs the sweep looks at along";
    for (int axis = 0; axis < 3; ++axis)
        summary << (axis ? "," : "") << " " << kAxisNames[axis] << " " << axes.looked[axis] << " ("
                << formatNumber(axes.sweepMs[axis], 3) << " ms)";
    summary << "; the variance picks " << kAxisNames[axes.chosen] << "\n";
    const double sap10k = figures.sap10k, speedup10k = figures.speedup10k, sap100k = figures.sap100k;
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
    const double perBody = phasesPerBody(phases);
    summary << "where the time goes, sparse 10,001 bodies, ns per body: bounds " << formatNumber(phases.bounds, 3)
            << ", variance " << formatNumber(phases.variance, 3) << ", sort " << formatNumber(phases.sort, 3)
            << ", sweep " << formatNumber(phases.sweep, 3) << ", pair sort " << formatNumber(phases.pairSort, 3)
            << ": " << formatNumber(perBody, 3) << " in all; brute force " << formatNumber(phases.brutePerPair, 3)
            << " ns per pair, so 100x faster would take under "
            << formatNumber(phases.brutePerPair * 10000 / 2 / 100, 3) << " ns per body\n";
    summary << "dense against sparse, 10,001 bodies (SAP incremental; dense measured once it has piled up):\n";
    for (StressDensity density : kDensities) {
        const SceneResult& result = found.scaling.at({density, 10000});
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
    return summary.str();
}

/// The table of targets, the notes and the dense-against-sparse table as a figure, and the two plots.
void writeFiles(BenchRun& bench, const Findings& found, const CsvTable& table, const Series& broadphasePlot,
                const Series& stepPlot) {
    const TargetFigures figures = targetFigures(found);
    const double sap10k = figures.sap10k, speedup10k = figures.speedup10k, sap100k = figures.sap100k;
    const SettledResult& rest = figures.rest;
    const AxisComparison& axes = found.axes;
    const PhaseCosts& phases = found.phases;
    const double perBody = phasesPerBody(phases);
    CsvTable targets({"target (one thread, CPU time)", "asked", "measured", ""});
    targets.addRow({"sparse 10,001 bodies: SAP against brute force", "at least 100x",
                    formatNumber(speedup10k, 3) + "x", verdict(speedup10k >= 100)});
    targets.addRow({"sparse 10,001 bodies: SAP broadphase", "under 2 ms", formatNumber(sap10k, 3) + " ms", verdict(sap10k < 2)});
    targets.addRow({"sparse 100,001 bodies: SAP broadphase", "under 25 ms", formatNumber(sap100k, 3) + " ms", verdict(sap100k < 25)});
    targets.addRow({"settled 10,001 spheres: full sort against insertion sort", "at least 3x",
                    formatNumber(rest.fullSortMs / rest.insertionSortMs, 3) + "x", verdict(rest.fullSortMs >= 3 * rest.insertionSortMs)});
    const auto ms = [](double value) { return formatNumber(value, 3) + " ms"; };
    std::vector<std::string> notes = {
        "crossover: sweep and prune's broadphase is faster from " + std::to_string(found.crossover.at(StressDensity::Sparse)) +
            " bodies (sparse) and " + std::to_string(found.crossover.at(StressDensity::Dense)) + " (dense); auto uses " +
            std::to_string(kAutoSapMinBodies),
        "axis choice, 10,001 bodies on the ground: pairs the sweep looks at along x " + std::to_string(axes.looked[0]) +
            ", y " + std::to_string(axes.looked[1]) + ", z " + std::to_string(axes.looked[2]),
        "    its time along x " + ms(axes.sweepMs[0]) + ", y " + ms(axes.sweepMs[1]) + ", z " + ms(axes.sweepMs[2]) +
            "; the variance picks " + kAxisNames[axes.chosen],
        "where the time goes, sparse 10,001 bodies, ns per body: bounds " + formatNumber(phases.bounds, 3) +
            ", variance " + formatNumber(phases.variance, 3) + ", sort " + formatNumber(phases.sort, 3) + ", sweep " +
            formatNumber(phases.sweep, 3) + ", pair sort " + formatNumber(phases.pairSort, 3),
        "    " + formatNumber(perBody, 3) + " in all; brute force takes " + formatNumber(phases.brutePerPair, 3) +
            " ns a pair, so 100x faster needs under " + formatNumber(phases.brutePerPair * 10000 / 2 / 100, 3) +
            " ns per body"};
    CsvTable denseAgainstSparse({"10,001 bodies", "candidates / body", "looked at / body", "broadphase", "brute force",
                        "narrowphase", "solve", "step", "step, brute force"});
    for (StressDensity density : {StressDensity::Sparse, StressDensity::Dense}) {
        const SceneResult& result = found.scaling.at({density, 10000});
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
    for (const auto& [name, series] : broadphasePlot.byName) plot.series.push_back(series);
    bench.writePlot(plot);
    PlotSpec stepSpec("Whole step against body count: where the time goes", "bodies", "ms per step (median)");
    stepSpec.integerX = true;
    stepSpec.caption = "The whole step with each broadphase (the rest of the step is the same, since every broadphase "
                       "hands the narrowphase the same pairs), and its narrowphase and solve alone (narrow+solve).";
    for (const auto& [name, series] : stepPlot.byName) stepSpec.series.push_back(series);
    bench.writePlot(stepSpec, "-step");
    bench.writeTables({FigureTable{notes, &targets},
                       FigureTable{{"dense against sparse: sweep and prune (incremental), dense measured once it has piled up"},
                                   &denseAgainstSparse}},
                      "-summary");
}


void measureBroadphase(BenchRun& bench) {
    const bool quick = bench.quick();
    CsvTable table({"part", "density", "shape", "bodies", "method", "broadphase_ms", "step_ms", "sort_ms",
                    "candidates", "axis_overlaps", "contacts", "narrowphase_ms", "solve_ms"});
    Series broadphasePlot, stepPlot;
    Findings found;
    found.crossover = measureCrossover(bench, table);
    found.scaling = measureScaling(bench, table, broadphasePlot, stepPlot);
    found.settled = measureSettledSorts(bench, table);
    found.axes = compareAxes(StressDensity::Sparse, 10000);
    bench.progress().advance();
    found.phases = measurePhases(10000, quick ? 30 : 100);
    bench.progress().endStage();
    bench.out() << table.toText() << "\n" << summaryText(found);
    writeFiles(bench, found, table, broadphasePlot, stepPlot);
}

}  // namespace
}  // namespace broadphase_bench

BenchEntry broadphaseBench() {
    return benchEntry(5, broadphase_bench::measureBroadphase, R"(
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
