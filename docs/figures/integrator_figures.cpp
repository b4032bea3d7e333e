// Figures for chapter 1, computed by the engine's own integrators on the chapter's oscillator
// (01_integrators/oscillator.h: one body on a zero-rest-length spring, no gravity).
#include "figures.h"

#include "01_integrators/integrate.h"
#include "01_integrators/oscillator.h"
#include "app/svg_plot.h"
#include "svg.h"
#include "world/world.h"

#include <cmath>
#include <cstdio>
#include <exception>

namespace figures {

using namespace stepwise;

namespace {

constexpr IntegratorKind kIntegratorMethods[3] = {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet,
                                        IntegratorKind::Rk4};
// A coarse step, about eight steps a period, so that each method's error is visible at once:
// at h w = 0.8 RK4 loses about (h w)^6 / 72 = 0.36% of the energy a step.
constexpr double kFigureHOmega = 0.8;
constexpr int kFigurePeriods = 30;

struct OscillatorRun {
    std::vector<double> time, position, scaledVelocity, energyRatio;
};

// The oscillator at 1 Hz, started 1 m from its anchor at rest, stepped by `method`.
OscillatorRun runFigureOscillator(IntegratorKind method) {
    Oscillator oscillator;
    World world;
    world.settings.gravity = Vec3::Zero();
    world.settings.integrator = method;
    const int body = addOscillator(world, oscillator);
    const Real dt = Real(kFigureHOmega / oscillator.omega);
    const int steps = static_cast<int>(std::ceil(kFigurePeriods * 2 * 3.14159265358979323846 / kFigureHOmega));
    const double initial = computeEnergy(world).total();
    OscillatorRun path;
    for (int step = 0; step <= steps; ++step) {
        if (step > 0) integrate(world, dt);
        const Motion& motion = *world.motionOf(body);
        path.time.push_back(step * double(dt));
        path.position.push_back(double(world.bodies[body].transform.position.x() - oscillator.anchor.x()));
        path.scaledVelocity.push_back(double(motion.linearVelocity.x()) / oscillator.omega);
        path.energyRatio.push_back(computeEnergy(world).total() / initial);
    }
    return path;
}

bool saveIntegratorPlot(const std::string& path, const PlotSpec& plot) {
    try {
        writeSvgPlot(path, plot);
    } catch (const std::exception&) {
        return false;
    }
    return true;
}

std::string integratorStepLabel() {
    char text[64];
    std::snprintf(text, sizeof text, "h w = %.1f, %d periods", kFigureHOmega, kFigurePeriods);
    return text;
}

}  // namespace

bool drawIntegratorPhase(const std::string& path) {
    // One panel per method, each with the exact orbit (the unit circle, dashed) and the
    // method's state (x, v / w) after every step.
    const char* colours[3] = {"#1f77b4", "#d62728", "#2ca02c"};   // as the energy plot colours them
    Svg svg(840, 330);
    for (int slot = 0; slot < 3; ++slot) {
        const Viewport view{slot * 280.0, 30, 280, 280, {0, 0}, 110};
        std::vector<Point2> circle;
        for (int i = 0; i <= 200; ++i) {
            const double angle = 2 * 3.14159265358979323846 * i / 200;
            circle.push_back({std::cos(angle), std::sin(angle)});
        }
        svg.line(view, {-1.2, 0}, {1.2, 0}, "stroke:#ccc");
        svg.line(view, {0, -1.2}, {0, 1.2}, "stroke:#ccc");
        svg.polyline(view, circle, "stroke:#555;stroke-width:1.5;stroke-dasharray:5,4");
        const OscillatorRun run = runFigureOscillator(kIntegratorMethods[slot]);
        std::vector<Point2> orbit;
        for (std::size_t i = 0; i < run.position.size(); ++i) orbit.push_back({run.position[i], run.scaledVelocity[i]});
        for (const Point2& point : orbit) svg.dot(view, point, 1.8, colours[slot]);
        svg.dot(view, orbit.front(), 4, "#000");
        svg.textAt({slot * 280.0 + 12, 22}, toString(kIntegratorMethods[slot]), std::string("fill:") + colours[slot]);
    }
    svg.textAt({12, 322}, "x (m) across, v / w (m) up, one dot a step; " + integratorStepLabel() + "; dashed: the exact orbit; black: the start",
               "fill:#333");
    return svg.save(path);
}

bool drawIntegratorEnergy(const std::string& path) {
    PlotSpec plot("Energy over time (" + integratorStepLabel() + ")", "time (s)", "energy / initial energy", false, false);
    for (IntegratorKind method : kIntegratorMethods) {
        const OscillatorRun run = runFigureOscillator(method);
        PlotSeries series(toString(method));
        series.x = run.time;
        series.y = run.energyRatio;
        series.lineOnly = true;
        plot.series.push_back(series);
    }
    plot.caption = "The same runs, energy against time. Semi-implicit Euler's energy oscillates in a band of "
                   "relative width about h w that does not move; Verlet's band is narrower (second order); RK4's "
                   "energy falls by about (h w)^6 / 72 a step and keeps falling.";
    return saveIntegratorPlot(path, plot);
}

}  // namespace figures
