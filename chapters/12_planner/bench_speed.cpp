// `stepwise bench speed`: what each of chapter 10's optimisations buys, and where the engine stands
// beside Bullet (when the program was built with the peer), on the scenes of the chapter's targets.
#include "12_planner/benches.h"

#include "12_planner/chapter.h"
#include "12_planner/speed_runs.h"
#include "12_planner/contact_truth.h"
#include "08_joints/builders.h"
#include "08_joints/scenes.h"
#include "10_skip_work/scenes.h"
#include "11_wide_solve/scenes.h"
#include "app/bench_util.h"
#include "app/peer.h"
#include "world/state_hash.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <ostream>

namespace stepwise {

namespace {

using speed_bench::Measurement;
using speed_bench::framesUntilAsleep;
using speed_bench::runBeside;
using speed_bench::runEngine;

/// One way to run a scene: the chapter's step with some optimisations off, or the peer.
struct Configuration {
    std::string name;
    SpeedOptions options;
    bool peer = false;
};

std::vector<Configuration> configurations(bool withPeer) {
    std::vector<Configuration> list;
    SpeedOptions all;
    all.sleeping = false;  // the targets are timed awake; sleeping has its own measurement
    list.push_back({"fast step", all, false});
    SpeedOptions scalar = all;
    scalar.solverPath = SolverPath::Scalar;
    list.push_back({"scalar solve", scalar, false});
    SpeedOptions noCache = all;
    noCache.contactCache.enabled = false;
    list.push_back({"no contact cache", noCache, false});
    SpeedOptions noBoxBox = all;
    noBoxBox.boxBoxQuery = false;
    list.push_back({"no box-box query", noBoxBox, false});
    SpeedOptions noShock = all;
    noShock.shockPropagation = false;
    list.push_back({"no shock sweep", noShock, false});
    SpeedOptions reference = all;
    reference.fastSolve = false;
    list.push_back({"chapter 8's solve", reference, false});
    if (withPeer) list.push_back({peerEngine().name, all, true});
    return list;
}


struct BenchScene {
    std::string name;
    World world;
    long frames;
    long timedFrom;     // frames before it are not timed (the pile's first contacts)
    bool joints = false;  // timed by the fast step, its scalar solve and chapter 8's solve only
};

/// Every scene through every configuration (the peer beside the first): the main table and the
/// solve's profile.
void measureScenes(BenchRun& bench, const std::vector<BenchScene>& scenes, const std::vector<Configuration>& list,
                   bool withPeer, CsvTable& table, CsvTable& profile) {
    bench.progress().stage("scenes x configurations", static_cast<long>(scenes.size() * list.size()));
    for (const BenchScene& scene : scenes) {
        const int bodies = scene.world.dynamicBodyCount();
        std::vector<std::pair<const Configuration*, Measurement>> results(list.size());
        for (std::size_t i = 0; i < list.size(); ++i) {
            const Configuration& configuration = list[i];
            if (configuration.peer) continue;  // beside the fast step (below)
            const bool jointScene = configuration.options.fastSolve && configuration.options.solverPath == SolverPath::Wide;
            if (scene.joints && i > 0 && jointScene) continue;  // the contact optimisations: the contact scenes'
            if (i == 0 && withPeer) {
                try {
                    auto [engine, peer] = runBeside(scene.world, configuration.options, scene.frames, scene.timedFrom);
                    results[0] = {&configuration, engine};
                    results.back() = {&list.back(), peer};
                } catch (const std::runtime_error& refused) {  // a joint or spring the peer has not
                    bench.out() << "bench speed: " << scene.name << ": the peer refuses the scene: " << refused.what() << "\n";
                    results[0] = {&configuration, runEngine(scene.world, configuration.options, scene.frames, scene.timedFrom)};
                }
                bench.progress().advance();
                bench.progress().advance();
                continue;
            }
            // Chapter 8's solve is slow on thousands of bodies: a second of simulated time measures it
            // (all of a joint scene's: its error is measured over the last second).
            const long frames = configuration.options.fastSolve || scene.joints ? scene.frames : std::min<long>(scene.frames, 60);
            results[i] = {&configuration, runEngine(scene.world, configuration.options, frames, scene.timedFrom)};
            bench.progress().advance();
        }
        if (!scene.joints) {
            const ContactDepthErrors errors = depthAgainstTrue(scene.world, list.front().options, scene.frames);
            results.front().second.beyondTrue = errors.deeper;
            results.front().second.shortOfTrue = errors.shallower;
        }
        // The profile: the first configuration again, its phases clocked (not timed as a whole).
        const Measurement fast = runEngine(scene.world, list.front().options, scene.frames, scene.timedFrom, /*profile=*/true);
        const FastSolveStats& phases = fast.solvePhases;
        std::vector<std::string> row = {scene.name, std::to_string(phases.manifolds), std::to_string(phases.points)};
        for (double ms : phases.phaseMs) row.push_back(formatNumber(ms));
        const long builds = fast.jointsBuilt + fast.jointsKept;
        row.push_back(builds > 0 ? formatNumber(static_cast<double>(fast.jointsKept) / static_cast<double>(builds)) : "");
        profile.addRow(std::move(row));
        const double peerMs = withPeer ? results.back().second.stepMs.median : 0;
        for (const auto& result : results) {
            const Configuration* configuration = result.first;
            if (!configuration) continue;  // not run on this scene
            const Measurement& m = result.second;
            auto stage = [&](const char* group) {
                const auto found = m.stageMs.find(group);
                return found == m.stageMs.end() ? std::string("") : formatNumber(found->second);
            };
            table.addRow({scene.name, std::to_string(bodies), configuration->name, std::to_string(m.frames),
                          formatNumber(m.stepMs.median), formatNumber(m.stepMs.lower), formatNumber(m.stepMs.upper),
                          stage(stage_group::kBroadphase), stage(stage_group::kNarrowphase), stage(stage_group::kSolve),
                          formatNumber(1e6 * m.stepMs.median / bodies), formatNumber(m.maxSideways),
                          formatNumber(m.lowest), configuration->peer ? "" : formatNumber(m.maxPenetration),
                          scene.joints && !configuration->peer ? formatNumber(m.jointError.position) : "",
                          scene.joints && !configuration->peer ? formatNumber(m.jointError.angle) : "",
                          peerMs > 0 ? formatNumber(peerMs / m.stepMs.median, 3) : "",
                          m.beyondTrue >= 0 ? formatNumber(m.beyondTrue) : "",
                          m.shortOfTrue >= 0 ? formatNumber(m.shortOfTrue) : "",
                          m.jointGapMean >= 0 ? formatNumber(m.jointGapMean) : ""});
        }
    }
    bench.progress().endStage();

}

/// Settled piles with sleeping on and off.
void measureSleep(BenchRun& bench, CsvTable& sleepTable) {
    const bool quick = bench.quick();
    // Piles that have settled, stepped until every body sleeps (at most a minute): the step with
    // sleeping on against the same step awake. The mixed pile's spheres and capsules have a little
    // rolling resistance: without it they roll, or spin in place on one point, for ever, and one
    // moving body keeps its whole island awake. The pile of boxes and hulls alone is measured beside
    // it. A settled pile still has its late slides (a body that creeps, then tips), so the frame at
    // which it has all slept varies from build to build: it is measured, not assumed.
    bench.progress().stage("settled piles, asleep and awake", 6);
    // The ragdolls with their joint friction, as the chapter builds them.
    const std::vector<World> piles = {buildMixedPile(quick ? 300 : 2000, true), buildMixedPile(quick ? 300 : 2000, false),
                                      buildRagdollField(quick ? 20 : 100)};
    for (const World& pile : piles) {
        const long settle = framesUntilAsleep(pile, quick ? 600 : 3600);
        SpeedOptions asleep, awake;
        awake.sleeping = false;
        const Measurement sleeping = runEngine(pile, asleep, settle + 60, settle);
        bench.progress().advance();
        const Measurement notSleeping = runEngine(pile, awake, settle + 60, settle);
        bench.progress().advance();
        const int bodies = pile.dynamicBodyCount();
        sleepTable.addRow({pile.name, std::to_string(bodies), "on", std::to_string(settle), std::to_string(sleeping.sleeping),
                           formatNumber(sleeping.stepMs.median),
                           formatNumber(sleeping.stepMs.median / notSleeping.stepMs.median, 3)});
        sleepTable.addRow({pile.name, std::to_string(bodies), "off", std::to_string(settle), "0",
                           formatNumber(notSleeping.stepMs.median), "1"});
    }
    bench.progress().endStage();

}

// [ch12-unlike-drops]
/// The unlike pile's drops: its drop, and the same drop with one body moved a tenth of a
/// millimetre further each time. A pile is chaotic: where a late-settling body rolls onto
/// another, and how deep the contact reads as it lands, differs from drop to drop, and one drop's
/// deepest contact after five seconds is one draw of it.
constexpr int kUnlikeDrops = 20;
constexpr Real kDropNudge = Real(1e-4);  // m along x, times the drop's number

/// Each drop's row in `drops`; returns each drop's deepest contact after five seconds, m.
std::vector<Real> measureDrops(BenchRun& bench, const World& pile, long frames, CsvTable& drops) {
    std::vector<Real> depths;
    std::size_t nudged = pile.bodies.size();  // the last dynamic body: the top of the pile as it falls
    while (nudged > 0 && pile.bodies[nudged - 1].type != BodyType::Dynamic) --nudged;
    if (nudged == 0) return depths;
    const int count = bench.quick() ? 3 : kUnlikeDrops;
    bench.progress().stage("the unlike pile, dropped again", count);
    SpeedOptions awake;
    awake.sleeping = false;
    for (int drop = 0; drop < count; ++drop) {
        World world = pile;
        const Real moved = kDropNudge * static_cast<Real>(drop);
        world.bodies[nudged - 1].transform.position.x() += moved;
        const Measurement m = runEngine(world, awake, frames, 0);
        depths.push_back(m.maxPenetration);
        drops.addRow({std::to_string(drop), formatNumber(moved), formatNumber(m.maxPenetration),
                      formatNumber(m.stepMs.median)});
        bench.progress().advance();
    }
    bench.progress().endStage();
    return depths;
}
// [ch12-unlike-drops]

/// One line under the drops' table: the median and the deepest of their deepest contacts after
/// five seconds, and how many read deeper than twice the slop.
std::string dropSummary(std::vector<Real> depths, const World& world) {
    if (depths.empty()) return "";
    std::sort(depths.begin(), depths.end());
    const Real bound = 2 * world.settings.slop;
    const auto deeper = std::count_if(depths.begin(), depths.end(), [&](Real depth) { return depth > bound; });
    return "deepest contact after 5 s over " + std::to_string(depths.size()) + " drops: median " +
           formatNumber(depths[depths.size() / 2]) + " m, deepest " + formatNumber(depths.back()) + " m, " +
           std::to_string(deeper) + " deeper than twice the slop (" + formatNumber(bound) + " m)\n";
}

/// Pyramids of growing size: the fast step, its scalar solve and the peer.
void measureScaling(BenchRun& bench, const std::vector<Configuration>& list, bool withPeer, CsvTable& scaling,
                    PlotSpec& plot) {
    const bool quick = bench.quick();
    // Scaling: pyramids of growing size.
    plot.integerX = true;
    plot.caption = std::string("Median ms per step (quartiles as whiskers) of pyramids of 10 to ") + (quick ? "30" : "100") +
                   " rows, 120 frames each, single thread, " + realTypeName() +
                   " build; chapter 10 with sleeping off, its scalar solve, and the peer when the program has one "
                   "(its frames alternating with chapter 10's).";
    const std::vector<int> rowsList = quick ? std::vector<int>{10, 20, 30} : std::vector<int>{10, 20, 40, 60, 80, 100};
    std::vector<Configuration> scalingList = {list[0], list[1]};
    if (withPeer) scalingList.push_back(list.back());
    bench.progress().stage("pyramids of growing size", static_cast<long>(rowsList.size() * scalingList.size()));
    // Measured row by row (chapter 10 and the peer side by side, runBeside), tabled configuration
    // by configuration.
    std::vector<std::vector<Measurement>> measured(scalingList.size());
    for (int rows : rowsList) {
        const World pyramid = buildPyramidRow(1, rows);
        const long frames = quick ? 30 : 120;
        for (std::size_t c = 0; c < scalingList.size(); ++c) {
            const Configuration& configuration = scalingList[c];
            if (configuration.peer) continue;
            if (c == 0 && withPeer) {
                auto [engine, peer] = runBeside(pyramid, configuration.options, frames, 0);
                measured[0].push_back(engine);
                measured.back().push_back(peer);
                bench.progress().advance();
            } else {
                measured[c].push_back(runEngine(pyramid, configuration.options, frames, 0));
            }
            bench.progress().advance();
        }
    }
    for (std::size_t c = 0; c < scalingList.size(); ++c) {
        PlotSeries series(scalingList[c].name);
        for (std::size_t r = 0; r < rowsList.size(); ++r) {
            const Measurement& m = measured[c][r];
            const int bodies = buildPyramidRow(1, rowsList[r]).dynamicBodyCount();
            scaling.addRow({std::to_string(rowsList[r]), std::to_string(bodies), scalingList[c].name,
                            formatNumber(m.stepMs.median), formatNumber(m.stepMs.lower), formatNumber(m.stepMs.upper)});
            series.x.push_back(bodies);
            series.y.push_back(m.stepMs.median);
            series.yLow.push_back(m.stepMs.lower);
            series.yHigh.push_back(m.stepMs.upper);
        }
        plot.series.push_back(series);
    }
    bench.progress().endStage();

}

void measureSpeed(BenchRun& bench) {
    const bool quick = bench.quick();
    const bool withPeer = static_cast<bool>(peerEngine().run);
    std::ostream& out = bench.out();
    if (!withPeer)
        out << "bench speed: no peer engine in this program (the `stepwise` program links the Bullet peer where "
               "libbullet-dev is found): Bullet skipped\n";

    // [ch12-bench-scenes]
    std::vector<BenchScene> scenes;
    scenes.push_back({"pyramid 100 rows", buildPyramidRow(1, quick ? 30 : 100), quick ? 60 : 600, 0});
    scenes.push_back({"ten 20-row pyramids", buildPyramidRow(quick ? 3 : 10, 20), quick ? 60 : 600, 0});
    // Boxes that touch their neighbours in a row: twice the contacts, and side contacts that carry no load.
    scenes.push_back({"touching 100 rows", buildPyramidRow(1, quick ? 25 : 100, kTouchingSpacing), quick ? 60 : 600, 0});
    scenes.push_back({"ten touching 20-row", buildPyramidRow(quick ? 2 : 10, 20, kTouchingSpacing), quick ? 60 : 600, 0});
    scenes.push_back({"mixed pile", buildMixedPile(quick ? 300 : 2000), quick ? 120 : 600, 0});
    // One density, sizes 0.15 to 0.6 m: masses up to about 150 to 1 apart, timed from its first frame.
    scenes.push_back({"unlike pile", buildMixedPile(quick ? 150 : 600, true, kUnlikePileSizes), quick ? 120 : 600, 0});
    // Joints, springs and kinematic bodies: chapter 8's scenes, and a field of ragdolls without
    // joint friction (the peer's cone-twist has none).
    scenes.push_back({"ragdoll pile", buildRagdollPile(10), quick ? 120 : 600, 0, true});
    World chain;
    ChainSpec swinging;
    swinging.direction = Vec3(1, 0, 0);
    addChain(chain, swinging);
    chain.name = "chain-20";
    scenes.push_back({"20-link chain", chain, quick ? 120 : 600, 0, true});
    scenes.push_back({"joints sandbox", buildJointsSandbox(), quick ? 120 : 600, 0, true});
    scenes.push_back({"100 ragdolls", buildRagdollField(quick ? 20 : 100, 0), quick ? 120 : 600, 0, true});
    for (BenchScene& scene : scenes) scene.world.settings.sleeping = false;
    // [ch12-bench-scenes]
    const std::string& only = bench.options().only;
    if (!only.empty()) {
        scenes.erase(std::remove_if(scenes.begin(), scenes.end(),
                                    [&](const BenchScene& scene) { return scene.name.find(only) == std::string::npos; }),
                     scenes.end());
        if (scenes.empty()) throw std::runtime_error("bench speed --only \"" + only + "\": no scene's name contains it");
    }

    CsvTable table({"scene", "bodies", "configuration", "frames", "ms_median", "ms_q1", "ms_q3", "broadphase_ms",
                    "narrowphase_ms", "solve_ms", "ns_per_body", "max_sideways_m", "lowest_m", "max_penetration_m",
                    "joint_error_m", "joint_error_rad", "x_faster_than_peer", "depth_beyond_true_m",
                    "overlap_unseen_m", "joint_gap_mean_m"});
    // Where the fast solve's time goes, phase by phase (chapter 10's configuration).
    CsvTable profile({"scene", "manifolds", "points", "prepare_ms", "integrate_ms", "warm_start_ms", "solve_ms",
                      "relax_ms", "store_ms", "joint_rows_kept"});
    const std::vector<Configuration> list = configurations(withPeer);
    measureScenes(bench, scenes, list, withPeer, table, profile);
    CsvTable drops({"drop", "moved_m", "max_penetration_m", "ms_median"});
    std::string dropLine;
    for (const BenchScene& scene : scenes)
        if (scene.name == "unlike pile")
            dropLine = dropSummary(measureDrops(bench, scene.world, scene.frames, drops), scene.world);
    if (!only.empty()) {  // the chosen scenes' tables; the files stay whole runs' only
        out << table.toText() << "\n" << profile.toText();
        if (!drops.rows().empty()) out << "\n" << drops.toText() << dropLine;
        return;
    }
    CsvTable sleepTable({"scene", "bodies", "sleeping", "settle_frames", "bodies_asleep", "ms_median", "fraction_of_awake"});
    measureSleep(bench, sleepTable);
    CsvTable scaling({"rows", "bodies", "configuration", "ms_median", "ms_q1", "ms_q3"});
    PlotSpec plot("ms per step against body count (pyramids)", "boxes", "ms per step");
    measureScaling(bench, list, withPeer, scaling, plot);

    out << table.toText() << "\n" << profile.toText() << "\n" << drops.toText() << dropLine
        << "\n" << sleepTable.toText() << "\n"
        << scaling.toText();
    bench.writeCsv(table);
    bench.writeCsv(profile, "-profile");
    bench.writeCsv(drops, "-drops");
    bench.writeCsv(scaling, "-scaling");
    bench.writePlot(plot);
    const std::vector<FigureTable> figures = {
        {{"Ms per step and per stage, single thread, " + std::string(realTypeName()) + " build."}, &table},
        {{"Where the fast solve spends its time: ms per step in each phase, and the share of joints that kept their rows."}, &profile},
        {{"A settled pile: the step with sleeping on, as a fraction of the same step awake."}, &sleepTable}};
    bench.writeTables(figures, "-tables");
}

}  // namespace

BenchEntry speedBench() {
    return benchEntry(10, measureSpeed, R"(
        speed: ms per step and per stage on a 100-row pyramid, ten 20-row pyramids and a
            2,000-body pile, each optimisation off in turn, Bullet beside it; a settled pile
            asleep and awake; ms against body count
        speed.csv          per scene and configuration: ms per step, per stage, drift, penetration
        speed-profile.csv  the fast solve phase by phase: ms per step in each; the share
                           of joint row builds a joint kept its last substep's rows
        speed-drops.csv    the unlike pile dropped again, one body moved 0.1 mm more each
                           time: deepest contact after 5 s and ms per step of each drop
        speed-scaling.csv  pyramids of growing size: ms per step against body count
        speed.svg          ms per step against body count, chapter 10, scalar, Bullet
        speed-tables.svg   the tables as a figure for the page)");
}

}  // namespace stepwise
