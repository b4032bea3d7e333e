// The work-precision bench of chapter 1 (Hairer & Wanner's "work-precision diagram"): for each
// integrator and step size, how far from the exact answer it ends and how long it took.
// The system is eight bodies, each on a zero-rest-length spring to its own world anchor and
// without gravity: an isotropic harmonic oscillator with the closed form
//   x(t) = anchor + d0 cos(w t) + (v0 / w) sin(w t),   w = sqrt(k / m).
#include "01_integrators/bench_integrators.h"

#include "01_integrators/integrate.h"
#include "01_integrators/oscillator.h"
#include "app/bench_util.h"
#include "math/random.h"

#include <cmath>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace stepwise {

namespace {

constexpr double kOmega = 2 * 3.14159265358979323846;  // rad/s: one oscillation per second
constexpr double kDuration = 2.3;                      // s; not a whole number of periods, so
                                                       // no error term happens to vanish there
constexpr int kBodies = 8;

// Eight oscillators at random displacements and velocities, one per body, 3 m apart.
std::vector<Oscillator> makeOscillators() {
    Random random(20240601u);
    auto uniform = [&] { return Real(random.uniform(-1, 1)); };
    std::vector<Oscillator> oscillators(kBodies);
    for (int i = 0; i < kBodies; ++i) {
        oscillators[i].omega = kOmega;
        oscillators[i].anchor = Vec3(Real(3 * i), 0, 0);
        // One draw per statement (z, y, x): a call's arguments are evaluated in an unspecified
        // order, so draws inside one expression would give GCC and Clang different oscillators.
        const Real offsetZ = uniform(), offsetY = uniform(), offsetX = uniform();
        const Real speedZ = uniform(), speedY = uniform(), speedX = uniform();
        oscillators[i].offset = Vec3(offsetX, offsetY, offsetZ);
        oscillators[i].velocity = Real(kOmega) * Vec3(speedX, speedY, speedZ);
    }
    return oscillators;
}

World makeOscillatorWorld(const std::vector<Oscillator>& oscillators, IntegratorKind method) {
    World world;
    world.settings.gravity = Vec3::Zero();
    world.settings.integrator = method;
    for (const Oscillator& oscillator : oscillators) addOscillator(world, oscillator);
    return world;
}

double maxErrorAgainstExact(const World& world, const std::vector<Oscillator>& oscillators, double t) {
    double worst = 0;
    for (size_t i = 0; i < oscillators.size(); ++i)
        worst = std::max(worst, (world.bodies[i].transform.position.cast<double>() - oscillators[i].exactPosition(t)).norm());
    return worst;
}

struct Measurement {
    IntegratorKind method;
    int steps;
    double dt;
    double error;
    Spread seconds;   // wall time of one run to kDuration: median and quartiles of the runs
};

// Runs one configuration often enough that the timer sees real numbers: at least seven runs
// and at least `minimumSeconds` of stepping in total.
Measurement measure(const std::vector<Oscillator>& oscillators, IntegratorKind method, int steps, double minimumSeconds) {
    const World initial = makeOscillatorWorld(oscillators, method);
    const Real dt = Real(kDuration / steps);
    Measurement result{method, steps, kDuration / steps, 0, {}};
    std::vector<double> runSeconds;
    double total = 0;
    while (runSeconds.size() < 7 || total < minimumSeconds) {
        World world = initial;
        Stopwatch stopwatch;
        for (int step = 0; step < steps; ++step) integrate(world, dt);
        const double seconds = stopwatch.seconds();
        runSeconds.push_back(seconds);
        total += seconds;
        if (runSeconds.size() == 1) result.error = maxErrorAgainstExact(world, oscillators, kDuration);
    }
    result.seconds = spreadOf(runSeconds);
    return result;
}

// Least-squares slope of log(error) against log(dt) over the points above the round-off
// floor and below the pre-asymptotic range: the observed order of the method.
double observedOrder(const std::vector<Measurement>& rows, IntegratorKind method) {
    const double floor = 1000 * std::numeric_limits<Real>::epsilon();
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const Measurement& row : rows) {
        if (row.method != method || row.error <= floor || row.error >= 1e-1) continue;
        const double x = math::log(row.dt), y = math::log(row.error);
        n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    if (n < 2) return std::nan("");
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

void measureIntegrators(BenchRun& run) {
    const std::vector<Oscillator> oscillators = makeOscillators();
    const IntegratorKind methods[] = {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Rk4};
    const std::vector<int> stepCounts = run.quick() ? std::vector<int>{16, 32, 64, 128, 256, 512, 1024}
                                                    : std::vector<int>{16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192};
    const double minimumSeconds = run.quick() ? 0.01 : 0.2;

    run.progress().stage("3 integrators x " + std::to_string(stepCounts.size()) + " step sizes",
                         long(std::size(methods) * stepCounts.size()));
    // [ch01-bench]
    std::vector<Measurement> rows;
    for (IntegratorKind method : methods)
        for (int steps : stepCounts) {
            rows.push_back(measure(oscillators, method, steps, minimumSeconds));
            run.progress().advance();
        }
    // [ch01-bench]
    run.progress().endStage();

    const std::string precision = realTypeName();
    CsvTable table({"method", "steps", "dt_s", "h_omega", "error_m", "run_ms", "ns_per_body_step", "run_ms_q1",
                    "run_ms_q3"});
    PlotSpec workPrecision{"Work-precision: " + std::to_string(kBodies) + " oscillators to t = 2.3 s (Real = " + precision + ")",
                           "run time (s)", "max position error (m)"};
    workPrecision.caption = "Each point is one integrator at one step size: the largest distance from the exact "
                            "solution at t = 2.3 s against the time the run took (median of at least 7 runs; "
                            "whiskers span the middle half of the runs). Lower left is better: for any error you "
                            "can afford, the leftmost method reaches it soonest.";
    PlotSpec errorByStep{"Error against step size (Real = " + precision + ")", "dt (s)", "max position error (m)"};
    errorByStep.caption = "The same errors against the step size dt. On log axes a method of order p is a line of "
                          "slope p (1 for semi-implicit Euler, 2 for Verlet, 4 for RK4) until the error reaches "
                          "the round-off of Real.";
    for (IntegratorKind method : methods) {
        PlotSeries byTime(toString(method));
        PlotSeries byStep(toString(method));
        for (const Measurement& row : rows) {
            if (row.method != method) continue;
            table.addRow({toString(method), std::to_string(row.steps), formatNumber(row.dt), formatNumber(row.dt * kOmega),
                          formatNumber(row.error), formatNumber(row.seconds.median * 1e3),
                          formatNumber(row.seconds.median * 1e9 / (double(row.steps) * kBodies)),
                          formatNumber(row.seconds.lower * 1e3), formatNumber(row.seconds.upper * 1e3)});
            byTime.x.push_back(row.seconds.median);
            byTime.xLow.push_back(row.seconds.lower);
            byTime.xHigh.push_back(row.seconds.upper);
            byTime.y.push_back(row.error);
            byStep.x.push_back(row.dt);
            byStep.y.push_back(row.error);
        }
        workPrecision.series.push_back(byTime);
        errorByStep.series.push_back(byStep);
    }

    run.out() << table.toText() << "\nobserved order (slope of log error against log dt):\n";
    for (IntegratorKind method : methods)
        run.out() << "  " << toString(method) << "  " << formatNumber(observedOrder(rows, method), 3) << "\n";
    run.writeCsv(table);
    run.writePlot(workPrecision);
    run.writePlot(errorByStep, "-dt");
}

}  // namespace

BenchEntry integratorsBench() {
    return benchEntry(1, measureIntegrators, R"(
        integrators: integrator error against run time on a spring oscillator (work-precision)
        integrators.csv     per integrator and step count: dt, error, run time (median, quartiles)
        integrators.svg     work-precision diagram: error against run time
        integrators-dt.svg  error against step size (the slopes are the orders))");
}

}  // namespace stepwise
