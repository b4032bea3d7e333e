// Figures for chapter 12, computed by running the engine: how far a load gets in a given number of
// sweeps, and the layers and groups of a shock sweep.
#include "figures.h"

#include "04_pgs/scenes.h"
#include "10_skip_work/scenes.h"
#include "11_wide_solve/contact_solver.h"
#include "12_planner/chapter.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace figures {

using namespace stepwise;

namespace {

constexpr int kColumnHeight = 10;

/// A column of unit boxes, each resting exactly on the one below, nothing carried yet.
World restingColumn(int substeps) {
    World world = emptyWorld("column");
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(5, Real(0.5), 5), Quat::Identity(), Material{});
    for (int i = 0; i < kColumnHeight; ++i)
        addCrate(world, "box" + std::to_string(i), Vec3(0, Real(0.5) + static_cast<Real>(i), 0), Vec3::Constant(Real(0.5)),
                 1, Material{}, Quat::Identity());
    world.settings.solverIterations = substeps;
    world.settings.planIterations = false;
    world.settings.sleeping = false;
    return world;
}

/// The contacts' normal load, layer by layer from the ground, after one frame of `substeps`
/// substeps (each one sweep), as a fraction of the weight above the layer.
std::vector<double> loadAfter(int substeps) {
    World world = restingColumn(substeps);
    SpeedOptions options;
    options.shockPropagation = false;
    Pipeline pipeline = makeChapter12Pipeline(world, options);
    pipeline.step(world);
    std::vector<double> load(kColumnHeight, 0.0);
    const double weightImpulse = 9.81 * static_cast<double>(world.settings.dt) / substeps;  // one box, one substep
    for (const Contact& contact : world.contacts) {
        const int layer = std::min(contact.bodyA, contact.bodyB);  // ground is body 0: layer 0 under box 1
        if (layer < 0 || layer >= kColumnHeight) continue;
        double sum = 0;
        for (int i = 0; i < contact.pointCount; ++i) sum += static_cast<double>(contact.points[i].normalImpulse);
        load[static_cast<std::size_t>(layer)] = sum / (weightImpulse * (kColumnHeight - layer));
    }
    return load;
}

std::string shade(double fraction) {  // white (nothing) to dark blue (the whole weight above)
    const double f = std::clamp(fraction, 0.0, 1.0);
    char colour[16];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", static_cast<int>(255 - 224 * f), static_cast<int>(255 - 136 * f),
                  static_cast<int>(255 - 75 * f));
    return colour;
}

}  // namespace

// [ch12-figure-load]
bool drawLoadCrossing(const std::string& path) {
    // Columns: frames of 1 to 12 substeps, from the same untouched start. Rows: the ten contact
    // layers of the column, ground at the bottom. Each cell: the layer's load after the frame as a
    // fraction of the weight it must carry.
    const int most = 12;
    Svg svg(720, 470);
    const Viewport pixels{0, 0, 720, 470, {360, 235}, 1};
    const double left = 110, top = 40, cell = 44, height = 36;
    for (int substeps = 1; substeps <= most; ++substeps) {
        const std::vector<double> load = loadAfter(substeps);
        const double x = left + (substeps - 1) * cell;
        for (int layer = 0; layer < kColumnHeight; ++layer) {
            const double y = top + (kColumnHeight - 1 - layer) * height;
            svg.rect(x, y, cell - 2, height - 2, shade(load[static_cast<std::size_t>(layer)]));
        }
        svg.textAt({x + 12, top + kColumnHeight * height + 18}, std::to_string(substeps));
    }
    for (int layer = 0; layer < kColumnHeight; ++layer)
        svg.textAt({10, top + (kColumnHeight - 1 - layer) * height + 24},
                   layer == 0 ? "ground" : "layer " + std::to_string(layer));
    svg.textAt({left, 25}, "load of each contact layer after one frame, as a share of the weight above it");
    svg.textAt({left + 120, top + kColumnHeight * height + 40}, "substeps (one sweep each) in the frame");
    (void)pixels;
    return svg.save(path);
}
// [ch12-figure-load]

bool drawShockLayers(const std::string& path) {
    // A five-row pyramid at rest: each box coloured by its depth (contacts down to the ground),
    // each contact between two depths marked with its shock-sweep group, the held (lower) body
    // below it.
    World world = buildPyramidRow(1, 5);
    world.settings.sleeping = false;
    Pipeline pipeline = makeChapter12Pipeline(world);
    for (int frame = 0; frame < 30; ++frame) pipeline.step(world);
    std::vector<int> contacts;
    collectSolvableContacts(world, contacts);
    StackSearch search;
    supportDepth(world, contacts, search);
    std::vector<int> slotA, slotB, slotDepth(world.bodies.size() + 1, 0);
    for (std::size_t body = 0; body < world.bodies.size(); ++body)
        if (world.bodies[body].type == BodyType::Dynamic)
            slotDepth[body + 1] = body < search.depth.size() ? search.depth[body] : 0;
    const auto slotOf = [&](int body) { return world.bodies[static_cast<std::size_t>(body)].type == BodyType::Dynamic ? body + 1 : 0; };
    for (const int index : contacts) {
        slotA.push_back(slotOf(world.contacts[static_cast<std::size_t>(index)].bodyA));
        slotB.push_back(slotOf(world.contacts[static_cast<std::size_t>(index)].bodyB));
    }
    ShockOrder order;
    orderShockSweep(slotA, slotB, slotDepth, order);

    Svg svg(720, 420);
    const Viewport view{0, 30, 720, 380, {0, 2.4}, 120};
    const char* depthColours[] = {"#dddddd", "#c6dbef", "#9ecae1", "#6baed6", "#3182bd", "#08519c"};
    for (std::size_t body = 0; body < world.bodies.size(); ++body) {
        const Body& b = world.bodies[body];
        if (b.type != BodyType::Dynamic) continue;
        const Vec3 c = b.transform.position;
        const double x = static_cast<double>(c.x()), y = static_cast<double>(c.y());
        const int depth = body < search.depth.size() ? search.depth[body] : 0;
        svg.polygon(view, {{x - 0.5, y - 0.5}, {x + 0.5, y - 0.5}, {x + 0.5, y + 0.5}, {x - 0.5, y + 0.5}},
                    std::string("fill:") + depthColours[std::min(depth, 5)] + ";stroke:#333;stroke-width:1");
        svg.text(view, {x - 0.1, y + 0.05}, "d" + std::to_string(depth));
    }
    svg.polygon(view, {{-3.2, -0.02}, {3.2, -0.02}, {3.2, -0.2}, {-3.2, -0.2}}, "fill:#888");
    for (std::size_t group = 0; group + 1 < order.groupStart.size(); ++group) {
        for (int k = order.groupStart[group]; k < order.groupStart[group + 1]; ++k) {
            const Contact& contact = world.contacts[static_cast<std::size_t>(
                contacts[static_cast<std::size_t>(order.entries[static_cast<std::size_t>(k)])])];
            Vec3 centre = Vec3::Zero();
            for (int i = 0; i < contact.pointCount; ++i) centre += contact.points[i].pointB;
            centre /= static_cast<Real>(std::max(1, contact.pointCount));
            const Point2 at{static_cast<double>(centre.x()), static_cast<double>(centre.y())};
            svg.dot(view, at, 9, "#d62728");
            svg.text(view, {at.x - 0.05, at.y - 0.04}, std::to_string(group + 1), "fill:white;font-size:11px");
        }
    }
    svg.textAt({20, 22}, "depth d of each box (contacts down to the ground); red: contacts in shock-sweep group order");
    return svg.save(path);
}

}  // namespace figures
