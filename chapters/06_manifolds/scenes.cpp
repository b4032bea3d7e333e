// Chapter 6's stacking scenes.
#include "06_manifolds/scenes.h"

#include "04_pgs/scenes.h"
#include "06_manifolds/stacking_study.h"
#include "app/panel.h"
#include "app/registry.h"
#include "world/contact_draw.h"
#include "world/debug_draw.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <string>

namespace stepwise {

namespace {

const Vec3 kUnitHalf(Real(0.5), Real(0.5), Real(0.5));

World stackingWorld(const std::string& name) {
    World world = emptyWorld(name);
    addGroundPlane(world, kStackFriction);
    return world;
}

int addUnitBox(World& world, const std::string& name, const Vec3& center, Real mass) {
    return addCrate(world, name, center, kUnitHalf, mass, Material{kStackFriction, 0});
}

}  // namespace

World buildBoxStack(int count) {
    World world = stackingWorld("stack-" + std::to_string(count));
    for (int i = 0; i < count; ++i)
        addUnitBox(world, "box" + std::to_string(i), Vec3(0, Real(0.5) + static_cast<Real>(i), 0), 1);
    return world;
}

World buildPyramid(int rows) {
    World world = stackingWorld("pyramid-" + std::to_string(rows));
    const Real spacing = Real(1.05);
    for (int row = 0; row < rows; ++row) {
        const int boxes = rows - row;
        const Real left = -Real(0.5) * spacing * static_cast<Real>(boxes - 1);
        for (int i = 0; i < boxes; ++i)
            addUnitBox(world, "r" + std::to_string(row) + "b" + std::to_string(i),
                       Vec3(left + spacing * static_cast<Real>(i), Real(0.5) + static_cast<Real>(row), 0), 1);
    }
    return world;
}

World buildHeavyOnLight() {
    World world = stackingWorld("heavy-on-light");
    for (int i = 0; i < 3; ++i)
        addUnitBox(world, "light" + std::to_string(i), Vec3(Real(-1.1) + Real(1.1) * static_cast<Real>(i), Real(0.5), 0), 1);
    addCrate(world, "heavy", Vec3(0, Real(1.5), 0), Vec3(Real(1.6), Real(0.5), Real(0.5)), 100,
             Material{kStackFriction, 0});
    return world;
}

World buildMassTower(bool heaviestAtBottom) {
    World world = stackingWorld(heaviestAtBottom ? "tower-heavy-below" : "tower-heavy-above");
    const Real masses[] = {1000, 100, 10, 1};  // bottom to top when the heaviest is at the bottom
    for (int i = 0; i < 4; ++i) {
        const Real mass = heaviestAtBottom ? masses[i] : masses[3 - i];
        addUnitBox(world, "box" + std::to_string(static_cast<int>(mass)) + "kg", Vec3(0, Real(0.5) + static_cast<Real>(i), 0),
                   mass);
    }
    return world;
}

World buildCardHouse() {
    World world = stackingWorld("card-house");
    const Material card{Real(0.9), 0};
    const Vec3 cardHalf(Real(0.05), Real(0.6), Real(0.4));
    const Real lean = Real(0.35);  // rad from the vertical
    const Real height = 2 * cardHalf.y() * math::cos(lean);
    const Real foot = cardHalf.y() * math::sin(lean);
    for (int storey = 0; storey < 2; ++storey) {
        const int pairs = 2 - storey;
        const Real base = static_cast<Real>(storey) * (height + 2 * Real(0.05));
        for (int p = 0; p < pairs; ++p) {
            const Real x = (static_cast<Real>(p) - Real(0.5) * static_cast<Real>(pairs - 1)) * Real(1.1);
            for (int side : {-1, 1}) {
                const Real angle = static_cast<Real>(side) * lean;
                const Quat tilt(angleAxis(angle, Vec3::UnitZ()));
                // The plates' tops touch at x; their feet stand apart.
                const Vec3 center(x + static_cast<Real>(side) * (foot + cardHalf.x() * math::cos(lean)),
                                  base + Real(0.5) * height + Real(0.02), 0);
                addCrate(world, "card" + std::to_string(storey) + std::to_string(p) + (side < 0 ? "l" : "r"), center,
                         cardHalf, Real(0.5), card, tilt);
            }
        }
        if (storey == 0)
            addCrate(world, "floor", Vec3(0, height + Real(0.07), 0), Vec3(Real(1.3), Real(0.05), Real(0.4)), Real(0.5), card);
    }
    return world;
}

World buildStickingRamp(int* box) {
    World world = buildRampScene(Real(kPi / 6), Real(0.8), box);
    world.name = "stack-ramp";
    return world;
}

}  // namespace stepwise

namespace stepwise {

namespace {

/// The highest centre of a moving body, m.
Real tallestHeight(const World& world) {
    Real highest = 0;
    for (const Motion& motion : world.motions)
        highest = std::max(highest, world.bodies[static_cast<std::size_t>(motion.bodyIndex)].transform.position.y());
    return highest;
}

// [ch06-view]
/// The stacking scenes' view: toggles for manifolds against one point, warm starting and the
/// stabilisation (all Settings, read by the stages every step), the manifold points with their
/// feature ids, and a graph of the tallest box's height over time beside the scene.
class StackingView : public SceneView {
public:
    void draw(const World& world, DebugDraw& draw) const override {
        record(world);
        ContactDrawOptions contactOptions;
        contactOptions.normals = false;
        drawContacts(draw, world, contactOptions);
        if (showFeatureIds_) drawFeatureIds(world, draw);
        drawHeightGraph(world, draw);
    }
    bool hasPanel() const override { return true; }
    void panel(World& world, Panel& panel) override {
        panel.checkbox("manifolds (off: one point per pair)", world.settings.manifoldContacts);
        panel.checkbox("warm starting", world.settings.warmStarting);
        static const char* const kNames[] = {"baumgarte", "relax", "split_impulse", "soft_step"};
        int choice = static_cast<int>(world.settings.stabilisation);
        if (panel.combo("stabilisation", choice, kNames, 4)) world.settings.stabilisation = static_cast<Stabilisation>(choice);
        panel.checkbox("feature ids", showFeatureIds_);
        char line[96];
        std::snprintf(line, sizeof line, "tallest box: %.4f m (start %.4f m)", static_cast<double>(tallestHeight(world)),
                      history_.empty() ? 0.0 : static_cast<double>(startHeight_));
        panel.text(line);
        int points = 0, persisted = 0;
        for (const Contact& contact : world.contacts)
            for (int i = 0; i < contact.pointCount; ++i) ++points, persisted += contact.points[i].persisted ? 1 : 0;
        std::snprintf(line, sizeof line, "%d contact points, %d carried from the last step", points, persisted);
        panel.text(line);
    }

private:
    // The history is kept per frame number, so drawing a frame twice records it once.
    void record(const World& world) const {
        if (world.frame == 0 || history_.empty()) {
            history_.clear();
            startHeight_ = tallestHeight(world);
        }
        if (!history_.empty() && lastFrame_ == world.frame) return;
        lastFrame_ = world.frame;
        history_.push_back(tallestHeight(world));
        if (history_.size() > kHistory) history_.pop_front();
    }

    static void drawFeatureIds(const World& world, DebugDraw& draw) {
        for (const Contact& contact : world.contacts) {
            for (int i = 0; i < contact.pointCount; ++i) {
                char id[16];
                std::snprintf(id, sizeof id, "%08x", contact.points[i].featureId);
                draw.text(contact.points[i].pointB, id, contact.points[i].persisted ? colors::kGreen : colors::kWhite);
            }
        }
    }

    // Beside the scene, to the right of the moving bodies: 10 s of the tallest box's height,
    // its start as a dashed-grey reference, drawn 20 times taller than it moves (1 cm of sinking
    // shows as 20 cm) so that millimetres show.
    void drawHeightGraph(const World& world, DebugDraw& draw) const {
        Real right = 0;
        for (const Motion& motion : world.motions)
            right = std::max(right, world.bodies[static_cast<std::size_t>(motion.bodyIndex)].transform.position.x());
        const Vec3 origin(right + Real(2), startHeight_, 0);
        const Real width = 4, scale = 20;
        draw.line(origin, origin + Vec3(width, 0, 0), colors::kGrey);
        draw.text(origin + Vec3(0, Real(0.4), 0), "tallest box height (x20)", colors::kWhite);
        for (std::size_t i = 1; i < history_.size(); ++i) {
            const Real x0 = width * static_cast<Real>(i - 1) / kHistory, x1 = width * static_cast<Real>(i) / kHistory;
            const Real y0 = std::clamp(scale * (history_[i - 1] - startHeight_), Real(-3), Real(3));
            const Real y1 = std::clamp(scale * (history_[i] - startHeight_), Real(-3), Real(3));
            draw.line(origin + Vec3(x0, y0, 0), origin + Vec3(x1, y1, 0), colors::kCyan);
        }
    }

    static constexpr std::size_t kHistory = 600;  // 10 s at 60 Hz
    bool showFeatureIds_ = false;
    mutable std::deque<Real> history_;
    mutable Real startHeight_ = 0;
    mutable long lastFrame_ = -1;
};
// [ch06-view]

}  // namespace

void addChapter06Scenes(Registry& registry) {
    const char* const category = "Stacking";
    const SceneViewFactory view = viewOfType<StackingView>();
    registry.addScene({"stack-16", 6, category, prose(R"(
        16 boxes stand: none moves sideways by more than a centimetre)"),
        [] { return buildBoxStack(16); }, view});
    registry.addScene({"pyramid-20", 6, category, prose(R"(
        210 boxes in 20 rows stand still)"),
        [] { return buildPyramid(20); }, view});
    registry.addScene({"heavy-on-light", 6, category, prose(R"(
        100 kg on three 1 kg boxes sinks no more than the slop per contact)"),
        [] { return buildHeavyOnLight(); }, view});
    registry.addScene({"tower-heavy-below", 6, category, prose(R"(
        1, 10, 100, 1000 kg from the top: it stands)"),
        [] { return buildMassTower(true); }, view});
    registry.addScene({"tower-heavy-above", 6, category, prose(R"(
        1000 kg on top of 100, 10 and 1 kg: try soft_step)"),
        [] { return buildMassTower(false); }, view});
    registry.addScene({"card-house", 6, category, prose(R"(
        thin plates leaning on each other hold by friction)"),
        [] { return buildCardHouse(); }, view});
    registry.addScene({"stack-ramp", 6, category, prose(R"(
        a box on a 30 degree ramp with mu 0.8 does not creep)"),
        [] { return buildStickingRamp(); }, view});
}

}  // namespace stepwise
