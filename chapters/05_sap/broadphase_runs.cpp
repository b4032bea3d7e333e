// The measurements of `stepwise bench broadphase` (broadphase_runs.h). Times are the thread's CPU
// time (ThreadStopwatch): the machines this runs on are shared, and wall-clock time would count the
// other programs' turns.
#include "05_sap/broadphase_runs.h"

#include "05_sap/chapter.h"
#include "app/bench_util.h"

#include <algorithm>
#include <cmath>

namespace stepwise::broadphase_bench {

namespace {

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

}  // namespace

const char* methodName(Method method) {
    return method == Method::Brute ? "brute" : method == Method::SapFull ? "sap_full" : "sap_incremental";
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

int crossoverCount(const std::vector<std::pair<int, double>>& bruteOverSap) {
    int crossover = -1;
    for (auto it = bruteOverSap.rbegin(); it != bruteOverSap.rend(); ++it) {
        if (it->second <= 1) break;
        crossover = it->first;
    }
    return crossover;
}

}  // namespace stepwise::broadphase_bench
