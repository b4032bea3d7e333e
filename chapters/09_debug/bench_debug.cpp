// `stepwise bench debug`: the cost of the tools, so a reader knows what leaving them on costs.
//
//   history   pyramids of 10 to 528 boxes: the step's CPU time, the time to record a frame into
//             the 120-frame ring, the memory a frame takes, and a rewind of 60 frames, 60
//             speculative steps and a resume.
//   snapshot the 2,100-box scene of ten 20-row pyramids (speed-pyramids, through the latest
//             chapter the program has; a 20-row pyramid through chapter 8 where the registry has
//             no such scene): a frame kept whole against a compact snapshot, bytes per body and
//             per contact point, the time to record a frame and to restore one.
//   ray casts random rays at a sphere, a box, a capsule and a hull: the closed forms' time per
//             cast, and the GJK cast's time and largest deviation from them as its iteration cap
//             grows (the hull's reference is its face planes). The deviation is measured across
//             the surface (along the ray times the cosine of the incidence): a grazing ray turns
//             any surface error into a long one along itself, whatever the method.
#include "09_debug/benches.h"

#include "06_manifolds/scenes.h"
#include "08_joints/chapter.h"
#include "09_debug/debug_session.h"
#include "09_debug/ray_cast.h"
#include "09_debug/ray_targets.h"
#include "app/bench_util.h"
#include "app/registry.h"
#include "math/random.h"
#include "world/heap_bytes.h"

#include <algorithm>
#include <cmath>
#include <ostream>

namespace stepwise {

namespace {

struct HistoryCost {
    int bodies = 0;
    double stepMs = 0, recordMs = 0, rewindResumeMs = 0;
    double bytesPerFrame = 0;
};

HistoryCost measureHistory(int rows) {
    World world = buildPyramid(rows);
    Pipeline pipeline = makeChapter08Pipeline(world);
    for (int frame = 0; frame < 30; ++frame) pipeline.step(world);   // settle and grow every vector
    HistoryCost cost;
    cost.bodies = static_cast<int>(world.bodies.size());
    History history;
    std::vector<double> steps, records;
    for (int frame = 0; frame < 2 * kHistoryFrames; ++frame) {
        ThreadStopwatch clock;
        pipeline.step(world);
        steps.push_back(clock.seconds() * 1e3);
        clock.restart();
        history.record(world);
        records.push_back(clock.seconds() * 1e3);
    }
    cost.stepMs = median(steps);
    cost.recordMs = median(records);   // the second lap: slots reused, as in a long session
    cost.bytesPerFrame = double(history.bytes()) / double(history.size());
    DebugSession session(world, std::move(pipeline));
    for (int frame = 0; frame < 60; ++frame) session.step();
    ThreadStopwatch clock;
    session.rewindBy(60);
    for (int frame = 0; frame < 60; ++frame) session.step();
    const double withSteps = clock.seconds() * 1e3;
    session.resume();
    cost.rewindResumeMs = withSteps;
    return cost;
}

struct SnapshotCost {
    std::string scene;
    int bodies = 0, contactPoints = 0;
    double wholeBytes = 0, wholePerBody = 0, wholePerPoint = 0;     // a whole copy of the world
    double compactBytes = 0, compactPerBody = 0, compactPerPoint = 0;  // a snapshot
    double historyWholeMb = 0, historyCompactMb = 0;                // 120 frames, the base included
    double copyMs = 0, saveMs = 0, assignMs = 0, restoreMs = 0;
};

/// A whole world's bytes split as the snapshot's are: the contact records (and the pair lists
/// beside them) per contact point, everything else per body.
void wholeWorldSplit(const World& world, double& perBody, double& perPoint) {
    const double contactBytes = double(capacityBytes(world.contacts) + capacityBytes(world.pairs) + capacityBytes(world.pairGaps));
    const double bodyBytes = double(worldBytes(world)) - contactBytes;
    int points = 0;
    for (const Contact& contact : world.contacts) points += contact.pointCount;
    perBody = bodyBytes / double(std::max<std::size_t>(1, world.bodies.size()));
    perPoint = contactBytes / double(std::max(1, points));
}

SnapshotCost measureSnapshot(bool quick) {
    const Registry& registry = chapterRegistry();
    const SceneEntry* big = registry.findScene("speed-pyramids");
    SnapshotCost cost;
    World world = big ? big->build() : buildPyramid(20);
    Pipeline pipeline = big ? registry.makePipeline(world) : makeChapter08Pipeline(world);
    cost.scene = big ? "speed-pyramids (chapter " + std::to_string(registry.lastChapter()) + ")" : "pyramid-20 (chapter 8)";
    // Settled enough for every pyramid to stand on its contacts, before anything sleeps.
    const int settle = quick ? 10 : 20;
    for (int frame = 0; frame < settle; ++frame) pipeline.step(world);
    cost.bodies = static_cast<int>(world.bodies.size());
    History history;
    World copy = world;   // a slot of a ring of whole worlds
    WorldSnapshot snapshot;
    std::vector<double> copies, saves, assigns, restores;
    const int frames = quick ? 6 : 30;
    for (int frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        ThreadStopwatch clock;
        copy = world;
        copies.push_back(clock.seconds() * 1e3);
        clock.restart();
        saveSnapshot(world, snapshot);
        saves.push_back(clock.seconds() * 1e3);
        history.record(world);
    }
    World restored;
    for (int k = 0; k < frames; ++k) {
        ThreadStopwatch clock;
        restored = copy;
        assigns.push_back(clock.seconds() * 1e3);
        clock.restart();
        history.restore(history.newestFrame(), restored);
        restores.push_back(clock.seconds() * 1e3);
    }
    cost.copyMs = median(copies);
    cost.saveMs = median(saves);
    cost.assignMs = median(assigns);
    cost.restoreMs = median(restores);
    const SnapshotSize size = snapshotSize(snapshot);
    cost.contactPoints = static_cast<int>(size.contactPoints);
    cost.wholeBytes = double(worldBytes(world));
    wholeWorldSplit(world, cost.wholePerBody, cost.wholePerPoint);
    cost.compactBytes = double(snapshotBytes(snapshot));
    cost.compactPerBody = size.perBody();
    cost.compactPerPoint = size.perContactPoint();
    cost.historyWholeMb = cost.wholeBytes * kHistoryFrames / 1e6;
    cost.historyCompactMb = (cost.compactBytes * kHistoryFrames + double(history.baseBytes())) / 1e6;
    return cost;
}

RayHit reference(const Ray& ray, const RayTarget& target) {
    if (target.shape.type == ShapeType::Convex) return rayHullPlanes(ray, target.pose, *target.shape.hull);
    return castRay(ray, target.shape, target.pose);
}

/// Pyramids of growing size: the step, a frame's record and its memory, a rewind and resume.
CsvTable measureHistoryCosts(BenchRun& bench, PlotSpec& plot) {
    const std::vector<int> rows = bench.quick() ? std::vector<int>{4, 8, 16} : std::vector<int>{4, 8, 16, 24, 32};
    CsvTable history({"bodies", "step (ms)", "record (ms)", "record / step", "bytes per frame", "120 frames (MB)",
                      "rewind 60 + 60 steps + resume (ms)"});
    PlotSeries stepSeries, recordSeries;
    stepSeries.title = "step (chapter 8 pipeline)";
    recordSeries.title = "record one frame";
    bench.progress().stage("history", long(rows.size()));
    for (int count : rows) {
        const HistoryCost cost = measureHistory(count);
        history.addRow({std::to_string(cost.bodies), formatNumber(cost.stepMs), formatNumber(cost.recordMs),
                        formatNumber(100 * cost.recordMs / cost.stepMs, 3) + "%", formatNumber(cost.bytesPerFrame),
                        formatNumber(cost.bytesPerFrame * kHistoryFrames / 1e6, 3), formatNumber(cost.rewindResumeMs)});
        stepSeries.x.push_back(cost.bodies);
        stepSeries.y.push_back(cost.stepMs);
        recordSeries.x.push_back(cost.bodies);
        recordSeries.y.push_back(cost.recordMs);
        bench.progress().advance();
    }
    plot.series = {stepSeries, recordSeries};
    plot.caption = "Pyramids of boxes through chapter 8's pipeline; recording saves a compact snapshot into the "
                   "120-frame ring (slots reused).";
    return history;
}

/// The big scene's frame kept whole against kept as a snapshot.
CsvTable measureSnapshots(BenchRun& bench) {
    bench.progress().stage("snapshot", 1);
    const SnapshotCost snap = measureSnapshot(bench.quick());
    bench.progress().advance();
    CsvTable snapshots({"scene", "kept as", "bodies", "contact points", "bytes per frame", "bytes per body",
                        "bytes per contact point", "120 frames (MB)", "record (ms)", "restore (ms)"});
    snapshots.addRow({snap.scene, "whole world", std::to_string(snap.bodies), std::to_string(snap.contactPoints),
                      formatNumber(snap.wholeBytes), formatNumber(snap.wholePerBody), formatNumber(snap.wholePerPoint),
                      formatNumber(snap.historyWholeMb, 3), formatNumber(snap.copyMs), formatNumber(snap.assignMs)});
    snapshots.addRow({snap.scene, "snapshot", std::to_string(snap.bodies), std::to_string(snap.contactPoints),
                      formatNumber(snap.compactBytes), formatNumber(snap.compactPerBody), formatNumber(snap.compactPerPoint),
                      formatNumber(snap.historyCompactMb, 3), formatNumber(snap.saveMs), formatNumber(snap.restoreMs)});
    return snapshots;
}

/// One shape's rays through GJK at each iteration cap: a table row and a plot point per cap.
void measureRayCaps(const RayTarget& target, const std::vector<Ray>& aimed, const std::vector<RayHit>& exact,
                    CsvTable& rays, PlotSeries& series) {
    static const std::vector<int> caps{1, 2, 3, 4, 6, 8, 16, 64};
    const ConvexProxy proxy{&target.shape, target.pose};
    for (int cap : caps) {
        std::vector<RayHit> cast(aimed.size());
        ThreadStopwatch clock;
        for (std::size_t i = 0; i < aimed.size(); ++i) cast[i] = rayConvex(aimed[i], proxy, cap);
        const double ns = clock.seconds() * 1e9 / double(aimed.size());
        double deviation = 0;
        long hits = 0, otherwise = 0;
        for (std::size_t i = 0; i < aimed.size(); ++i) {
            hits += cast[i].hit ? 1 : 0;
            // A hit one method calls a miss: a graze along an edge or a rim, or a cast
            // stopped by its cap before it reached the shape.
            if (cast[i].hit != exact[i].hit) ++otherwise;
            else if (cast[i].hit)   // across the surface: along a grazing ray the same error is longer
                deviation = std::max(deviation, double(std::abs(cast[i].distance - exact[i].distance)) *
                                                    std::abs(double(exact[i].normal.dot(aimed[i].direction))));
        }
        rays.addRow({target.name, "GJK", std::to_string(cap), formatNumber(ns), std::to_string(hits),
                     std::to_string(otherwise), formatNumber(deviation)});
        // The plot's error: the deviation, or 1 m while any ray is still called otherwise.
        series.x.push_back(ns);
        series.y.push_back(std::max(otherwise > 0 ? 1.0 : deviation, 1e-12));
    }
}

/// Random rays at each target: the closed form (or the hull's planes), then GJK's cast.
CsvTable measureRays(BenchRun& bench, int rayCount, PlotSpec& rayPlot) {
    CsvTable rays({"shape", "method", "iteration cap", "ns per cast", "hits", "called otherwise",
                   "largest deviation across the surface (m)"});
    bench.progress().stage("ray casts", long(rayTargets().size()));
    for (const RayTarget& target : rayTargets()) {
        Random random(9);
        std::vector<Ray> aimed;
        for (int i = 0; i < rayCount; ++i) aimed.push_back(aimedRay(target, random));
        std::vector<RayHit> exact(aimed.size());
        ThreadStopwatch clock;
        for (std::size_t i = 0; i < aimed.size(); ++i) exact[i] = reference(aimed[i], target);
        const double exactNs = clock.seconds() * 1e9 / double(aimed.size());
        const long exactHits = std::count_if(exact.begin(), exact.end(), [](const RayHit& hit) { return hit.hit; });
        rays.addRow({target.name, target.shape.type == ShapeType::Convex ? "face planes" : "closed form", "-",
                     formatNumber(exactNs), std::to_string(exactHits), "-", "0 (reference)"});
        PlotSeries series;
        series.title = target.name;
        measureRayCaps(target, aimed, exact, rays, series);
        rayPlot.series.push_back(series);
        bench.progress().advance();
    }
    bench.progress().endStage();
    return rays;
}

void measureDebug(BenchRun& bench) {
    PlotSpec historyPlot("History: recording a frame beside stepping it (" + std::string(realTypeName()) + ")",
                         "bodies", "ms per frame (CPU, median)");
    const CsvTable history = measureHistoryCosts(bench, historyPlot);
    const CsvTable snapshots = measureSnapshots(bench);
    const int rayCount = bench.quick() ? 2000 : 20000;
    PlotSpec rayPlot("GJK ray cast: deviation from the closed form against time per cast (" + std::string(realTypeName()) + ")",
                     "time per cast (ns, CPU)", "largest deviation across the surface (m)");
    rayPlot.caption = std::to_string(rayCount) + " rays per shape from 3 m; along each line the iteration cap grows " +
                      "1 to 64; drawn at 1 m while a ray is still called otherwise, a deviation of 0 at 1e-12 m.";
    const CsvTable rays = measureRays(bench, rayCount, rayPlot);

    std::ostream& out = bench.out();
    out << "history (" << realTypeName() << ", pyramids through chapter 8's pipeline, medians of " << 2 * kHistoryFrames
        << " frames):\n"
        << history.toText() << "\nsnapshot (" << realTypeName()
        << ", a frame kept whole against kept as a snapshot; bytes per body and per contact point split the frame's "
           "bytes between the bodies' state and the contact cache; 120 frames include the snapshot's base world; "
           "restore: a whole copy assigned, or base plus snapshot):\n"
        << snapshots.toText() << "\nray casts (" << rayCount << " rays per shape):\n" << rays.toText();
    bench.writeCsv(history);
    bench.writeCsv(rays, "-rays");
    bench.writeCsv(snapshots, "-snapshot");
    bench.writePlot(historyPlot);
    bench.writePlot(rayPlot, "-rays");
}

}  // namespace

BenchEntry debugBench() {
    return benchEntry(9, measureDebug, R"(
        debug: history cost per frame against scene size, rewind and resume, GJK ray cast error
            against its iteration cap
        debug.csv       history: step, record and memory per frame against body count
        debug-snapshot.csv  a frame of 2,100 boxes kept whole or as a snapshot: bytes per body and
                        per contact point, record and restore time
        debug-rays.csv  ray casts: time per cast and deviation from the closed form
        debug.svg       history: step and record time against body count
        debug-rays.svg  GJK ray cast deviation against time per cast, iteration cap growing)");
}

}  // namespace stepwise
