// Chapter 5's demo scenes, the broadphase overlay and the panel.
#include "05_sap/scenes.h"

#include "05_sap/chapter.h"
#include "app/panel.h"
#include "app/registry.h"
#include "world/debug_draw.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

namespace stepwise {

namespace {

const char* const kAxisNames[] = {"x", "y", "z"};

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

bool isEmpty(const Aabb& box) { return (box.min.array() > box.max.array()).any(); }

/// The box around every moving body's bounds (empty when there is none).
Aabb movingBounds(const World& world) {
    Aabb all;
    const std::vector<Aabb>& bounds = world.broadphase.bounds;
    for (std::size_t i = 0; i < bounds.size() && i < world.bodies.size(); ++i)
        if (world.bodies[i].type != BodyType::Static && !isEmpty(bounds[i])) all.grow(bounds[i]);
    return all;
}

void drawBoundsAndPairs(const World& world, const BroadphaseOverlay& overlay, DebugDraw& draw) {
    const std::vector<Aabb>& bounds = world.broadphase.bounds;
    std::vector<char> inPair(world.bodies.size(), 0);
    for (const BodyPair& pair : world.candidatePairs) {
        if (pair.bodyB >= static_cast<int>(world.bodies.size())) continue;
        const Body& a = world.bodies[static_cast<std::size_t>(pair.bodyA)];
        const Body& b = world.bodies[static_cast<std::size_t>(pair.bodyB)];
        // Pairs with the ground (every landed body has one) are left out: they would all meet
        // at its centre and make every box orange.
        if (a.type == BodyType::Static || b.type == BodyType::Static) continue;
        inPair[static_cast<std::size_t>(pair.bodyA)] = inPair[static_cast<std::size_t>(pair.bodyB)] = 1;
        if (overlay.candidatePairs) draw.line(a.transform.position, b.transform.position, colors::kYellow);
    }
    if (!overlay.bounds) return;
    for (std::size_t i = 0; i < bounds.size() && i < world.bodies.size(); ++i) {
        if (world.bodies[i].type == BodyType::Static || isEmpty(bounds[i])) continue;
        Transform pose;
        pose.position = bounds[i].center();
        draw.box(pose, bounds[i].extents(), inPair[i] ? colors::kOrange : colors::kGrey, Fill::Wire);
    }
}

// The interval picture: the sweep axis as an arrow beside the bodies, and each moving body's
// interval on it as a cyan segment, spread over a few lanes so overlapping intervals show.
void drawIntervals(const World& world, DebugDraw& draw) {
    const int axis = world.broadphase.axis;
    const Aabb all = movingBounds(world);
    if (axis < 0 || axis > 2 || isEmpty(all)) return;
    // Beside the bodies: off the low side of the next axis in the ground plane (z for x, x else).
    const int side = axis == 0 ? 2 : 0;
    const Real lane = Real(0.3);
    constexpr int kLanes = 6;
    Vec3 origin = all.min;
    origin[side] -= Real(1) + lane * kLanes;
    if (axis != 1) origin.y() = std::max(all.min.y(), Real(0.05));
    Vec3 tip = origin;
    tip[axis] = all.max[axis] + Real(1);
    draw.arrow(origin, tip, colors::kWhite);
    draw.text(tip, std::string("sweep axis ") + kAxisNames[axis], colors::kWhite);
    int drawn = 0;
    for (const SweepEndpoint& end : world.broadphase.endpoints) {
        const std::size_t body = static_cast<std::size_t>(end.body);
        if (body >= world.bodies.size() || world.bodies[body].type == BodyType::Static) continue;
        const Aabb& box = world.broadphase.bounds[body];
        Vec3 from = origin, to = origin;
        from[side] += lane * static_cast<Real>(1 + drawn % kLanes);
        to[side] = from[side];
        from[axis] = box.min[axis];
        to[axis] = box.max[axis];
        draw.line(from, to, colors::kCyan);
        ++drawn;
    }
}

/// The stress scenes' view: what the overlay shows, and the generator's parameters for the
/// "regenerate" button. The demo makes a fresh view at every load, so a restart (R) brings the
/// scene's own parameters back.
class StressView : public SceneView {
public:
    explicit StressView(StressParams params) : params_(params) {}
    void draw(const World& world, DebugDraw& draw) const override { drawBroadphase(world, overlay_, draw); }
    bool hasPanel() const override { return true; }
    void panel(World& world, Panel& panel) override;

private:
    StressParams params_;
    BroadphaseOverlay overlay_;
};

void StressView::panel(World& world, Panel& panel) {
    const char* const modes[] = {"auto", "sweep and prune", "brute force"};
    int mode = world.settings.broadphase == BroadphaseMode::Sap ? 1 : world.settings.broadphase == BroadphaseMode::Brute ? 2 : 0;
    if (panel.combo("broadphase", mode, modes, 3))
        world.settings.broadphase = mode == 1 ? BroadphaseMode::Sap : mode == 2 ? BroadphaseMode::Brute : BroadphaseMode::Auto;
    describeBroadphase(world, panel);
    panel.checkbox("draw bounds", overlay_.bounds);
    panel.checkbox("draw candidate pairs", overlay_.candidatePairs);
    panel.checkbox("draw sweep axis and intervals", overlay_.intervals);

    panel.text("stress scene generator:");
    panel.sliderInt("bodies", params_.count, 10, 5000);
    const char* const densities[] = {"sparse", "dense"};
    int density = params_.density == StressDensity::Dense ? 1 : 0;
    if (panel.combo("density", density, densities, 2)) params_.density = density == 1 ? StressDensity::Dense : StressDensity::Sparse;
    // The combo lists the kinds in StressShape's order, which is the order of its names.
    const char* const shapes[] = {"sphere", "diamond", "box", "mixed", "capsule", "cylinder", "all"};
    int shape = static_cast<int>(params_.shape);
    if (panel.combo("shape", shape, shapes, 7)) params_.shape = static_cast<StressShape>(shape);
    float height = static_cast<float>(params_.dropHeight);
    if (panel.sliderFloat("drop height (m)", height, 0.0f, 50.0f)) params_.dropHeight = static_cast<Real>(height);
    if (panel.button("regenerate")) {
        // The world is replaced in place; the settings (and the broadphase toggle) stay. The
        // pipeline's stages keep no state, so they step the new bodies at once (F frames them).
        World fresh = buildStressScene(params_, world.name);
        fresh.settings = world.settings;
        world = std::move(fresh);
    }
}

}  // namespace

// [ch05-demo-draw]
void drawBroadphase(const World& world, const BroadphaseOverlay& overlay, DebugDraw& draw) {
    drawBoundsAndPairs(world, overlay, draw);
    if (overlay.intervals) drawIntervals(world, draw);
}
// [ch05-demo-draw]

void describeBroadphase(const World& world, Panel& panel) {
    const BroadphaseState& state = world.broadphase;
    if (state.used == BroadphaseMode::Auto) {
        panel.text("no broadphase has run yet (step once)");
        return;
    }
    panel.text(std::string("broadphase: ") + toString(state.used) + " (" + state.reason + ")");
    const double bodies = static_cast<double>(world.bodies.size());
    panel.text("candidate pairs: " + std::to_string(world.candidatePairs.size()) + " of " +
               format("%.0f", bodies * (bodies - 1) / 2) + " pairs of bodies");
    if (state.used != BroadphaseMode::Sap) return;
    panel.text(std::string("sweep axis: ") + kAxisNames[state.axis] + format(" (centre variance x %.3g", double(state.centreVariance.x())) +
               format(", y %.3g", double(state.centreVariance.y())) + format(", z %.3g m^2)", double(state.centreVariance.z())));
    panel.text(state.fullSort ? std::string("last sort: full (new axis, new bodies, or too much moved)")
                              : "last sort: incremental, " + std::to_string(state.sortMoves) + " moves");
    panel.text("intervals overlapping on the axis: " + std::to_string(state.axisOverlaps));
}

StressParams demoStressParams(StressDensity density) {
    StressParams params;
    params.density = density;
    params.count = density == StressDensity::Dense ? 343 : 400;
    params.shape = StressShape::Mixed;
    params.dropHeight = density == StressDensity::Dense ? 1 : 3;
    return params;
}

void addChapter05Scenes(Registry& registry) {
    const char* const category = "Sweep and prune";
    const auto stressScene = [](StressDensity density, const char* name) {
        const StressParams params = demoStressParams(density);
        const std::string sceneName = name;
        return std::make_pair([params, sceneName] { return buildStressScene(params, sceneName); },
                              SceneViewFactory([params] { return std::unique_ptr<SceneView>(std::make_unique<StressView>(params)); }));
    };
    const auto sparse = stressScene(StressDensity::Sparse, "sap-stress");
    const auto dense = stressScene(StressDensity::Dense, "sap-stress-dense");
    registry.addScene({"sap-stress", 5, category, prose(R"(
        400 bodies spread out fall and land: switch brute force and sweep and prune and watch the broadphase
        time (the bodies move exactly the same); orange bounds have a candidate pair with another body, the
        cyan intervals lie on the sweep axis)"),
        sparse.first, sparse.second});
    registry.addScene({"sap-stress-dense", 5, category, prose(R"(
        343 bodies packed in a block fall into a pile: nearly every body has candidate pairs, so sweep and
        prune saves less and the narrowphase and solver take the time)"),
        dense.first, dense.second});
}

}  // namespace stepwise
