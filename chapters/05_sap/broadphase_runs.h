#pragma once
// The measurements behind `stepwise bench broadphase` (bench_broadphase.cpp): a stress scene
// stepped by chapter 5's pipeline with each broadphase timed on the same world, the sort alone on
// a settled scene, the sweep along each axis, and sweep and prune's phases one at a time.

#include "05_sap/stress_scene.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace stepwise::broadphase_bench {

enum class Method { Brute, SapFull, SapIncremental };
const char* methodName(Method method);
constexpr Method kMethods[] = {Method::Brute, Method::SapFull, Method::SapIncremental};

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

/// One stress scene stepped by chapter 5's pipeline (sweep and prune, incremental); each measured
/// frame the other broadphases are timed on the same world before it steps.
SceneResult measureScene(const SceneRun& run);

struct SettledResult {
    double insertionSortMs = 0, fullSortMs = 0;           // the sort alone
    double incrementalMs = 0, fullMs = 0;                 // the whole broadphase
    double moves = 0;                                     // insertion-sort moves per frame
};

/// Spheres resting on the ground: the sort from last step's order against a full sort, and the
/// whole broadphase with each.
SettledResult measureSettled(int count, int settleFrames, int measuredFrames);

/// Pairs the sweep looks at, and its time, along each axis: what the variance's choice saves.
struct AxisComparison {
    int chosen = -1;
    long looked[3] = {0, 0, 0};
    double sweepMs[3] = {0, 0, 0};
};
AxisComparison compareAxes(StressDensity density, int count);

/// Where sweep and prune's time goes, per body, ns: each phase of sweepAndPrune timed alone over
/// `repetitions` runs on a scene that has landed, and brute force's time per pair.
struct PhaseCosts {
    double bounds = 0, variance = 0, sort = 0, sweep = 0, pairSort = 0, brutePerPair = 0;
};
PhaseCosts measurePhases(int count, int repetitions);

/// The smallest count from which sweep and prune's broadphase is faster at every measured count.
int crossoverCount(const std::vector<std::pair<int, double>>& bruteOverSap);

/// A number for a table cell; empty where it is not finite.
std::string cell(double value);

}  // namespace stepwise::broadphase_bench
