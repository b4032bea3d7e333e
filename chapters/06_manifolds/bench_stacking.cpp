// `stepwise bench stacking`: what stands, and what it costs.
//
//   iterations  a pyramid (10 rows, 55 boxes; 5 rows in --quick) for 5 s, the iterations from 1
//               to 50, for each stabilisation with warm starting and manifolds, and for the
//               default stabilisation also without warm starting and with one point per pair.
//   substeps    the same pyramid, 1 to 8 substeps at the default 10 iterations, each stabilisation.
//   pyramids    10, 20 and 40 rows (55, 210, 820 boxes) at the default settings, each stabilisation.
//   targets     the chapter's test scenes at the default settings for 10 s (2 s in --quick).
//
// Each run reports the largest horizontal drift of a box from its start, the largest sag beyond
// the slop per contact beneath it, the deepest overlap after the first second, and the mean wall
// time of a step. Drift and sag are plotted against the step time: the chapter's "run time
// against error" figure.
#include "06_manifolds/benches.h"

#include "06_manifolds/scenes.h"
#include "06_manifolds/stacking_study.h"
#include "app/bench_util.h"

#include <algorithm>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace stepwise {

namespace {

const Stabilisation kStabilisations[] = {Stabilisation::Baumgarte, Stabilisation::SplitImpulse, Stabilisation::Relax,
                                         Stabilisation::SoftStep};

/// Values below this are drawn at it on the log axes (a box that did not move at all).
constexpr double kFloor = 1e-6;

struct Variant {
    Stabilisation stabilisation = Settings{}.stabilisation;
    bool warm = true;
    bool multiPoint = true;
    std::string label() const {
        std::string text = toString(stabilisation);
        if (!warm) text += ", cold";
        if (!multiPoint) text += ", one point";
        return text;
    }
};

StackingConfig configOf(const Variant& variant, int iterations, int substeps) {
    StackingConfig config;
    config.stabilisation = variant.stabilisation;
    config.warmStarting = variant.warm;
    config.manifold.multiPoint = variant.multiPoint;
    config.iterations = iterations;
    config.substeps = substeps;
    return config;
}

void addRow(CsvTable& table, const std::string& part, const std::string& scene, const Variant& variant, int iterations,
            int substeps, const StackingMeasure& m) {
    table.addRow({part, scene, toString(variant.stabilisation), variant.warm ? "on" : "off",
                  variant.multiPoint ? "manifold" : "one_point", std::to_string(iterations), std::to_string(substeps),
                  formatNumber(m.maxDrift), formatNumber(std::max(0.0, m.maxSinkExcess)), formatNumber(m.maxSinkPerContact),
                  formatNumber(m.maxPenetration), formatNumber(m.stepMs), m.stood ? "yes" : "no"});
}

void addPoint(PlotSeries& series, double ms, double value) {
    series.x.push_back(std::max(ms, 1e-4));
    series.y.push_back(std::max(value, kFloor));
}

/// The suite's sizes: a quick run's or a full run's.
struct StackingPlan {
    int pyramidRows = 10;
    double sweepSeconds = 5, targetSeconds = 10;
    std::vector<int> iterationCounts, substepCounts;
};

StackingPlan stackingPlan(bool quick) {
    StackingPlan plan;
    plan.pyramidRows = quick ? 5 : 10;
    plan.sweepSeconds = quick ? 2 : 5;
    plan.targetSeconds = quick ? 2 : 10;
    plan.iterationCounts = quick ? std::vector<int>{1, 4, 10} : std::vector<int>{1, 2, 4, 8, 10, 16, 32, 50};
    plan.substepCounts = quick ? std::vector<int>{1, 4} : std::vector<int>{1, 2, 4, 8};
    return plan;
}

/// The plots' series, by line name.
struct StackingPlots {
    std::map<std::string, PlotSeries> drift, sag, penetration, substepDrift;
};

/// One pyramid through every variant at each iteration count, and each stabilisation at each
/// substep count.
void measureSweeps(BenchRun& bench, const StackingPlan& plan, CsvTable& table, StackingPlots& plots) {
    std::vector<Variant> variants;
    for (Stabilisation stabilisation : kStabilisations) variants.push_back({stabilisation, true, true});
    variants.push_back({Settings{}.stabilisation, false, true});
    variants.push_back({Settings{}.stabilisation, true, false});

    const World pyramid = buildPyramid(plan.pyramidRows);
    bench.progress().stage("iterations", static_cast<long>(variants.size() * plan.iterationCounts.size()));
    for (const Variant& variant : variants) {
        for (int iterations : plan.iterationCounts) {
            const StackingMeasure m = measureStacking(pyramid, configOf(variant, iterations, 1), plan.sweepSeconds);
            addRow(table, "iterations", pyramid.name, variant, iterations, 1, m);
            addPoint(plots.drift[variant.label()], m.stepMs, m.maxDrift);
            addPoint(plots.sag[variant.label()], m.stepMs, std::max(0.0, m.maxSinkExcess));
            addPoint(plots.penetration[variant.label()], m.stepMs, m.maxPenetration);
            bench.progress().advance();
        }
    }
    bench.progress().stage("substeps", static_cast<long>(4 * plan.substepCounts.size()));
    for (Stabilisation stabilisation : kStabilisations) {
        const Variant variant{stabilisation, true, true};
        for (int substeps : plan.substepCounts) {
            const StackingMeasure m = measureStacking(pyramid, configOf(variant, 10, substeps), plan.sweepSeconds);
            addRow(table, "substeps", pyramid.name, variant, 10, substeps, m);
            addPoint(plots.substepDrift[variant.label()], m.stepMs, m.maxDrift);
            bench.progress().advance();
        }
    }
}

/// Pyramids of growing size at the default settings, one row per stabilisation.
CsvTable measurePyramidSizes(BenchRun& bench, const StackingPlan& plan, CsvTable& table) {
    const bool quick = bench.quick();
    const std::vector<int> sizes = quick ? std::vector<int>{5, 10} : std::vector<int>{10, 20, 40};
    bench.progress().stage("pyramids", static_cast<long>(4 * sizes.size()));
    CsvTable pyramids({"rows", "boxes", "stabilisation", "drift_m", "sag_beyond_slop_m", "max_penetration_m", "step_ms"});
    for (int rows : sizes) {
        const World world = buildPyramid(rows);
        for (Stabilisation stabilisation : kStabilisations) {
            const Variant variant{stabilisation, true, true};
            const StackingMeasure m = measureStacking(world, configOf(variant, 10, 1), plan.sweepSeconds);
            addRow(table, "pyramids", world.name, variant, 10, 1, m);
            pyramids.addRow({std::to_string(rows), std::to_string(rows * (rows + 1) / 2), toString(stabilisation),
                             formatNumber(m.maxDrift), formatNumber(std::max(0.0, m.maxSinkExcess)),
                             formatNumber(m.maxPenetration), formatNumber(m.stepMs)});
            bench.progress().advance();
        }
    }

    return pyramids;
}

/// The chapter's targets on their own scenes, default settings.
CsvTable measureTargets(BenchRun& bench, const StackingPlan& plan, CsvTable& table) {
    const bool quick = bench.quick();
    struct Target {
        const char* what;
        std::function<World()> build;
    };
    const std::vector<Target> targets = {
        {"stack of 16", [] { return buildBoxStack(16); }},
        {"pyramid of 20 rows", [] { return buildPyramid(20); }},
        {"100 kg on three 1 kg", [] { return buildHeavyOnLight(); }},
        {"tower, heaviest below", [] { return buildMassTower(true); }},
        {"tower, heaviest above", [] { return buildMassTower(false); }},
        {"box on a 30 deg ramp, mu 0.8", [] { return buildStickingRamp(); }},
    };
    CsvTable summary({"scene", "stabilisation", "warm", "stood", "drift_m", "sink_per_contact_m", "max_penetration_m", "step_ms"});
    bench.progress().stage("targets", static_cast<long>(targets.size() * 3));
    for (const Target& target : targets) {
        if (quick && std::string(target.what) == "pyramid of 20 rows") {
            bench.progress().advance(3);
            continue;  // 18 s a run: full runs only
        }
        const World world = target.build();
        for (const Variant& variant : {Variant{}, Variant{Settings{}.stabilisation, false, true},
                                       Variant{Stabilisation::SoftStep, true, true}}) {
            const StackingMeasure m = measureStacking(world, configOf(variant, world.settings.solverIterations, world.settings.substeps),
                                                      plan.targetSeconds);
            addRow(table, "targets", world.name, variant, world.settings.solverIterations, world.settings.substeps, m);
            summary.addRow({target.what, toString(variant.stabilisation), variant.warm ? "on" : "off", m.stood ? "yes" : "no",
                            formatNumber(m.maxDrift), formatNumber(m.maxSinkPerContact), formatNumber(m.maxPenetration),
                            formatNumber(m.stepMs)});
            bench.progress().advance();
        }
    }
    return summary;
}

/// The two tables as text and as a figure, the CSV and the four plots.
void writeStackingResults(BenchRun& bench, const StackingPlan& plan, const CsvTable& table, const CsvTable& pyramids,
                          const CsvTable& summary, StackingPlots& plots) {
    std::ostream& out = bench.out();
    out << "pyramids at the default settings (" << realTypeName() << ", " << plan.sweepSeconds << " s each):\n"
        << pyramids.toText() << "\n";
    out << "targets at the default settings (" << plan.targetSeconds << " s each; default stabilisation "
        << toString(Settings{}.stabilisation) << "):\n"
        << summary.toText();
    bench.writeCsv(table);

    const std::string runs = std::to_string(plan.pyramidRows * (plan.pyramidRows + 1) / 2) + "-box pyramid, " +
                             std::to_string(static_cast<int>(plan.sweepSeconds)) + " s at 60 Hz, " + realTypeName();
    const auto plotOf = [&](const std::string& title, const std::string& yLabel, std::map<std::string, PlotSeries>& byName,
                            const std::string& caption) {
        PlotSpec plot(title, "step time (ms, wall clock)", yLabel);
        plot.caption = caption;
        for (auto& [name, series] : byName) {
            series.title = name;
            plot.series.push_back(series);
        }
        return plot;
    };
    bench.writePlot(plotOf("Drift against run time, iterations 1 to 50 (" + runs + ")", "largest drift of a box (m)", plots.drift,
                           "Each point is one run; along a line the iterations grow (relax and soft_step spend them as "
                           "substeps of one iteration). Drift is the largest horizontal distance any box moved from its "
                           "start; 1e-6 m stands for no motion."));
    bench.writePlot(plotOf("Sag beyond the slop against run time (" + runs + ")", "largest sag beyond slop per contact (m)", plots.sag,
                           "How far the most-sunk box sank beyond the slop per contact beneath it; 1e-6 m stands for "
                           "none."),
                    "-sag");
    bench.writePlot(plotOf("Deepest overlap against run time (" + runs + ")", "deepest overlap after 1 s (m)", plots.penetration,
                           "The deepest overlap between any two bodies after the first second."),
                    "-penetration");
    bench.writePlot(plotOf("Drift against run time, substeps 1 to 8 at 10 iterations (" + runs + ")",
                           "largest drift of a box (m)", plots.substepDrift,
                           "Each point is one run; along a line the substeps grow from 1 to 8."),
                    "-substeps");
    bench.writeTables({FigureTable{{"pyramids at the default settings (" + std::to_string(static_cast<int>(plan.sweepSeconds)) +
                                    " s each, " + realTypeName() + ")"},
                                   &pyramids},
                       FigureTable{{"the chapter's targets (" + std::to_string(static_cast<int>(plan.targetSeconds)) +
                                    " s each, 60 Hz, 10 iterations, 1 substep)"},
                                   &summary}},
                      "-summary");
}

void measureStackingBench(BenchRun& bench) {
    const StackingPlan plan = stackingPlan(bench.quick());
    CsvTable table({"part", "scene", "stabilisation", "warm_starting", "contacts", "iterations", "substeps", "drift_m",
                    "sag_beyond_slop_m", "sink_per_contact_m", "max_penetration_m", "step_ms", "stood"});
    StackingPlots plots;
    measureSweeps(bench, plan, table, plots);
    const CsvTable pyramids = measurePyramidSizes(bench, plan, table);
    const CsvTable summary = measureTargets(bench, plan, table);
    bench.progress().endStage();
    writeStackingResults(bench, plan, table, pyramids, summary, plots);
}

}  // namespace

BenchEntry stackingBench() {
    return benchEntry(6, measureStackingBench, R"(
        stacking: chapter 6: drift, sag and deepest overlap of pyramids against step time,
            iterations 1 to 50 and substeps 1 to 8, each stabilisation, warm starting on and
            off, manifolds and one point; pyramids of 10, 20, 40 rows; the chapter's targets
        stacking.csv              per part, scene, stabilisation, warm starting, contacts,
                                  iterations and substeps: drift, sag, sink per contact,
                                  deepest overlap, step ms
        stacking.svg              plot: drift against step time as the iterations grow
        stacking-sag.svg          plot: sag beyond the slop against step time
        stacking-penetration.svg  plot: deepest overlap against step time
        stacking-substeps.svg     plot: drift against step time as the substeps grow
        stacking-summary.svg      table: pyramids of each size, and the targets)");
}

}  // namespace stepwise
