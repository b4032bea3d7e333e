// `stepwise bench solver`: constraint error against run time as the iterations go from 1 to 50,
// Gauss-Seidel against Jacobi, on the sphere pit (a settled pile with many coupled contacts).
//
// Two measurements, both in the CSV and the plot:
//   fixed_set   one frame's rows, frozen, solved from zero impulses with k iterations: the
//               velocity residual left (m/s) against the time of the solve. This isolates the
//               iteration itself: same rows, same starting point, only k and the method change.
//   simulation  the scene run with k iterations per step: the deepest overlap at the end of each
//               step (m, the run report's max_penetration, mean over the settled half of the run)
//               against the solve stage's time per frame. This is what a user sees.
#include "04_pgs/benches.h"

#include "03_epa/chapter.h"
#include "04_pgs/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "04_pgs/frozen_rows.h"
#include "04_pgs/scenes.h"
#include "app/bench_util.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace stepwise {

namespace {

const char* solverLabel(SolverKind kind) { return kind == SolverKind::Jacobi ? "jacobi" : "gauss_seidel"; }

struct FixedSetResult {
    double solveMs = 0;
    double residual = 0;
};

FixedSetResult solveFrozen(const FrozenRows& frozen, SolverKind kind, int iterations, int repeats) {
    FixedSetResult result;
    std::vector<double> times;
    for (int repeat = 0; repeat < repeats; ++repeat) {
        std::vector<ConstraintRow> rows = frozen.rows;
        std::vector<SolverBody> bodies = frozen.bodies;
        Stopwatch watch;
        solveRows(rows, bodies, kind, iterations);
        times.push_back(watch.seconds() * 1e3);
        result.residual = measureResidual(rows, bodies).rms;
    }
    result.solveMs = median(times);
    return result;
}

struct SimulationResult {
    double solveMs = 0;        // per frame
    double penetration = 0;    // mean over the settled half of the deepest contact, m
    double residual = 0;       // mean over the settled half of the residual rms, m/s
};

SimulationResult simulatePit(int sphereCount, int frames, SolverKind kind, int iterations) {
    World world = buildSpherePitScene(sphereCount);
    world.settings.solver = kind;
    world.settings.solverIterations = iterations;
    Pipeline pipeline = makeChapter04Pipeline(world);
    const Stage* solve = pipeline.find(stage_group::kSolve);
    if (!solve) throw std::logic_error("chapter 4 pipeline has no solve stage");
    SimulationResult result;
    std::vector<double> frameMs;
    int measured = 0;
    for (int frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        frameMs.push_back(solve->lastMs);
        if (frame < frames / 2) continue;
        // The run report's max_penetration: the deepest overlap at the end of the step.
        result.penetration += static_cast<double>(measureDeepestPenetration(world));
        result.residual += static_cast<double>(world.step.solver.residualRms);
        ++measured;
    }
    result.penetration /= std::max(1, measured);
    result.residual /= std::max(1, measured);
    result.solveMs = median(frameMs);  // the median: a shared machine's hiccups stay out
    return result;
}

}  // namespace

bool benchOutputsWritable(const BenchOptions& options, const std::string& suite) {
    for (const std::string& path : {options.csvPath, options.plotPath}) {
        if (path.empty()) continue;
        if (!std::ofstream(path, std::ios::binary | std::ios::app)) {
            std::cerr << "error: bench " << suite << ": cannot write '" << path << "'\n";
            return false;
        }
    }
    return true;
}

int runSolverBench(const BenchOptions& options) {
    if (!benchOutputsWritable(options, "solver")) return 2;
    std::ostream& out = options.out ? *options.out : std::cout;
    const std::vector<int> iterationCounts = options.quick ? std::vector<int>{1, 2, 4, 8, 16, 32, 50}
                                                           : std::vector<int>{1, 2, 3, 4, 6, 8, 10, 12, 16, 20, 25, 30, 40, 50};
    const int sphereCount = 40;
    const int freezeFrames = 20;
    const int simulationFrames = options.quick ? 180 : 360;
    const int repeats = options.quick ? 300 : 2000;

    CsvTable table({"part", "solver", "iterations", "solve_ms", "velocity_residual", "max_penetration"});
    PlotSpec plot;
    plot.title = "Sequential impulses: error against solve time, iterations 1 to 50";
    plot.xLabel = "solve time (ms; fixed set: one solve, running: per frame)";
    plot.yLabel = "residual (m/s) or deepest penetration (m)";

    const FrozenRows frozen = freezeSpherePitRows(sphereCount, freezeFrames);
    out << "fixed set: " << frozen.rows.size() << " rows from the pit of " << sphereCount << " spheres after "
        << freezeFrames << " frames\n";
    for (SolverKind kind : {SolverKind::GaussSeidel, SolverKind::Jacobi}) {
        const std::string name = kind == SolverKind::Jacobi ? "Jacobi" : "G-S";
        PlotSeries residualSeries{name + ": residual, fixed set", {}, {}, false};
        PlotSeries penetrationSeries{name + ": depth, running", {}, {}, false};
        for (int iterations : iterationCounts) {
            const FixedSetResult fixed = solveFrozen(frozen, kind, iterations, repeats);
            table.addRow({"fixed_set", solverLabel(kind), std::to_string(iterations), formatNumber(fixed.solveMs),
                          formatNumber(fixed.residual), ""});
            residualSeries.x.push_back(fixed.solveMs);
            residualSeries.y.push_back(fixed.residual);

            const SimulationResult simulation = simulatePit(sphereCount, simulationFrames, kind, iterations);
            table.addRow({"simulation", solverLabel(kind), std::to_string(iterations), formatNumber(simulation.solveMs),
                          formatNumber(simulation.residual), formatNumber(simulation.penetration)});
            penetrationSeries.x.push_back(simulation.solveMs);
            penetrationSeries.y.push_back(simulation.penetration);
        }
        plot.series.push_back(residualSeries);
        plot.series.push_back(penetrationSeries);
    }
    out << table.toText();
    try {
        if (!options.csvPath.empty()) table.write(options.csvPath);
        if (!options.plotPath.empty()) writeSvgPlot(options.plotPath, plot);
    } catch (const std::runtime_error& error) {
        std::cerr << "error: bench solver: " << error.what() << "\n";
        return 2;
    }
    return 0;
}

}  // namespace stepwise
