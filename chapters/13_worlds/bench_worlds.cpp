// `stepwise bench worlds`: chapter 13 on the scene its shapes are for, a pile of a thousand bodies
// on a large terrain mesh, beside Bullet's btBvhTriangleMeshShape when the program has the peer
// (docs/peers.md). How fast each engine steps it, whether either lets a body through the ground,
// and how deep the settled bodies sink into it.
#include "13_worlds/bench_worlds.h"

#include "13_worlds/bench_terrain.h"
#include "13_worlds/chapter.h"
#include "13_worlds/scenes.h"
#include "app/bench_util.h"
#include "app/peer.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <ostream>
#include <stdexcept>

namespace stepwise {

namespace {

/// The scene and the run: the full form, or the quick one for CI.
struct PileSpec {
    int cells = 224;       // squares of 1 m a side: 2 x 224^2 = 100,352 triangles
    int bodies = 1000;
    long frames = 600;     // 10 s: the pile lands by 3 s; the last second is the settled one
    long timedFrom = 10;   // frame 0 builds the engine's tree over the mesh; both engines fall freely till then
};

PileSpec pileSpec(bool quick) { return quick ? PileSpec{100, 200, 300, 10} : PileSpec{}; }

/// The last second of the run: where penetration is measured, once the pile has settled.
constexpr long kSettledFrames = 60;

/// Points this far apart on each body's surface measure its depth into the ground: a 3 cm grid
/// finds the deepest point of a box across a ridge bent by a few degrees to a millimetre.
constexpr Real kSampleSpacing = Real(0.03);

/// How deep a settled body may lie in the ground: twice the slop the solve leaves uncorrected.
Real twiceSlop(const World& world) { return 2 * world.settings.slop; }

/// What measures both engines alike: the terrain's surface and each body's surface points.
struct Yardstick {
    GridTerrain terrain;
    std::vector<std::vector<Vec3>> samples;  // per body; empty for the ground
    explicit Yardstick(const World& start) : terrain(start.bodies.front()) {
        for (const Body& body : start.bodies) samples.push_back(surfaceSamples(body.shape, kSampleSpacing));
    }
};

/// What one engine's run showed.
struct Findings {
    bool ran = false;
    std::string name;
    std::vector<double> stepMs;              // per timed frame
    std::map<std::string, double> stageMs;   // mean per sampled frame, by stage group (the engine)
    TerrainJudgement judged;                 // from the poses: the deepest over the last second, the last frame's tunnelling
    double contactDepth = -1;                // m, the deepest contact with the ground in the last second as the engine
                                             // measures its contacts; < 0: not measured
    int fewestSubsteps = 0, mostSubsteps = 0;  // the engine's plan
};

/// The deepest contact point between the terrain (body 0) and any body, m.
double deepestOnTerrain(const World& world) {
    double deepest = 0;
    for (const Contact& contact : world.contacts) {
        if (contact.bodyA != 0 && contact.bodyB != 0) continue;
        for (int i = 0; i < contact.pointCount; ++i) deepest = std::max(deepest, double(contact.points[i].depth));
    }
    return deepest;
}

std::vector<Transform> posesOf(const World& world) {
    std::vector<Transform> poses;
    for (const Body& body : world.bodies) poses.push_back(body.transform);
    return poses;
}

/// Chapter 13 stepping a copy of the scene one frame at a time, so that the peer's frames can
/// alternate with its own (runBoth).
class EngineSide {
public:
    EngineSide(const World& start, const PileSpec& spec, const Yardstick& yardstick)
        : start_(start), world_(start), pipeline_(makeChapter13Pipeline(world_)), spec_(spec), yardstick_(yardstick) {
        findings_.ran = true;
        findings_.name = "chapter 13";
        findings_.contactDepth = 0;
    }

    void step(long frame) {
        pipeline_.step(world_);
        if (frame + kSettledFrames >= spec_.frames) {
            findings_.contactDepth = std::max(findings_.contactDepth, deepestOnTerrain(world_));
            judgeDepth(start_, yardstick_.terrain, yardstick_.samples, posesOf(world_), twiceSlop(start_), findings_.judged);
        }
        if (frame < spec_.timedFrom) return;
        findings_.stepMs.push_back(pipeline_.lastStepMs());
        if (!pipeline_.lastStepTimedStages()) return;  // stages are timed one frame in eight
        for (const Stage& stage : pipeline_.stages()) findings_.stageMs[stageGroup(stage.name)] += stage.lastMs;
        ++stageFrames_;
    }

    Findings finish() {
        for (auto& [group, ms] : findings_.stageMs) ms /= static_cast<double>(std::max(1L, stageFrames_));
        judgeTunnelling(start_, yardstick_.terrain, posesOf(world_), findings_.judged);
        findings_.fewestSubsteps = world_.step.iterationPlan.fewestIterations;
        findings_.mostSubsteps = world_.step.iterationPlan.mostIterations;
        return findings_;
    }

private:
    const World& start_;
    World world_;
    Pipeline pipeline_;
    PileSpec spec_;
    const Yardstick& yardstick_;
    Findings findings_;
    long stageFrames_ = 0;
};

/// The engine and the peer take turns of this many frames, as in `stepwise bench speed`
/// (bench_speed.cpp, runBeside): each engine's frames are timed alone, and a slow minute of a
/// shared host slows both.
constexpr long kFramesATurn = 30;

/// The peer's side: its timings and contact depths from its run, its poses judged as the
/// engine's are (the last second's as they come, between its frames).
Findings peerFindings(const World& start, const PileSpec& spec, const Yardstick& yardstick, const PeerRun& run,
                      TerrainJudgement judged) {
    Findings findings;
    findings.ran = true;
    findings.name = peerEngine().name;
    const long timedFrom = std::min<long>(spec.timedFrom, static_cast<long>(run.stepMs.size()));
    findings.stepMs.assign(run.stepMs.begin() + timedFrom, run.stepMs.end());
    if (!run.staticPenetration.empty()) {
        findings.contactDepth = 0;
        const std::size_t last = run.staticPenetration.size();
        for (std::size_t i = last - std::min<std::size_t>(kSettledFrames, last); i < last; ++i)
            findings.contactDepth = std::max(findings.contactDepth, run.staticPenetration[i]);
    }
    findings.judged = std::move(judged);
    judgeTunnelling(start, yardstick.terrain, run.finalPoses, findings.judged);
    return findings;
}

/// Both engines on the scene, taking turns (the engine alone when the program has no peer, or
/// the peer refuses the scene, which `out` is told).
std::pair<Findings, Findings> runBoth(const World& start, const PileSpec& spec, std::ostream& out) {
    const Yardstick yardstick(start);
    EngineSide engine(start, spec, yardstick);
    long engineFrames = 0;
    const auto engineRest = [&] {
        while (engineFrames < spec.frames) engine.step(engineFrames++);
        return std::make_pair(engine.finish(), Findings{});
    };
    if (!peerEngine().run) {
        out << "bench worlds: no peer engine in this program (the `stepwise` program links the Bullet peer where "
               "libbullet-dev is found): Bullet skipped\n";
        return engineRest();
    }
    try {
        TerrainJudgement peerJudged;
        const PeerRun peer = peerEngine().run(start, spec.frames, [&](long peerFrame, const std::vector<Transform>& poses) {
            if (peerFrame + kSettledFrames >= spec.frames)
                judgeDepth(start, yardstick.terrain, yardstick.samples, poses, twiceSlop(start), peerJudged);
            if ((peerFrame + 1) % kFramesATurn != 0 && peerFrame + 1 != spec.frames) return;
            while (engineFrames <= peerFrame) engine.step(engineFrames++);
        });
        return {engine.finish(), peerFindings(start, spec, yardstick, peer, peerJudged)};
    } catch (const std::runtime_error& refused) {
        out << "bench worlds: the peer refuses the scene: " << refused.what() << "\n";
        return engineRest();
    }
}

/// The processor's "model name" from /proc/cpuinfo, for the results file (the pages name no
/// machine); "" where there is none.
std::string processorName() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) return line.substr(line.find(':') + 2);
    return "";
}

/// The host's load average over the last minute from /proc/loadavg ("" where there is none): on a
/// shared machine, what else was running when the bench was.
std::string loadAverage() {
    std::ifstream loadavg("/proc/loadavg");
    std::string minute;
    loadavg >> minute;
    return minute;
}

std::string stageCell(const Findings& findings, const char* group) {
    const auto found = findings.stageMs.find(group);
    return found == findings.stageMs.end() ? "" : formatNumber(found->second);
}

void addRow(CsvTable& table, const World& start, const PileSpec& spec, const Findings& findings, double peerMedian) {
    const double ms = median(findings.stepMs);
    table.addRow({start.name, findings.name, std::to_string(start.dynamicBodyCount()),
                  std::to_string(start.bodies.front().shape.mesh->triangles.size()), std::to_string(spec.frames),
                  formatNumber(ms), formatNumber(percentile(findings.stepMs, 0.95)), stageCell(findings, stage_group::kBroadphase),
                  stageCell(findings, stage_group::kNarrowphase), stageCell(findings, stage_group::kSolve),
                  peerMedian > 0 ? formatNumber(peerMedian / ms, 3) : "", std::to_string(findings.judged.tunnelled),
                  std::to_string(findings.judged.leftTerrain), formatNumber(double(findings.judged.deepest)),
                  std::to_string(findings.judged.mostOverBound),
                  findings.contactDepth >= 0 ? formatNumber(findings.contactDepth) : "",
                  formatNumber(double(twiceSlop(start)))});
}

/// What the bench is for, line by line: no body through the ground, the settled pile within twice
/// the slop of it, a frame at least twice as fast as the peer's; each with its measurement and
/// whether the engine meets it.
void printTargets(std::ostream& out, const World& start, const Findings& engine, const Findings& peer) {
    const double bound = double(twiceSlop(start));
    const auto verdict = [](bool met) { return met ? "met" : "MISSED"; };
    const auto both = [&](const std::string& engineValue, const std::string& peerValue) {
        out << "chapter 13 " << engineValue;
        if (peer.ran) out << "; " << peer.name << " " << peerValue;
    };
    out << "\ntargets:\n  no body through the ground: ";
    both(std::to_string(engine.judged.tunnelled), std::to_string(peer.judged.tunnelled));
    out << " (" << verdict(engine.judged.tunnelled == 0) << ")\n";
    for (const std::string& name : engine.judged.tunnelledNames) out << "    chapter 13 lost " << name << "\n";
    for (const std::string& name : peer.judged.tunnelledNames) out << "    " << peer.name << " lost " << name << "\n";
    out << "  deepest body into the ground in the last second under 2 x slop = " << formatNumber(bound) << " m: ";
    const auto deepest = [](const TerrainJudgement& judged) {
        return formatNumber(double(judged.deepest)) + " m" + (judged.deepestBody.empty() ? "" : ", " + judged.deepestBody);
    };
    both(deepest(engine.judged), deepest(peer.judged));
    out << " (" << verdict(double(engine.judged.deepest) < bound) << ")\n    bodies deeper than the bound in one frame, at most: ";
    both(std::to_string(engine.judged.mostOverBound), std::to_string(peer.judged.mostOverBound));
    out << "\n    the deepest by shape:";
    for (int type = 0; type < kShapeTypeCount; ++type) {
        const Real engineDepth = engine.judged.deepestByShape[std::size_t(type)];
        const Real peerDepth = peer.judged.deepestByShape[std::size_t(type)];
        if (engineDepth > 0 || peerDepth > 0) {
            out << " " << toString(static_cast<ShapeType>(type)) << " ";
            out << formatNumber(double(engineDepth)) << (peer.ran ? " / " + formatNumber(double(peerDepth)) : std::string());
        }
    }
    out << " m\n";
    out << "    the engines' own deepest contact with it: ";
    both(formatNumber(engine.contactDepth) + " m", formatNumber(peer.contactDepth) + " m");
    out << "\n";
    if (peer.ran) {
        const double ratio = median(peer.stepMs) / median(engine.stepMs);
        out << "  at least 2x faster per frame than " << peer.name << ": " << formatNumber(ratio, 3) << "x ("
            << verdict(ratio >= 2) << ")\n";
    }
}

PlotSeries frameSeries(const Findings& findings, const PileSpec& spec) {
    PlotSeries series(findings.name);
    series.lineOnly = true;
    for (std::size_t i = 0; i < findings.stepMs.size(); ++i) {
        series.x.push_back(double(spec.timedFrom) + double(i));
        series.y.push_back(findings.stepMs[i]);
    }
    return series;
}

void measureWorlds(BenchRun& bench) {
    const PileSpec spec = pileSpec(bench.quick());
    World start = buildMeshTerrainPile(spec.cells, spec.bodies);
    start.settings.sleeping = false;  // timed awake, as the peer runs (docs/peers.md)
    std::ostream& out = bench.out();
    const std::string processor = processorName(), load = loadAverage();
    out << "bench worlds: " << start.dynamicBodyCount() << " bodies on a terrain mesh of "
        << start.bodies.front().shape.mesh->triangles.size() << " triangles, " << spec.frames << " frames, timed from frame "
        << spec.timedFrom << "; single thread, " << realTypeName() << " build"
        << (processor.empty() ? "" : "; " + processor) << (load.empty() ? "" : ", load average " + load) << "\n";
    bench.progress().stage("the pile, both engines in turns", 1);
    const auto [engine, peer] = runBoth(start, spec, out);
    bench.progress().endStage();

    CsvTable table({"scene", "engine", "bodies", "triangles", "frames", "ms_median", "ms_p95", "broadphase_ms",
                    "narrowphase_ms", "solve_ms", "x_faster_than_peer", "tunnelled", "left_terrain", "max_penetration_m",
                    "bodies_over_bound", "contact_depth_m", "twice_slop_m"});
    const double peerMedian = peer.ran ? median(peer.stepMs) : 0;
    addRow(table, start, spec, engine, peerMedian);
    if (peer.ran) addRow(table, start, spec, peer, 0);
    out << table.toText();
    out << "chapter 13's planner: " << engine.fewestSubsteps << " to " << engine.mostSubsteps << " substeps a frame";
    if (peer.ran)
        out << "; " << peer.name << ": " << start.settings.substeps << " substep(s), " << start.settings.solverIterations
            << " iterations";
    out << "\n";
    printTargets(out, start, engine, peer);
    bench.writeCsv(table);

    PlotSpec plot("ms per frame, a pile on a terrain mesh", "frame", "ms per frame", false, false);
    plot.integerX = true;
    plot.caption = std::to_string(start.dynamicBodyCount()) + " bodies dropped on " +
                   std::to_string(start.bodies.front().shape.mesh->triangles.size()) +
                   " triangles, ms per frame from frame " + std::to_string(spec.timedFrom) + ", single thread, " +
                   realTypeName() + " build: chapter 13's step, and Bullet's (btBvhTriangleMeshShape) when the program "
                   "has the peer, the two taking turns of 30 frames.";
    plot.series.push_back(frameSeries(engine, spec));
    if (peer.ran) plot.series.push_back(frameSeries(peer, spec));
    bench.writePlot(plot);
}

}  // namespace

BenchEntry worldsBench() {
    return benchEntry(13, measureWorlds, R"(
        worlds: a pile of 1,000 boxes, balls, capsules, cans and tables dropped on a terrain mesh
            of 100,352 triangles, chapter 13 and Bullet beside it: ms per frame, bodies through
            the ground, the deepest body into it once settled against 2 x slop
        worlds.csv   per engine: ms per frame (median, 95th percentile), the engine's stages (mean
            ms per frame), speed ratio, bodies tunnelled or off the terrain, the deepest body into
            the ground in the last second, how many were deeper than 2 x slop at once, the
            deepest contact
        worlds.svg   ms per frame against frame, both engines)");
}

}  // namespace stepwise
