// `stepwise bench joints`: how far chains stretch and ragdolls come apart, against what a step
// costs, as the solver iterations, the substeps, the joint order and the joints' feedback vary.
//
//   iterations  each chain and the ragdoll pile at 2 to 40 solver iterations (the relax solve's
//               substeps of one sweep each), 1 to 4 frame substeps.
//   order       the chains at the default settings, joints swept as listed, leaves first, ground first.
//   feedback    the hanging chain with rigid Baumgarte rows, and with soft rows of half the
//               (sub)step rate instead of a quarter.
//   direct      the chains with their joint rows swept 50 times per iteration (Gauss-Seidel near
//               convergence: a stand-in for a direct solve along the chain), and at 200 iterations.
//
// Chains: the largest stretch over the run and the final one (chainStretch). Ragdolls: the largest
// joint error over the last second. A run stops when a chain is 100% longer than at rest or not
// finite (rigid rows diverge), and says when. Step times are the thread's CPU time. The runs
// themselves are in joints_runs.cpp.
#include "08_joints/benches.h"

#include "08_joints/joints_runs.h"
#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace stepwise {

namespace joints_bench {
namespace {

std::string cell(double value) { return std::isnan(value) ? "-" : formatNumber(value); }

void addRow(CsvTable& table, Case which, const Config& config, const Outcome& m) {
    table.addRow({caseName(which), toString(config.order), feedbackName(config), config.warm ? "on" : "off",
                  std::to_string(config.iterations), std::to_string(config.substeps), std::to_string(config.sweeps),
                  formatNumber(m.seconds), formatNumber(m.stepMs), cell(m.largestStretch), cell(m.finalStretch),
                  formatNumber(double(m.error.position)), formatNumber(double(m.error.angle))});
}

/// Values below this are drawn at it on the log axes.
constexpr double kFloor = 1e-7;

void addPoint(PlotSeries& series, double ms, double value) {
    series.x.push_back(std::max(ms, 1e-4));
    series.y.push_back(std::isfinite(value) ? std::max(value, kFloor) : 10.0);
}

std::string percent(double fraction) { return std::isfinite(fraction) ? formatNumber(100 * fraction, 3) + "%" : "not finite"; }

/// The suite's sizes: a quick run's or a full run's.
struct JointBenchPlan {
    double chainSeconds = 10, pileSeconds = 4;
    int ragdolls = 5;
    std::vector<int> iterationCounts, substepCounts;
};

JointBenchPlan jointBenchPlan(bool quick) {
    JointBenchPlan plan;
    plan.chainSeconds = quick ? 3 : 10;
    plan.pileSeconds = quick ? 2.5 : 4;
    plan.ragdolls = quick ? 3 : 5;
    plan.iterationCounts = quick ? std::vector<int>{2, 10, 40} : std::vector<int>{2, 4, 6, 10, 20, 40};
    plan.substepCounts = quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 4};
    return plan;
}

/// The plots' series, by line name.
struct JointPlots {
    std::map<std::string, PlotSeries> stretch, pile, bySubsteps;
};

/// Every case at every iteration and substep count: the main table and the plots' points; the
/// outcomes at the default settings, by case.
std::map<Case, Outcome> measureIterations(BenchRun& bench, const JointBenchPlan& plan, CsvTable& table, JointPlots& plots) {
    std::vector<Case> cases(std::begin(kChains), std::end(kChains));
    cases.push_back(Case::RagdollPile);

    bench.progress().stage("iterations", long(cases.size() * plan.iterationCounts.size() * plan.substepCounts.size()));
    std::map<Case, Outcome> defaults;
    for (Case which : cases) {
        for (int substeps : plan.substepCounts) {
            for (int iterations : plan.iterationCounts) {
                Config config;
                config.iterations = iterations;
                config.substeps = substeps;
                const Outcome m = run(which, config, which == Case::RagdollPile ? plan.pileSeconds : plan.chainSeconds, plan.ragdolls);
                addRow(table, which, config, m);
                if (iterations == Config{}.iterations && substeps == 1) defaults[which] = m;
                const std::string steps = std::to_string(substeps) + (substeps == 1 ? " substep" : " substeps");
                if (which == Case::RagdollPile) {
                    addPoint(plots.pile["position (m), " + steps], m.stepMs, double(m.error.position));
                    addPoint(plots.pile["angle (rad), " + steps], m.stepMs, double(m.error.angle));
                } else {
                    if (substeps == 1) addPoint(plots.stretch[caseName(which)], m.stepMs, m.largestStretch);
                    if (which == Case::Swinging) addPoint(plots.bySubsteps[steps], m.stepMs, m.largestStretch);
                }
                bench.progress().advance();
            }
        }
    }

    return defaults;
}

/// Joint order at the default settings, and without warm starting (each substep's sweep then
/// starts from no impulse, and the order decides which way along the chain it carries a change).
CsvTable measureOrders(BenchRun& bench, const JointBenchPlan& plan, CsvTable& table) {
    CsvTable orders({"case", "order", "warm starting", "largest stretch", "final stretch", "step (ms)"});
    bench.progress().stage("order and feedback", long(std::size(kChains) * 6 + 2));
    for (Case which : kChains) {
        for (bool warm : {true, false}) {
            for (JointOrder order : {JointOrder::AsListed, JointOrder::LeavesFirst, JointOrder::GroundFirst}) {
                Config config;
                config.order = order;
                config.warm = warm;
                const Outcome m = run(which, config, plan.chainSeconds, plan.ragdolls);
                addRow(table, which, config, m);
                orders.addRow({caseName(which), toString(order), warm ? "on" : "off", percent(m.largestStretch),
                               percent(m.finalStretch), formatNumber(m.stepMs)});
                bench.progress().advance();
            }
        }
    }
    return orders;
}

/// The hanging chain with each kind of joint feedback.
CsvTable measureFeedback(BenchRun& bench, const JointBenchPlan& plan, CsvTable& table, const Outcome& hangingDefault) {
    CsvTable feedback({"case", "feedback", "ran (s)", "largest stretch", "final stretch", "step (ms)"});
    const auto addFeedback = [&](Case which, const Config& config, const Outcome& m) {
        feedback.addRow({caseName(which), feedbackName(config), formatNumber(m.seconds), percent(m.largestStretch),
                         percent(m.finalStretch), formatNumber(m.stepMs)});
    };
    addFeedback(Case::Hanging, Config{}, hangingDefault);
    Config rigid, stiffer;
    rigid.feedback = JointFeedback::Kind::Baumgarte;
    stiffer.hertzPerRate = 2 * kJointHertzPerStepRate;
    for (const Config& config : {rigid, stiffer}) {
        const Outcome m = run(Case::Hanging, config, plan.chainSeconds, plan.ragdolls);
        addRow(table, Case::Hanging, config, m);
        addFeedback(Case::Hanging, config, m);
        bench.progress().advance();
    }

    return feedback;
}

/// What a direct solve would buy: the same chains with their joints (near) converged.
CsvTable measureDirect(BenchRun& bench, const JointBenchPlan& plan, CsvTable& table, const std::map<Case, Outcome>& defaults) {
    const bool quick = bench.quick();
    CsvTable direct({"case", "solve", "largest stretch", "final stretch", "springs' sag at rest", "step (ms)", "cost"});
    const int sweeps = 50, manyIterations = 200;
    bench.progress().stage("direct", long(std::size(kChains) * (quick ? 1 : 2)));
    for (Case which : kChains) {
        const Outcome& base = defaults.at(which);
        const auto addDirect = [&](const std::string& solve, const Outcome& m) {
            direct.addRow({caseName(which), solve, percent(m.largestStretch), percent(m.finalStretch),
                           std::isnan(m.restingSag) ? "-" : percent(m.restingSag), formatNumber(m.stepMs),
                           formatNumber(m.stepMs / base.stepMs, 3) + "x"});
        };
        addDirect("default (10 iterations)", base);
        Config converged;
        converged.sweeps = sweeps;
        const Outcome swept = run(which, converged, plan.chainSeconds, plan.ragdolls);
        addRow(table, which, converged, swept);
        addDirect("joints swept " + std::to_string(sweeps) + "x per iteration", swept);
        bench.progress().advance();
        if (quick) continue;  // 200 iterations: full runs only
        Config many;
        many.iterations = manyIterations;
        const Outcome deep = run(which, many, plan.chainSeconds, plan.ragdolls);
        addRow(table, which, many, deep);
        addDirect(std::to_string(manyIterations) + " iterations", deep);
        bench.progress().advance();
    }
    bench.progress().endStage();

    return direct;
}

/// The tables as text and as a figure, the CSV and the three plots.
void writeJointResults(BenchRun& bench, const JointBenchPlan& plan, const CsvTable& table, const CsvTable& orders,
                       const CsvTable& feedback, const CsvTable& direct, JointPlots& plots) {
    std::ostream& out = bench.out();
    const std::string setting = std::string(realTypeName()) + ", 60 Hz, " + formatNumber(plan.chainSeconds) + " s per chain run";
    out << table.toText() << "\njoint order at the default settings (" << setting << "):\n" << orders.toText()
        << "\nfeedback, hanging chain (" << setting << "):\n" << feedback.toText()
        << "\nwhat a direct solve would buy (" << setting << "):\n" << direct.toText();
    bench.writeCsv(table);

    PlotSpec plot("Chain stretch against run time, iterations " + std::to_string(plan.iterationCounts.front()) + " to " +
                      std::to_string(plan.iterationCounts.back()) + " (" + setting + ")",
                  "step time (ms, CPU)", "largest stretch (fraction of rest length)");
    plot.caption = "Each point is one run; along a line the solver iterations grow (the relax solve's substeps of one sweep "
                   "each). Chains of 20 links of 1 kg (hanging at rest; released from horizontal) and of 10 links with a "
                   "10 kg end link, 25 cm apart, distance joints, one frame substep.";
    for (auto& [name, series] : plots.stretch) {
        series.title = name;
        plot.series.push_back(series);
    }
    bench.writePlot(plot);
    PlotSpec substepPlot("Swinging chain: iterations or substeps (" + setting + ")", "step time (ms, CPU)",
                         "largest stretch (fraction of rest length)");
    substepPlot.caption = "The 20-link chain released from horizontal; along each line the iterations grow, one line per "
                          "count of frame substeps (each runs the whole pipeline).";
    for (auto& [name, series] : plots.bySubsteps) {
        series.title = name;
        substepPlot.series.push_back(series);
    }
    bench.writePlot(substepPlot, "-substeps");
    PlotSpec pilePlot("Ragdoll pile: joint error against run time (" + std::to_string(plan.ragdolls) + " ragdolls, " +
                          realTypeName() + ")",
                      "step time (ms, CPU)", "largest joint error over the last second");
    pilePlot.caption = "Ragdolls dropped in a pile (chapter 8's builder), " + formatNumber(plan.pileSeconds) +
                       " s at 60 Hz; the largest anchor gap (m) and angle past a limit or off a locked axis (rad) of any "
                       "joint over the last second. Along a line the iterations grow.";
    for (auto& [name, series] : plots.pile) {
        series.title = name;
        pilePlot.series.push_back(series);
    }
    bench.writePlot(pilePlot, "-ragdolls");
    bench.writeTables({FigureTable{{"joint order at the default settings (" + setting + ")"}, &orders},
                       FigureTable{{"feedback of the joint rows, hanging 20-link chain"}, &feedback},
                       FigureTable{{"what a direct solve would buy: the chains with their joints (near) converged"}, &direct}},
                      "-summary");
}

void measureJoints(BenchRun& bench) {
    const JointBenchPlan plan = jointBenchPlan(bench.quick());
    CsvTable table({"case", "order", "feedback", "warm_starting", "iterations", "substeps", "joint_sweeps", "seconds", "step_ms",
                    "largest_stretch", "final_stretch", "joint_error_m", "joint_error_rad"});
    JointPlots plots;
    const std::map<Case, Outcome> defaults = measureIterations(bench, plan, table, plots);
    const CsvTable orders = measureOrders(bench, plan, table);
    const CsvTable feedback = measureFeedback(bench, plan, table, defaults.at(Case::Hanging));
    const CsvTable direct = measureDirect(bench, plan, table, defaults);
    writeJointResults(bench, plan, table, orders, feedback, direct, plots);
}

}  // namespace
}  // namespace joints_bench

BenchEntry jointsBench() {
    return benchEntry(8, joints_bench::measureJoints, R"(
        joints: chain stretch and ragdoll joint error against step time: iterations, substeps,
            joint order, rigid and soft feedback, near-converged joints
        joints.csv           per case, order, feedback, iterations, substeps and joint sweeps:
                             step ms, stretch, joint error
        joints.svg           largest chain stretch against step time as the iterations grow
        joints-substeps.svg  the swinging chain: iterations against frame substeps
        joints-ragdolls.svg  the ragdoll pile's joint error against step time
        joints-summary.svg   joint order, feedback, and near-converged joints)");
}

}  // namespace stepwise
