// Figures for chapter 5, computed by the engine's own sweep and prune.
#include "figures.h"

#include "05_sap/chapter.h"
#include "world/world.h"

#include <cstdio>

namespace figures {

using namespace stepwise;

bool drawSweepIntervals(const std::string& path) {
    // Seven bodies seen from above (x right, z up the page), no motion, no gravity: their boxes,
    // each box's interval on the sweep axis x below them, and the pairs the sweep reports.
    // Intervals that overlap on x but whose boxes miss on z are looked at and dropped.
    World world;
    world.settings.gravity = Vec3::Zero();
    const struct {
        double x, z, size;
        bool sphere;
    } layout[] = {{-3.2, 0.6, 0.5, true}, {-2.4, 1.1, 0.45, false}, {-1.2, -1.3, 0.6, true}, {-0.5, 1.4, 0.4, false},
                  {0.4, -0.9, 0.5, false}, {1.0, -0.3, 0.45, true}, {2.6, 0.9, 0.55, true}};
    for (const auto& body : layout) {
        BodyDef def;
        def.shape = body.sphere ? Shape::sphere(Real(body.size)) : Shape::box(Vec3::Constant(Real(body.size)));
        def.transform.position = Vec3(Real(body.x), 0, Real(body.z));
        addBody(world, def);
    }
    world.settings.broadphase = BroadphaseMode::Sap;
    sweepAndPrune(world);
    const BroadphaseState& state = world.broadphase;

    Svg svg(760, 520);
    const Viewport view{0, 30, 760, 470, {-0.1, -0.5}, 95};
    const char* const colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#17becf"};
    const double axisZ = -2.6;
    svg.arrow(view, {-4.2, axisZ}, {3.9, axisZ}, "#333");
    svg.text(view, {2.6, axisZ - 0.3}, "x (sweep axis)");
    int lane = 0;
    for (const SweepEndpoint& end : state.endpoints) {
        const std::size_t i = static_cast<std::size_t>(end.body);
        const Aabb& box = state.bounds[i];
        const std::string colour = colours[i % 7];
        const double x0 = box.min.x(), x1 = box.max.x(), z0 = box.min.z(), z1 = box.max.z();
        svg.polygon(view, {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}}, "fill:none;stroke:" + colour + ";stroke-dasharray:4 3");
        if (world.bodies[i].shape.type == ShapeType::Sphere)
            svg.circle(view, {layout[i].x, layout[i].z}, layout[i].size, "fill:" + colour + ";fill-opacity:0.35;stroke:" + colour);
        else
            svg.polygon(view, {{layout[i].x - layout[i].size, layout[i].z - layout[i].size}, {layout[i].x + layout[i].size, layout[i].z - layout[i].size},
                               {layout[i].x + layout[i].size, layout[i].z + layout[i].size}, {layout[i].x - layout[i].size, layout[i].z + layout[i].size}},
                        "fill:" + colour + ";fill-opacity:0.35;stroke:" + colour);
        // The interval, in lanes so overlapping ones stay apart, with its two ends on the axis.
        const double laneZ = axisZ + 0.25 + 0.16 * (lane++ % 4);
        svg.line(view, {x0, laneZ}, {x1, laneZ}, "stroke:" + colour + ";stroke-width:4");
        svg.line(view, {x0, axisZ}, {x0, laneZ}, "stroke:" + colour + ";stroke-width:1;stroke-dasharray:2 2");
        svg.line(view, {x1, axisZ}, {x1, laneZ}, "stroke:" + colour + ";stroke-width:1;stroke-dasharray:2 2");
    }
    for (const BodyPair& pair : world.candidatePairs)
        svg.line(view, {layout[pair.bodyA].x, layout[pair.bodyA].z}, {layout[pair.bodyB].x, layout[pair.bodyB].z},
                 "stroke:#000;stroke-width:3");
    char label[200];
    std::snprintf(label, sizeof label, "%ld pairs overlap on x and are looked at; %zu overlap on z too: candidate pairs (black)",
                  state.axisOverlaps, world.candidatePairs.size());
    svg.textAt({12, 24}, label, "fill:#333");
    return svg.save(path);
}

}  // namespace figures
