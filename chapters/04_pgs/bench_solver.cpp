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
#include <stdexcept>

namespace stepwise {

namespace {

const char* solverLabel(SolverKind kind) { return kind == SolverKind::Jacobi ? "jacobi" : "gauss_seidel"; }

struct FixedSetResult {
    Spread solveMs;            // one solve: median and quartiles of the repeats
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
    result.solveMs = spreadOf(times);
    return result;
}

struct SimulationResult {
    Spread solveMs;            // per frame: median and quartiles over the settled half
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
    pipeline.timeStagesEvery(1);  // every frame's solve time is a sample
    SimulationResult result;
    std::vector<double> frameMs;
    int measured = 0;
    for (int frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        if (frame < frames / 2) continue;
        // The settled half only: while the balls land the number of contacts, and with it the
        // work of a solve, still changes from frame to frame.
        frameMs.push_back(solve->lastMs);
        // The run report's max_penetration: the deepest overlap at the end of the step.
        result.penetration += static_cast<double>(measureDeepestPenetration(world));
        result.residual += static_cast<double>(world.step.solver.residualRms);
        ++measured;
    }
    result.penetration /= std::max(1, measured);
    result.residual /= std::max(1, measured);
    result.solveMs = spreadOf(frameMs);  // the median: a shared machine's hiccups stay out
    return result;
}

void measureSolver(BenchRun& run) {
    const std::vector<int> iterationCounts = run.quick() ? std::vector<int>{1, 2, 4, 8, 16, 32, 50}
                                                         : std::vector<int>{1, 2, 3, 4, 6, 8, 10, 12, 16, 20, 25, 30, 40, 50};
    const int sphereCount = 40;
    const int freezeFrames = 20;
    const int simulationFrames = run.quick() ? 180 : 360;
    const int repeats = run.quick() ? 300 : 2000;

    CsvTable table({"part", "solver", "iterations", "solve_ms", "velocity_residual", "max_penetration", "solve_ms_q1",
                    "solve_ms_q3"});
    PlotSpec plot("Sequential impulses: error against solve time, iterations 1 to 50",
                  "solve time (ms; fixed set: one solve, running: per frame)", "residual (m/s) or deepest penetration (m)");
    plot.caption = "Each point is one iteration count, 1 at the left to 50 at the right. Fixed set: one frame's rows "
                   "of the pit of " + std::to_string(sphereCount) + " spheres, solved from zero impulses; the "
                   "velocity residual left against the time of one solve (median of " + std::to_string(repeats) +
                   " solves). Running: the pit run for " + std::to_string(simulationFrames) + " frames; the mean "
                   "deepest penetration over the settled half against the solve time per frame (median over the "
                   "same frames). Whiskers span the middle half of the timings.";

    run.progress().stage("freezing the pit's rows", 1);
    const FrozenRows frozen = freezeSpherePitRows(sphereCount, freezeFrames);
    run.out() << "fixed set: " << frozen.rows.size() << " rows from the pit of " << sphereCount << " spheres after "
              << freezeFrames << " frames; solve_ms: median (q1, q3: quartiles)\n";
    for (SolverKind kind : {SolverKind::GaussSeidel, SolverKind::Jacobi}) {
        const std::string name = kind == SolverKind::Jacobi ? "Jacobi" : "G-S";
        run.progress().stage(std::string(solverLabel(kind)) + ": fixed set and running pit", long(iterationCounts.size()));
        PlotSeries residualSeries(name + ": residual, fixed set");
        PlotSeries penetrationSeries(name + ": depth, running");
        for (int iterations : iterationCounts) {
            const FixedSetResult fixed = solveFrozen(frozen, kind, iterations, repeats);
            table.addRow({"fixed_set", solverLabel(kind), std::to_string(iterations), formatNumber(fixed.solveMs.median),
                          formatNumber(fixed.residual), "", formatNumber(fixed.solveMs.lower),
                          formatNumber(fixed.solveMs.upper)});
            residualSeries.x.push_back(fixed.solveMs.median);
            residualSeries.xLow.push_back(fixed.solveMs.lower);
            residualSeries.xHigh.push_back(fixed.solveMs.upper);
            residualSeries.y.push_back(fixed.residual);

            const SimulationResult simulation = simulatePit(sphereCount, simulationFrames, kind, iterations);
            table.addRow({"simulation", solverLabel(kind), std::to_string(iterations),
                          formatNumber(simulation.solveMs.median), formatNumber(simulation.residual),
                          formatNumber(simulation.penetration), formatNumber(simulation.solveMs.lower),
                          formatNumber(simulation.solveMs.upper)});
            penetrationSeries.x.push_back(simulation.solveMs.median);
            penetrationSeries.xLow.push_back(simulation.solveMs.lower);
            penetrationSeries.xHigh.push_back(simulation.solveMs.upper);
            penetrationSeries.y.push_back(simulation.penetration);
            run.progress().advance();
        }
        plot.series.push_back(residualSeries);
        plot.series.push_back(penetrationSeries);
    }
    run.progress().endStage();
    run.out() << table.toText();
    run.writeCsv(table);
    run.writePlot(plot);
}

}  // namespace

BenchEntry solverBench() {
    return benchEntry(4, measureSolver, R"(
        solver: chapter 4: velocity residual and penetration against solve time, iterations
            1-50, Gauss-Seidel vs Jacobi
        solver.csv  per solver and iteration count: solve time (median, quartiles), residual,
                    penetration
        solver.svg  plot: residual and penetration against solve time)");
}

}  // namespace stepwise
