// Figures for chapter 4, computed by the engine's own solver code.
#include "figures.h"

#include "04_pgs/chapter.h"
#include "app/svg_plot.h"
#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

namespace figures {

using namespace stepwise;

bool drawFrictionPyramid(const std::string& path) {
    // Coulomb's law bounds the tangential impulse by a disc of radius mu lambda_n (a section of
    // the friction cone). Two friction rows along tangents t1, t2, each clamped to
    // [-mu lambda_n, mu lambda_n], bound it by a square instead (the pyramid): in the square's
    // corners friction may reach sqrt(2) times Coulomb's bound. The tangents are the engine's
    // own choice for a contact normal (anyPerpendicular), here seen along the normal.
    const Vec3 normal = Vec3(Real(0.3), 1, Real(0.2)).normalized();
    const Vec3 t1 = anyPerpendicular(normal);
    const Vec3 t2 = normal.cross(t1);
    const double bound = 1;  // mu lambda_n
    Svg svg(520, 440);
    const Viewport view{0, 0, 520, 440, {0, 0}, 140};
    svg.polygon(view, {{bound, bound}, {-bound, bound}, {-bound, -bound}, {bound, -bound}},
                "fill:#f8e3cc;stroke:#e08a2e;stroke-width:2");
    svg.circle(view, {0, 0}, bound, "fill:#dbe6f5;stroke:#3b6fb6;stroke-width:2;fill-opacity:0.8");
    svg.arrow(view, {0, 0}, {1.35, 0}, "#333");
    svg.arrow(view, {0, 0}, {0, 1.35}, "#333");
    svg.text(view, {1.38, -0.05}, "t1");
    svg.text(view, {0.05, 1.38}, "t2");
    svg.arrow(view, {0, 0}, {bound, bound}, "#c0392b");
    svg.text(view, {0.45, 0.75}, "sqrt(2) mu lambda_n", "fill:#c0392b");
    // The first tangent follows the slide, so friction against it ends on a face of the
    // pyramid, at exactly Coulomb's bound.
    svg.arrow(view, {0, 0}, {-bound, 0}, "#2a8a3e", 3);
    svg.text(view, {-1.8, 0.1}, "against the slide: mu lambda_n", "fill:#2a8a3e");
    svg.text(view, {-0.85, -0.2}, "cone: |lambda_t| <= mu lambda_n", "fill:#3b6fb6");
    svg.text(view, {-1.05, -1.15}, "pyramid: |lambda_1|, |lambda_2| <= mu lambda_n", "fill:#b0661e");
    char label[200];
    std::snprintf(label, sizeof label, "t1 = (%.2f, %.2f, %.2f), t2 = (%.2f, %.2f, %.2f) for n = (%.2f, %.2f, %.2f)",
                  double(t1.x()), double(t1.y()), double(t1.z()), double(t2.x()), double(t2.y()), double(t2.z()),
                  double(normal.x()), double(normal.y()), double(normal.z()));
    svg.textAt({10, 430}, label, "fill:#555;font-size:12px");
    return svg.save(path);
}

namespace {

// A 1 kg ball at rest, started `depth` metres inside a static slab, stepped by chapter 4's
// engine with the given Baumgarte factor: the energy it has gained after each frame.
std::vector<Point2> energyGain(Real beta, Real depth, int frames) {
    World world;
    world.settings.baumgarte = beta;
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(5, Real(0.5), 5));
    BodyDef ball;
    ball.name = "ball";
    ball.shape = Shape::sphere(Real(0.25));
    ball.mass = 1;
    ball.transform.position = Vec3(0, Real(0.25) - depth, 0);
    addBody(world, ball);
    Pipeline pipeline = makeChapter04Pipeline(world);
    const Energy start = computeEnergy(world);
    std::vector<Point2> curve{{0, 0}};
    for (int frame = 1; frame <= frames; ++frame) {
        pipeline.step(world);
        const Energy now = computeEnergy(world);
        curve.push_back({world.time, (now.kinetic + now.gravity) - (start.kinetic + start.gravity)});
    }
    return curve;
}

}  // namespace

// A plot with axes, ticks, a legend and a caption: the bench plots' writer (app/svg_plot.h).
bool drawBaumgarteEnergy(const std::string& path) {
    const Real depth = Real(0.1);
    const int frames = 90;
    PlotSpec plot("Baumgarte's energy gain", "time (s)", "energy gained (J)", false, false);
    for (const Real beta : {Real(0.2), Real(0.5), Real(1)}) {
        PlotSeries series;
        series.lineOnly = true;
        double peak = 0;
        for (const Point2 point : energyGain(beta, depth, frames)) {
            series.x.push_back(point.x);
            series.y.push_back(point.y);
            peak = std::max(peak, point.y);
        }
        char title[80];
        std::snprintf(title, sizeof title, "beta = %.1f: peak +%.2f J", double(beta), peak);
        series.title = title;
        plot.series.push_back(series);
    }
    // Lifting the ball out of the ground, to the slop, takes m g (depth - slop); anything above
    // that line is energy the position correction made up.
    World reference;
    const double needed = double(-reference.settings.gravity.y()) * double(depth - reference.settings.slop);
    char lift[80];
    std::snprintf(lift, sizeof lift, "m g (depth - slop) = %.2f J", needed);
    PlotSeries liftLine(lift);
    liftLine.x = {0, frames * double(reference.settings.dt)};
    liftLine.y = {needed, needed};
    liftLine.lineOnly = true;
    liftLine.dashed = true;
    plot.series.push_back(liftLine);
    char caption[300];
    std::snprintf(caption, sizeof caption,
                  "Energy gained by a 1 kg ball started %.0f cm inside the ground, at rest, stepped by chapter 4's "
                  "engine at 60 Hz. Lifting it out to the slop takes m g (depth - slop) (dashed); anything above "
                  "that line is energy the position correction made up.",
                  double(depth) * 100);
    plot.caption = caption;
    try {
        writeSvgPlot(path, plot);
    } catch (const std::exception&) {
        return false;
    }
    return true;
}

}  // namespace figures
