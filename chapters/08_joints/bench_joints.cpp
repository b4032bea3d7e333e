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
// finite (rigid rows diverge), and says when. Step times are the thread's CPU time.
#include "08_joints/benches.h"

#include "06_manifolds/chapter.h"
#include "08_joints/builders.h"
#include "08_joints/chapter.h"
#include "08_joints/scenes.h"
#include "app/bench_util.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace stepwise {

namespace {

enum class Case { Hanging, Swinging, HeavyEnd, HeavyEndSwinging, RagdollPile };

const char* caseName(Case which) {
    switch (which) {
        case Case::Hanging: return "hanging_chain";
        case Case::Swinging: return "swinging_chain";
        case Case::HeavyEnd: return "heavy_end_chain";
        case Case::HeavyEndSwinging: return "heavy_end_swinging";
        case Case::RagdollPile: return "ragdoll_pile";
    }
    return "?";
}

const Case kChains[] = {Case::Hanging, Case::Swinging, Case::HeavyEnd, Case::HeavyEndSwinging};

struct Config {
    JointOrder order = kDefaultJointOrder;
    JointFeedback::Kind feedback = JointFeedback::Kind::Soft;
    bool warm = true;                            // Settings::warmStarting
    int iterations = Settings{}.solverIterations;
    int substeps = 1;
    int sweeps = 1;                              // joint sweeps per solver iteration
    Real hertzPerRate = kJointHertzPerStepRate;  // the soft rows' stiffness
};

const char* feedbackName(const Config& config) {
    if (config.feedback == JointFeedback::Kind::Baumgarte) return "baumgarte";
    return config.hertzPerRate == kJointHertzPerStepRate ? "soft" : "soft_half_rate";
}

// [ch08-bench-variants]
/// Chapter 8's joint passes (JointConstraints, joint_solver.cpp) with the two knobs the engine
/// fixes and the bench varies: how many times each iteration sweeps the joint rows, and the soft
/// rows' frequency as a fraction of the (sub)step rate.
class VariedJoints final : public ExtraConstraints {
public:
    explicit VariedJoints(const Config& config) : config_(config) {}
    bool active(const World& world) const override { return !world.joints.empty(); }
    void prepare(const World& world, const std::vector<SolverBody>& bodies, Real h, bool positionFeedback) override {
        rows_ = JointRows{};  // prepared again for every (sub)step and pass
        JointFeedback feedback = jointFeedback(world.settings, h, config_.feedback);
        feedback.soft = makeSoftness(config_.hertzPerRate / h, kJointDampingRatio, h);
        if (!positionFeedback) feedback.kind = JointFeedback::Kind::None;
        const bool carry = !positionFeedback || world.settings.warmStarting;
        for (int joint : jointSolveOrder(world, config_.order)) appendJointRows(rows_, world, joint, bodies, h, feedback, carry);
    }
    void warmStart(std::vector<SolverBody>& bodies) override {
        for (const ConstraintRow& row : rows_.rows)
            if (row.impulse != 0) applyRowImpulse(row, row.impulse, bodies);
    }
    void iterate(std::vector<SolverBody>& bodies) override {
        for (int sweep = 0; sweep < config_.sweeps; ++sweep)
            for (const JointRowSet& set : rows_.joints) solveJointRows(rows_, set, bodies);
    }
    void store(World& world) const override {
        world.jointImpulses.resize(world.joints.size());
        for (const JointRowSet& set : rows_.joints)
            for (int slot = 0; slot < set.rowCount && slot < JointImpulses::kSlots; ++slot)
                world.jointImpulses[static_cast<std::size_t>(set.joint)].slot[slot] =
                    rows_.rows[static_cast<std::size_t>(set.firstRow + slot)].impulse;
    }

private:
    Config config_;
    JointRows rows_;
};

/// The chapter's pipeline; a varied configuration swaps its solve for one with VariedJoints.
Pipeline pipelineFor(const World& world, const Config& config) {
    Pipeline pipeline = makeChapter08Pipeline(world, JointOptions{config.order, config.feedback});
    if (config.sweeps == 1 && config.hertzPerRate == kJointHertzPerStepRate) return pipeline;
    const bool split = chooseStepOrder(world) == StepOrder::SplitIntegration;
    if (Stage* solve = pipeline.find(stage_group::kSolve))
        solve->run = [split, config](World& stepWorld, Real dt) {
            VariedJoints joints(config);
            runStabilisedSolve(stepWorld, dt, split, &joints);
        };
    return pipeline;
}
// [ch08-bench-variants]

// [ch08-bench-sag]
/// How long soft joints hold a hanging chain at rest, whatever the solver: at rest each row is a
/// spring of stiffness m_eff w^2 (Box2D's soft constraint, w = 2 pi hertz) carrying the weight
/// below it, so it is longer by that weight over m_eff w^2. Summed over the joints, as a fraction
/// of the rest length.
double restingSag(const World& world, const Chain& chain, const Config& config) {
    const double h = double(world.settings.dt) / (config.iterations * config.substeps);
    const double omega = 2 * double(kPi) * double(config.hertzPerRate) / h;
    const auto inverseMass = [&](int body) {
        const Motion* motion = world.motionOf(body);
        return motion ? double(motion->inverseMass) : 0.0;
    };
    double below = 0, sag = 0;  // N of weight below the joint; m
    for (auto joint = chain.joints.rbegin(); joint != chain.joints.rend(); ++joint) {
        const JointDesc& desc = world.joints[static_cast<std::size_t>(*joint)];
        below += double(world.settings.gravity.norm()) / inverseMass(desc.bodyB);
        sag += below * (inverseMass(desc.bodyA) + inverseMass(desc.bodyB)) / (omega * omega);
    }
    return sag / double(chain.restLength);
}
// [ch08-bench-sag]

struct Outcome {
    double seconds = 0;       // simulated; less than asked when the run stopped
    double stepMs = 0;
    double largestStretch = std::nan("");  // chains only
    double finalStretch = std::nan("");
    double restingSag = std::nan("");      // chains hanging at rest only
    JointErrorSummary error;  // chains: over the run; ragdolls: over the last second
};

// [ch08-bench-run]
/// One case through one configuration for `seconds` of 60 Hz frames.
Outcome run(Case which, const Config& config, double seconds, int ragdolls) {
    World world;
    Chain chain;
    std::vector<int> joints;
    if (which == Case::RagdollPile) {
        world = buildRagdollPile(ragdolls);
        for (int i = 0; i < static_cast<int>(world.joints.size()); ++i) joints.push_back(i);
    } else {
        ChainSpec spec;
        spec.links = (which == Case::Hanging || which == Case::Swinging) ? 20 : 10;
        spec.endMass = (which == Case::HeavyEnd || which == Case::HeavyEndSwinging) ? 10 : 0;
        if (which == Case::Swinging || which == Case::HeavyEndSwinging) spec.direction = Vec3(1, 0, 0);
        chain = addChain(world, spec);
        joints = chain.joints;
    }
    world.settings.solverIterations = config.iterations;
    world.settings.substeps = config.substeps;
    world.settings.warmStarting = config.warm;
    Outcome outcome;
    if (which == Case::Hanging || which == Case::HeavyEnd) outcome.restingSag = restingSag(world, chain, config);
    Pipeline pipeline = pipelineFor(world, config);
    const int frames = static_cast<int>(std::lround(seconds / double(world.settings.dt)));
    const int measuredFrom = which == Case::RagdollPile ? frames - static_cast<int>(std::lround(1 / double(world.settings.dt))) : 0;
    double cpu = 0;
    int frame = 0;
    for (; frame < frames; ++frame) {
        ThreadStopwatch clock;
        pipeline.step(world);
        cpu += clock.seconds();
        if (frame >= measuredFrom) {
            const JointErrorSummary error = largestJointError(world, joints);
            outcome.error.position = std::max(outcome.error.position, error.position);
            outcome.error.angle = std::max(outcome.error.angle, error.angle);
        }
        if (which == Case::RagdollPile) continue;
        const double stretch = double(chainStretch(world, chain));
        outcome.finalStretch = stretch;
        outcome.largestStretch = std::isnan(outcome.largestStretch) ? stretch : std::max(outcome.largestStretch, stretch);
        if (!std::isfinite(stretch) || stretch > 1) {  // diverged: the rest would measure nothing
            ++frame;
            break;
        }
    }
    outcome.seconds = frame * double(world.settings.dt);
    outcome.stepMs = 1e3 * cpu / std::max(1, frame);
    return outcome;
}
// [ch08-bench-run]

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

BenchEntry jointsBench() {
    return benchEntry(8, measureJoints, R"(
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
