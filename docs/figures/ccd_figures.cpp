// Figures for chapter 7, computed by the engine's own conservative advancement and TOI loop.
#include "figures.h"

#include "02_gjk/gjk.h"
#include "07_ccd/time_of_impact.h"
#include "07_ccd/toi_loop.h"

#include <cstdio>

namespace figures {

using namespace stepwise;

namespace {

Point2 ccdSide(const Vec3& p) { return {double(p.x()), double(p.y())}; }

// A box's outline in the x-y plane (the box turns about z only).
std::vector<Point2> ccdOutline(const Shape& box, const Transform& pose) {
    const Vec3& h = box.halfExtents;
    std::vector<Point2> corners;
    for (const Vec3& local : {Vec3(-h.x(), -h.y(), 0), Vec3(h.x(), -h.y(), 0), Vec3(h.x(), h.y(), 0), Vec3(-h.x(), h.y(), 0)})
        corners.push_back(ccdSide(pose.apply(local)));
    return corners;
}

std::string ccdText(const char* pattern, double a, double b = 0, double c = 0) {
    char text[160];
    std::snprintf(text, sizeof text, pattern, a, b, c);
    return text;
}

}  // namespace

bool drawCcdAdvancement(const std::string& path) {
    // A plank flying at a wall and turning as it goes. Conservative advancement from t = 0: each
    // iteration measures the distance with GJK and advances by (distance - target) / bound.
    // timeOfImpact with its iteration cap at k reports where the k-th query stood.
    const Shape plank = Shape::box(Vec3(Real(0.35), Real(0.06), Real(0.06)));
    const Shape wall = Shape::box(Vec3(Real(0.05), Real(1.2), Real(1)));
    const Transform start{Vec3(Real(-2.3), Real(0.35), 0), Quat(Eigen::AngleAxis<Real>(Real(0.3), Vec3::UnitZ()))};
    const Transform end{Vec3(Real(0.7), Real(0.05), 0), Quat(Eigen::AngleAxis<Real>(Real(2.6), Vec3::UnitZ()))};
    const Sweep sweep = sweepBetween(start, end, Vec3::Zero());
    const Sweep still = stillSweep(Transform{}, Vec3::Zero());
    const ToiOptions options = toiOptionsFor(Settings{});

    struct Iterate {
        ToiResult at;
        Real bound = 0;
    };
    std::vector<Iterate> steps;
    for (int k = 1; k <= kToiMaxIterations; ++k) {
        ToiOptions capped = options;
        capped.maxIterations = k;
        const ToiResult at = timeOfImpact(plank, sweep, wall, still, capped);
        steps.push_back({at, closingSpeedBound(sweep, plank, still, wall, at.normal)});
        if (at.state != ToiState::Stalled) break;
    }

    Svg svg(1000, 470);
    const Viewport scene{0, 40, 520, 420, {-1.05, 0.15}, 150};
    // The plot is drawn in pixels: a viewport that maps (x, height - y) to the pixel (x, y).
    const Viewport pixels{0, 0, 1000, 470, {500, 235}, 1};
    const auto pixel = [](Point2 p) { return Point2{p.x, 470 - p.y}; };
    // Left: the wall, the plank's start and end, and its pose at each query with the distance.
    svg.polygon(scene, ccdOutline(wall, Transform{}), "fill:#888;fill-opacity:0.35;stroke:#555;stroke-width:2");
    svg.polygon(scene, ccdOutline(plank, poseAt(sweep, 1)), "fill:none;stroke:#d62728;stroke-width:1.5;stroke-dasharray:5 4");
    svg.text(scene, {0.15, -0.45}, "end of the step: through", "fill:#d62728");
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const ToiResult& at = steps[k].at;
        const bool last = k + 1 == steps.size();
        svg.polygon(scene, ccdOutline(plank, poseAt(sweep, at.time)),
                    last ? "fill:#2ca02c;fill-opacity:0.35;stroke:#2ca02c;stroke-width:2"
                         : "fill:#1f77b4;fill-opacity:0.12;stroke:#1f77b4;stroke-width:1.5");
        if (!last) svg.line(scene, ccdSide(at.pointA), ccdSide(at.pointB), "stroke:#000;stroke-width:1.5");
        const Point2 label = ccdSide(poseAt(sweep, at.time).position);
        if (!last) svg.text(scene, {label.x - 0.3, label.y + 0.12}, ccdText("t%.0f", double(k)), "font-size:12px");
    }
    svg.textAt({10, 24}, ccdText("a plank at a wall: %.0f distance queries, time of impact t = %.3f", double(steps.size()),
                                double(steps.back().at.time)), "fill:#333");

    // Right: the distance against t (sampled with GJK), the queries, and from each the bound's
    // line d_k - mu_k (t - t_k): the distance never falls below it, so the next query is safe.
    const double x0 = 570, y0 = 400, w = 400, h = 320;
    const double maxDistance = double(steps.front().at.distance) * 1.1;
    const auto map = [&](double t, double d) { return pixel({x0 + t * w, y0 - d / maxDistance * h}); };
    svg.line(pixels, pixel({x0, y0}), pixel({x0 + w, y0}), "stroke:#000;stroke-width:1");
    svg.line(pixels, pixel({x0, y0}), pixel({x0, y0 - h}), "stroke:#000;stroke-width:1");
    svg.textAt({x0 + w - 150, y0 + 34}, "t (fraction of the step)");
    svg.textAt({x0 - 10, y0 - h - 40}, ccdText("distance, m (axis to %.2f)", maxDistance));
    for (int tick = 0; tick <= 4; ++tick) svg.textAt({x0 + tick * w / 4 - 8, y0 + 16}, ccdText("%.2f", tick / 4.0), "font-size:11px");
    std::vector<Point2> curve;
    for (int i = 0; i <= 200; ++i) {
        const double t = i / 200.0;
        const GjkDistanceResult gap = gjkDistance(ConvexProxy{&plank, poseAt(sweep, Real(t))}, ConvexProxy{&wall, Transform{}});
        if (!gap.separated) break;
        curve.push_back(map(t, double(gap.distance)));
    }
    svg.polyline(pixels, curve, "stroke:#1f77b4;stroke-width:2");
    for (std::size_t k = 0; k + 1 < steps.size(); ++k) {
        const ToiResult& at = steps[k].at;
        const double next = double(steps[k + 1].at.time);
        svg.line(pixels, map(double(at.time), double(at.distance)), map(next, double(options.target)),
                 "stroke:#ff7f0e;stroke-width:1.5;stroke-dasharray:6 3");
        svg.line(pixels, map(next, double(options.target)), map(next, double(steps[k + 1].at.distance)),
                 "stroke:#aaa;stroke-width:1");
    }
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const Point2 at = map(double(steps[k].at.time), double(steps[k].at.distance));
        svg.dot(pixels, at, 4, k + 1 == steps.size() ? "#2ca02c" : "#000");
        const Point2 label = pixel(at);
        if (k + 1 < steps.size() && k < 3) svg.textAt({label.x + 6, label.y - 6}, ccdText("d%.0f", double(k)), "font-size:12px");
    }
    svg.textAt({x0 + 150, y0 - h + 10}, "distance (GJK)", "fill:#1f77b4");
    svg.textAt({x0 + 150, y0 - h + 28}, "d_k - mu_k (t - t_k)", "fill:#ff7f0e");
    svg.textAt({x0 + 60, y0 - h - 20},
               ccdText("first bound mu_0 = %.2f m per step (turn: %.2f rad)", double(steps.front().bound), double(sweepAngle(sweep))),
               "fill:#333;font-size:12px");
    return svg.save(path);
}

bool drawToiLoop(const std::string& path) {
    // Three bullets and a wall in one step. A and B fly at the wall along x, B faster and behind;
    // D falls across A's line later in the step, where A waits after B hits it. The impacts are
    // found with the engine's findImpact and the earliest taken first, as the TOI loop takes
    // them; the loop's own run on the same world gives the count in the caption.
    World world;
    world.settings.ccd = CcdMode::On;
    addStaticBox(world, "wall", Vec3::Zero(), Vec3(Real(0.05), 2, 2));
    const auto bullet = [&](const char* name, const Vec3& from) {
        BodyDef def;
        def.name = name;
        def.shape = Shape::sphere(Real(0.05));
        def.transform.position = from;
        def.bullet = true;
        return addBody(world, def);
    };
    const int a = bullet("A", Vec3(-3, 0, 0)), b = bullet("B", Vec3(-4, 0, 0)), d = bullet("D", Vec3(Real(-1.21), Real(2.6), 0));
    const Vec3 travel[3] = {Vec3(4, 0, 0), Vec3(6, 0, 0), Vec3(0, -4, 0)};
    const int movers[3] = {a, b, d};
    world.step.ccd.sweepStart.clear();
    for (const Body& body : world.bodies) world.step.ccd.sweepStart.push_back(body.transform);
    const Real dt = Real(1) / 60;
    for (int i = 0; i < 3; ++i) {
        world.bodies[std::size_t(movers[i])].transform.position += travel[i];
        world.motionOf(movers[i])->linearVelocity = travel[i] / dt;
    }

    std::vector<Sweep> sweeps;
    for (std::size_t i = 0; i < world.bodies.size(); ++i)
        sweeps.push_back(sweepBetween(world.step.ccd.sweepStart[i], world.bodies[i].transform, Vec3::Zero()));
    const ToiOptions options = toiOptionsFor(world.settings);
    const auto impact = [&](int mover, int other, ToiEvent& event) {
        return mayHit(world, mover, other) && findImpact(world, mover, other, sweeps, options, event);
    };

    // Round 1: every pair the loop checks.
    std::vector<ToiEvent> found;
    for (int mover : movers)
        for (int other = 0; other < int(world.bodies.size()); ++other) {
            ToiEvent event;
            if (other < mover && other != 0) continue;  // each pair of bullets once
            if (impact(mover, other, event)) found.push_back(event);
        }
    const auto first = std::min_element(found.begin(), found.end(),
                                        [](const ToiEvent& x, const ToiEvent& y) { return x.toi.time < y.toi.time; });
    const ToiEvent taken = *first;
    // Its bodies wait at their poses of that time; what involved them is looked at again.
    for (int body : {taken.mover, taken.other}) {
        const Real t = taken.toi.time;
        sweeps[std::size_t(body)] = stillSweep(poseAt(sweeps[std::size_t(body)], t), Vec3::Zero());
        sweeps[std::size_t(body)].alpha0 = t;
    }
    ToiEvent second;
    const bool again = impact(d, a, second) || impact(a, d, second);

    World run = world;
    resolveTimesOfImpact(run, dt);

    Svg svg(900, 320);
    const double x0 = 120, x1 = 860, rowTop = 80, rowGap = 70;
    const auto xAt = [&](double t) { return x0 + t * (x1 - x0); };
    const char* names[3] = {"A", "B", "D"};
    const auto row = [&](int body) {
        for (int i = 0; i < 3; ++i)
            if (movers[i] == body) return i;
        return -1;
    };
    for (int i = 0; i < 3; ++i) {
        const double y = rowTop + i * rowGap;
        svg.rect(x0, y - 6, x1 - x0, 12, "#dde8f3");
        svg.textAt({30, y + 5}, std::string("bullet ") + names[i]);
    }
    for (int tick = 0; tick <= 10; ++tick) {
        const double x = xAt(tick / 10.0);
        svg.textAt({x - 9, rowTop + 3 * rowGap}, ccdText("%.1f", tick / 10.0), "font-size:11px");
    }
    svg.textAt({x1 - 160, rowTop + 3 * rowGap + 22}, "t (fraction of the step)");
    const Viewport pixels{0, 0, 900, 330, {450, 165}, 1};
    const auto mark = [&](const ToiEvent& event, const std::string& colour, const std::string& label) {
        for (int body : {event.mover, event.other}) {
            const int r = row(body);
            if (r < 0) continue;
            const double x = xAt(double(event.toi.time)), y = rowTop + r * rowGap;
            svg.line(pixels, {x, 330 - (y - 14)}, {x, 330 - (y + 14)}, "stroke:" + colour + ";stroke-width:3");
            svg.textAt({x - 14, colour == "#d62728" ? y + 30 : y - 18}, label, "font-size:12px;fill:" + colour);
        }
    };
    for (const ToiEvent& event : found) {
        const bool isTaken = event.mover == taken.mover && event.other == taken.other;
        const std::string other = event.other == 0 ? "wall" : world.bodies[std::size_t(event.other)].name;
        mark(event, isTaken ? "#2ca02c" : "#d62728",
             isTaken ? "1st" : world.bodies[std::size_t(event.mover)].name + "-" + other + " dropped");
    }
    if (again) {
        const double y = rowTop + row(d) * rowGap;
        svg.rect(xAt(double(second.toi.time)), y - 6, xAt(1) - xAt(double(second.toi.time)), 12, "#bbb");
        mark(second, "#2ca02c", "2nd, found again");
    }
    for (int body : {taken.mover, taken.other}) {
        const double y = rowTop + row(body) * rowGap;
        svg.rect(xAt(double(taken.toi.time)), y - 6, xAt(1) - xAt(double(taken.toi.time)), 12, "#bbb");
    }
    svg.textAt({10, 24}, ccdText("found in the step: %.0f impacts; the earliest (t = %.3f) is resolved first, and the",
                                double(found.size()), double(taken.toi.time)), "fill:#333");
    svg.textAt({10, 44}, ccdText("impacts of its bodies are dropped and searched again; the engine's loop resolves %.0f (grey: time lost)",
                                double(run.step.ccd.toiEvents)), "fill:#333");
    return svg.save(path);
}

}  // namespace figures
