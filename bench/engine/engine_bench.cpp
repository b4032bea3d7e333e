// `stepwise bench engine`: every reference scene over the sweep (suite.h), scored (reference.h);
// the CSV of every run, the summary (per scene: the defaults, the cheapest configuration that
// meets the tolerance, Bullet's), the error of each check at the defaults, and work-precision
// plots per group of scenes.
#include "engine/engine_bench.h"

#include "app/bench_util.h"
#include "engine/suite.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <ostream>
#include <random>

namespace stepwise::engine_bench {

namespace {

/// One scene run with one configuration, scored.
struct Outcome {
    const Configuration* configuration = nullptr;
    RunResult run;
    Score score;
    double cost = 0;   // ms per 1/60 s of simulated time: ms per step at the default dt
    bool scored() const { return run.failure.empty() || run.failure.rfind("blew up", 0) == 0; }
    bool refused() const { return run.failure.rfind("refused", 0) == 0; }
    bool meets() const { return run.failure.empty() && score.meets(); }
};

struct SceneResults {
    const ReferenceScene* scene = nullptr;
    std::vector<Outcome> outcomes;   // in sweep order
};

Outcome runOne(const ReferenceScene& scene, const Configuration& configuration) {
    Outcome outcome;
    outcome.configuration = &configuration;
    const World world = withKnobs(scene.world, configuration.knobs);
    outcome.run = configuration.peer ? runPeer(world, scene.sidecar.seconds, configuration.peerKnobs)
                                     : runEngine(world, scene.sidecar.seconds);
    if (!outcome.run.failure.empty()) {
        outcome.score.worst = std::numeric_limits<double>::infinity();
        return outcome;
    }
    outcome.score = scoreRun(scene.sidecar, outcome.run.trajectory);
    return outcome;
}

std::string scoreText(const Outcome& outcome) {
    if (outcome.refused()) return "refused";
    if (!outcome.run.failure.empty()) return "blew up";
    return std::isinf(outcome.score.worst) ? "unmeasured" : formatNumber(outcome.score.worst, 3);
}

const Outcome* findDefault(const SceneResults& results, bool peer);

/// The cheapest outcome of the engine (or of the peer) that meets every check; null when none.
/// With `atSceneDt`, only the engine's configurations that keep the scene's own dt: the knobs the
/// planner sets (substeps, iterations) and the ones a user sets without changing the frame rate
/// (a game stepped at 60 Hz must deliver a state every 1/60 s; only its author can halve that).
/// Timings of repeated runs scatter by a few per cent: a passing default is kept unless another
/// configuration is at least kCheaperBy cheaper.
const Outcome* cheapestPassing(const SceneResults& results, bool peer, bool atSceneDt = false) {
    constexpr double kCheaperBy = 0.1;
    const Real sceneDt = results.scene->world.settings.dt;
    const auto keepsDt = [&](const Outcome& outcome) {
        return withKnobs(results.scene->world, outcome.configuration->knobs).settings.dt == sceneDt;
    };
    const Outcome* best = nullptr;
    for (const Outcome& outcome : results.outcomes)
        if (outcome.configuration->peer == peer && outcome.meets() && (!atSceneDt || keepsDt(outcome)) &&
            (!best || outcome.cost < best->cost))
            best = &outcome;
    const Outcome* defaults = findDefault(results, peer);
    if (best && defaults && defaults->meets() && best->cost > (1 - kCheaperBy) * defaults->cost) return defaults;
    return best;
}

const Outcome* findDefault(const SceneResults& results, bool peer) {
    for (const Outcome& outcome : results.outcomes)
        if (outcome.configuration->peer == peer && outcome.configuration->family.find("default") != std::string::npos)
            return &outcome;
    return nullptr;
}

// [engine-bench-turns]
/// The configurations' runs are timed in turns: round after round, one more run of each, so a host
/// that slows down or speeds up over the minutes a scene takes (these VMs wander by a fifth and
/// more) moves every configuration's time alike, and the ratios the summary reports compare runs
/// made side by side, not minutes apart. Small scenes step in microseconds, where one run is
/// mostly the clock's noise: a configuration takes turns until its runs add up to
/// kTimedMsAtLeast, and its time is the median run. `only`: the configurations that take turns
/// (all when empty); `fewest`: the runs each of them has at least.
constexpr double kTimedMsAtLeast = 100;
constexpr std::size_t kMostRuns = 500;

void timeInTurns(SceneResults& results, const std::vector<const Outcome*>& only = {}, std::size_t fewest = 1) {
    const auto takesTurns = [&](const Outcome& outcome) {
        const bool chosen = only.empty() || std::find(only.begin(), only.end(), &outcome) != only.end();
        return chosen && outcome.run.failure.empty() && !outcome.run.timedRuns.empty();
    };
    const auto wantsMore = [&](const Outcome& outcome) {
        const std::vector<double>& runs = outcome.run.timedRuns;
        const double ms = std::accumulate(runs.begin(), runs.end(), 0.0) * double(outcome.run.frames);
        return takesTurns(outcome) && runs.size() < kMostRuns && (ms < kTimedMsAtLeast || runs.size() < fewest);
    };
    const ReferenceScene& scene = *results.scene;
    // Each round takes the configurations in another order, so none always follows the same one (a
    // run after Bullet's starts with Bullet's code and data in the caches). Seeded: runs repeat.
    std::vector<std::size_t> order(results.outcomes.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::mt19937 shuffler(2024);
    for (bool another = true; another;) {
        another = false;
        std::shuffle(order.begin(), order.end(), shuffler);
        for (const std::size_t index : order) {
            Outcome& outcome = results.outcomes[index];
            if (!wantsMore(outcome)) continue;
            const World world = withKnobs(scene.world, outcome.configuration->knobs);
            outcome.run.timedRuns.push_back(outcome.configuration->peer
                                                ? timePeer(world, outcome.run.frames, outcome.configuration->peerKnobs)
                                                : timeEngine(world, outcome.run.frames));
            another = true;
        }
    }
    for (Outcome& outcome : results.outcomes) {
        if (outcome.run.timedRuns.empty()) continue;
        outcome.run.msPerStep = median(outcome.run.timedRuns);
        const Real dt = withKnobs(scene.world, outcome.configuration->knobs).settings.dt;
        outcome.cost = outcome.run.msPerStep / (60.0 * double(dt));
    }
}

/// The runs the summary compares (each engine's defaults, their cheapest passing configurations)
/// take at least kFewestTurns turns beside one another: a scene whose run lasts seconds (the pile)
/// is timed more than once. A cheaper configuration found by the new times takes its turns too.
constexpr std::size_t kFewestTurns = 3;

void timeComparedInTurns(SceneResults& results, bool withPeer) {
    for (int pass = 0; pass < 3; ++pass) {
        std::vector<const Outcome*> compared;
        for (bool peer : {false, true}) {
            if (peer && !withPeer) continue;
            for (const Outcome* outcome : {findDefault(results, peer), cheapestPassing(results, peer),
                                           cheapestPassing(results, peer, /*atSceneDt=*/true)})
                if (outcome && std::find(compared.begin(), compared.end(), outcome) == compared.end())
                    compared.push_back(outcome);
        }
        const bool timed = std::all_of(compared.begin(), compared.end(), [](const Outcome* outcome) {
            return !outcome->run.failure.empty() || outcome->run.timedRuns.size() >= kFewestTurns;
        });
        if (timed) return;
        timeInTurns(results, compared, kFewestTurns);
    }
}
// [engine-bench-turns]

/// The CSV writer does not quote: a peer's refusal ("joints[0] (distance, ...") keeps its words
/// with its commas turned into semicolons, so the row keeps its columns.
std::string withoutCommas(std::string text) {
    std::replace(text.begin(), text.end(), ',', ';');
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
}

CsvTable runsTable(const std::vector<SceneResults>& all) {
    CsvTable table({"scene", "group", "bodies", "engine", "family", "configuration", "dt", "substeps", "iterations", "frames",
                    "ms_per_step", "ms_per_60th_s", "score", "meets", "worst_check", "errors", "note"});
    for (const SceneResults& results : all) {
        const ReferenceScene& scene = *results.scene;
        for (const Outcome& o : results.outcomes) {
            const Settings& s = withKnobs(scene.world, o.configuration->knobs).settings;
            std::string errors;
            for (std::size_t i = 0; i < o.score.errors.size(); ++i)
                errors += (i ? "; " : "") + scene.sidecar.checks[i].metric + " " + formatNumber(o.score.errors[i], 3);
            const bool peer = o.configuration->peer;
            table.addRow({scene.name, scene.sidecar.group, std::to_string(scene.world.dynamicBodyCount()),
                          peer ? peerName() : "stepwise", o.configuration->family, o.configuration->name,
                          formatNumber(double(s.dt), 4),
                          std::to_string(peer && o.configuration->peerKnobs.substeps ? o.configuration->peerKnobs.substeps : s.substeps),
                          std::to_string(peer && o.configuration->peerKnobs.iterations ? o.configuration->peerKnobs.iterations
                                                                                       : s.solverIterations),
                          std::to_string(o.run.frames), o.refused() ? "" : formatNumber(o.run.msPerStep),
                          o.refused() ? "" : formatNumber(o.cost), scoreText(o), o.meets() ? "yes" : "no",
                          o.run.failure.empty() ? scene.sidecar.checks[o.score.worstCheck].metric : "", errors,
                          withoutCommas(o.run.failure)});
        }
    }
    return table;
}

CsvTable summaryTable(const std::vector<SceneResults>& all, bool withPeer) {
    CsvTable table({"scene", "bodies", "default_score", "default_ms", "cheapest_passing", "cheapest_ms", "default_over_cheapest",
                    "cheapest_at_scene_dt", "default_over_it", "bullet_default_score", "bullet_default_ms", "bullet_cheapest_passing", "bullet_cheapest_ms",
                    "bullet_over_default"});
    for (const SceneResults& results : all) {
        const Outcome* engine = findDefault(results, false);
        const Outcome* cheapest = cheapestPassing(results, false);
        std::vector<std::string> row = {results.scene->name, std::to_string(results.scene->world.dynamicBodyCount()),
                                        scoreText(*engine), formatNumber(engine->cost, 3),
                                        cheapest ? cheapest->configuration->name : "none",
                                        cheapest ? formatNumber(cheapest->cost, 3) : "",
                                        cheapest ? formatNumber(engine->cost / cheapest->cost, 3) : ""};
        const Outcome* sameDt = cheapestPassing(results, false, /*atSceneDt=*/true);
        row.insert(row.end(), {sameDt ? sameDt->configuration->name : "none",
                               sameDt ? formatNumber(engine->cost / sameDt->cost, 3) : ""});
        const Outcome* peer = withPeer ? findDefault(results, true) : nullptr;
        if (!peer) {
            row.insert(row.end(), {"", "", "", "", ""});
        } else if (peer->refused()) {
            row.insert(row.end(), {"refused", "", "", "", ""});
        } else {
            const Outcome* peerCheapest = cheapestPassing(results, true);
            row.insert(row.end(), {scoreText(*peer), formatNumber(peer->cost, 3),
                                   peerCheapest ? peerCheapest->configuration->name : "none",
                                   peerCheapest ? formatNumber(peerCheapest->cost, 3) : "",
                                   formatNumber(peer->cost / engine->cost, 3)});
        }
        table.addRow(row);
    }
    return table;
}

/// Each check at the defaults: the error, the tolerance, and the reason for it.
CsvTable checksTable(const std::vector<SceneResults>& all, bool withPeer) {
    CsvTable table({"scene", "metric", "body", "tolerance", "stepwise_error", "stepwise_score", "bullet_error", "bullet_score"});
    for (const SceneResults& results : all) {
        const Outcome* engine = findDefault(results, false);
        const Outcome* peer = withPeer ? findDefault(results, true) : nullptr;
        const Sidecar& sidecar = results.scene->sidecar;
        for (std::size_t i = 0; i < sidecar.checks.size(); ++i) {
            const Check& check = sidecar.checks[i];
            const auto cells = [&](const Outcome* o) -> std::vector<std::string> {
                if (!o) return {"", ""};
                if (!o->run.failure.empty()) return {scoreText(*o), ""};
                return {formatNumber(o->score.errors[i], 3), formatNumber(o->score.errors[i] / check.tolerance, 3)};
            };
            std::vector<std::string> row = {results.scene->name, check.metric, check.body, formatNumber(check.tolerance, 3)};
            for (const Outcome* o : {engine, peer}) {
                const std::vector<std::string> pair = cells(o);
                row.insert(row.end(), pair.begin(), pair.end());
            }
            table.addRow(row);
        }
    }
    return table;
}

constexpr double kFloor = 1e-3, kCeiling = 1e3;  // scores drawn within these: zeros and blow-ups stay on the plot

double drawn(double score) { return std::clamp(score, kFloor, kCeiling); }

PlotSeries toleranceLine(double lowest, double highest) {
    PlotSeries line("tolerance (score 1)");
    line.dashed = line.lineOnly = true;
    line.x = {lowest, highest};
    line.y = {1, 1};
    return line;
}

// [engine-bench-plot]
/// Work precision of one scene: each configuration's cost against its score, one curve per
/// family (the points of a knob turned from cheap to dear), a marker for each default.
PlotSpec scenePlot(const SceneResults& results) {
    PlotSpec plot("work precision: " + results.scene->name, "ms per 1/60 s simulated", "error / tolerance (worst check)");
    std::vector<PlotSeries> families;
    double lowest = std::numeric_limits<double>::max(), highest = 0;
    for (const Outcome& o : results.outcomes) {
        if (o.refused()) continue;
        const std::string& family = o.configuration->family;
        if (families.empty() || families.back().title != family) {
            const bool curve = family == "dt" || family == "substeps" || family == "iterations" ||
                               family == "bullet iterations" || family == "bullet substeps";
            families.emplace_back(family, !curve);
        }
        families.back().x.push_back(o.cost);
        families.back().y.push_back(drawn(o.score.worst));
        lowest = std::min(lowest, o.cost);
        highest = std::max(highest, o.cost);
    }
    plot.series = families;
    if (highest > 0) plot.series.push_back(toleranceLine(lowest, highest));
    plot.caption = results.scene->name + ": each point one configuration, x its median ms per 1/60 s of simulated time "
                   "(ms per step at the default dt), y the worst error / tolerance over the scene's checks (at most 1 "
                   "meets every tolerance; drawn within 0.001 and 1000, a blow-up at 1000). Down and left is better. "
                   "Single thread, " + std::string(realTypeName()) + " build.";
    return plot;
}
// [engine-bench-plot]

/// Where each engine's defaults land on every scene: one marker per scene and engine.
PlotSpec defaultsPlot(const std::vector<SceneResults>& all, bool withPeer) {
    PlotSpec plot("the defaults on every reference scene", "ms per 1/60 s simulated", "error / tolerance (worst check)");
    PlotSeries engine("stepwise defaults", true), peer(peerName() + " defaults", true);
    double lowest = std::numeric_limits<double>::max(), highest = 0;
    for (const SceneResults& results : all)
        for (bool isPeer : {false, true}) {
            const Outcome* o = isPeer && !withPeer ? nullptr : findDefault(results, isPeer);
            if (!o || o->refused()) continue;
            (isPeer ? peer : engine).x.push_back(o->cost);
            (isPeer ? peer : engine).y.push_back(drawn(o->score.worst));
            lowest = std::min(lowest, o->cost);
            highest = std::max(highest, o->cost);
        }
    plot.series.push_back(engine);
    if (withPeer) plot.series.push_back(peer);
    if (highest > 0) plot.series.push_back(toleranceLine(lowest, highest));
    plot.caption = "One marker per reference scene and engine at its default settings: x the median ms per 1/60 s of "
                   "simulated time, y the worst error / tolerance (at most 1 meets the reference; drawn within 0.001 and "
                   "1000). The summary table names the scenes. Single thread, " + std::string(realTypeName()) + " build.";
    return plot;
}

void measureEngine(BenchRun& bench) {
    const BenchOptions& options = bench.options();
    if (!options.peer.empty() && options.peer != "bullet")
        throw std::runtime_error("--peer: unknown peer \"" + options.peer + "\" (known: bullet)");
    const bool withPeer = options.peer == "bullet" && havePeer();
    std::ostream& out = bench.out();
    if (options.peer == "bullet" && !withPeer)
        out << "bench engine: this program was built without the Bullet peer (libbullet-dev not found): Bullet skipped\n";
    const std::string directory = options.scenesDir.empty() ? std::string(STEPWISE_REFERENCE_SCENES) : options.scenesDir;
    const std::vector<ReferenceScene> scenes = loadReferenceScenes(directory);
    const std::vector<Configuration> list = sweep(bench.quick(), withPeer);

    std::vector<SceneResults> all;
    for (const ReferenceScene& scene : scenes) {
        bench.progress().stage(scene.name, static_cast<long>(list.size()) + 1);  // + the turns
        SceneResults results;
        results.scene = &scene;
        for (const Configuration& configuration : list) {
            results.outcomes.push_back(runOne(scene, configuration));
            bench.progress().advance();
        }
        timeInTurns(results);
        timeComparedInTurns(results, withPeer);
        bench.progress().advance();
        all.push_back(std::move(results));
    }
    bench.progress().endStage();

    const CsvTable runs = runsTable(all), summary = summaryTable(all, withPeer), checks = checksTable(all, withPeer);
    out << "bench engine: " << scenes.size() << (scenes.size() == 1 ? " reference scene" : " reference scenes")
        << " from " << directory << ", " << list.size()
        << " configurations" << (withPeer ? " (Bullet: " + peerName() + ")" : "") << ", " << realTypeName() << " build\n\n"
        << "score = error / tolerance, worst check; <= 1 meets the reference. ms: per 1/60 s simulated.\n"
        << summary.toText() << "\neach check at the defaults:\n" << checks.toText();
    for (const SceneResults& results : all)
        for (const Outcome& o : results.outcomes)
            if (o.refused() && o.configuration->family == "bullet default")
                out << "\n" << results.scene->name << ": Bullet " << o.run.failure;
    out << "\n";
    bench.writeCsv(runs);
    bench.writeCsv(summary, "-summary");
    bench.writeCsv(checks, "-checks");
    bench.writePlot(defaultsPlot(all, withPeer));
    for (const SceneResults& results : all) bench.writePlotFor(scenePlot(results), "-scene", results.scene->name);
    const std::vector<FigureTable> figures = {
        {{"Per scene: score (worst error / tolerance) and ms per 1/60 s at the defaults, the cheapest configuration "
          "that meets every tolerance, and Bullet's."}, &summary},
        {{"Each check at the defaults: error (in the check's units), tolerance, score."}, &checks}};
    bench.writeTables(figures, "-tables");
}

}  // namespace

BenchEntry engineBench() {
    return benchEntry(10, measureEngine, R"(
        engine: the whole engine on the reference suite (scenes/reference): error against the
            known answer and ms per step over a sweep of its knobs, Bullet beside it with
            --peer bullet
        engine.csv           every run: scene, configuration, ms per step, score, each check's
                             error
        engine-summary.csv   per scene: the defaults, the cheapest passing configuration,
                             Bullet's
        engine-checks.csv    each check at the defaults: error, tolerance, score
        engine.svg           every scene's error against ms at each engine's defaults
        engine-tables.svg    the summary and the checks as a figure for the page
        engine-scene-*.svg   work precision of one scene, one curve per family of
                             configurations)");
}

}  // namespace stepwise::engine_bench
