// The chapter 2 demo scenes and their overlay: two boxes, and a sphere against a diamond.

#include "02_gjk/scenes.h"

#include "02_gjk/chapter.h"
#include "app/panel.h"
#include "app/registry.h"
#include "world/debug_draw.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace stepwise {

World buildGjkTwoBoxes() {
    World world = emptyWorld("gjk-two-boxes", Vec3::Zero());
    BodyDef cube;
    cube.name = "cube";
    cube.type = BodyType::Kinematic;
    cube.shape = Shape::box(Vec3(0.5, 0.5, 0.5));
    cube.angularVelocity = Vec3(Real(0.25), Real(0.15), 0);
    addBody(world, cube);
    BodyDef plank;
    plank.name = "plank";
    plank.type = BodyType::Kinematic;
    plank.shape = Shape::box(Vec3(Real(1.2), Real(0.2), Real(0.3)));
    plank.transform.position = Vec3(Real(1.6), Real(0.3), 0);
    plank.angularVelocity = Vec3(0, Real(0.9), Real(0.3));
    addBody(world, plank);
    return world;
}

World buildGjkSphereDiamond() {
    World world = emptyWorld("gjk-sphere-diamond", Vec3::Zero());
    BodyDef ball;
    ball.name = "sphere";
    ball.type = BodyType::Static;
    ball.shape = Shape::sphere(Real(0.5));
    addBody(world, ball);
    BodyDef diamond;
    diamond.name = "diamond";
    diamond.type = BodyType::Kinematic;
    const Real tip = Real(0.7);
    diamond.shape = Shape::convex({Vec3(tip, 0, 0), Vec3(-tip, 0, 0), Vec3(0, tip, 0), Vec3(0, -tip, 0),
                                   Vec3(0, 0, Real(0.45)), Vec3(0, 0, Real(-0.45))});
    diamond.transform.position = Vec3(Real(1.1), 0, 0);
    diamond.angularVelocity = Vec3(0, Real(0.2), Real(0.8));
    addBody(world, diamond);
    return world;
}

namespace {

// Corners of a polytope body in world space (empty for round shapes).
std::vector<Vec3> worldCorners(const Body& body) {
    std::vector<Vec3> corners;
    if (body.shape.type == ShapeType::Box) {
        const Vec3& h = body.shape.halfExtents;
        for (int corner = 0; corner < 8; ++corner)
            corners.push_back(body.transform.apply(
                Vec3((corner & 1) ? h.x() : -h.x(), (corner & 2) ? h.y() : -h.y(), (corner & 4) ? h.z() : -h.z())));
    } else if (body.shape.type == ShapeType::Convex && body.shape.hull) {
        for (const Vec3& vertex : body.shape.hull->vertices) corners.push_back(body.transform.apply(vertex));
    }
    return corners;
}

// The demo's view of a GJK scene: which support map the overlay uses, and the user's hold on
// body 1 (the velocities its spin gets back when the user lets go).
class GjkView : public SceneView {
public:
    explicit GjkView(Vec3 overlayAnchor) : overlayAnchor_(overlayAnchor) {}
    void draw(const World& world, DebugDraw& draw) const override;
    bool hasPanel() const override { return true; }
    void panel(World& world, Panel& panel) override;

private:
    SupportMode mode() const { return supportMode_ == 0 ? SupportMode::Extents : SupportMode::Vertices; }
    Vec3 overlayAnchor_;
    int supportMode_ = 0;  // 0 extents, 1 vertices
    bool animate_ = true;
    Vec3 savedLinear_ = Vec3::Zero();
    Vec3 savedAngular_ = Vec3::Zero();
};

std::string describe(const GjkResult& result) {
    char text[160];
    std::snprintf(text, sizeof text, "GJK: %s after %d iterations (exit %s, simplex of %d)",
                  result.intersect ? "INTERSECT" : "separated", result.iterations, toString(result.exit), result.simplex.count);
    return text;
}

// Support mode, and position / rotation sliders that take body 1 over from its spin.
void GjkView::panel(World& world, Panel& panel) {
    if (world.bodies.size() < 2) return;
    const char* const modes[] = {"extents (3 sign tests)", "vertices (loop over 8)"};
    panel.combo("box support map", supportMode_, modes, 2);
    panel.text(describe(gjkIntersect(makeProxy(world.bodies[0], mode()), makeProxy(world.bodies[1], mode()))));

    Body& body = world.bodies[1];
    Motion* motion = world.motionOf(1);
    const bool wasAnimating = animate_;
    panel.checkbox("animate body 1", animate_);
    bool moved = false;
    float position[3] = {float(body.transform.position.x()), float(body.transform.position.y()), float(body.transform.position.z())};
    const char* const axes[3] = {"body 1 x (m)", "body 1 y (m)", "body 1 z (m)"};
    for (int axis = 0; axis < 3; ++axis)
        if (panel.sliderFloat(axes[axis], position[axis], -3.0f, 3.0f)) {
            body.transform.position[axis] = Real(position[axis]);
            moved = true;
        }
    // Rotation as yaw (Y), pitch (X), roll (Z) in degrees, applied in that order.
    const Vec3 euler = body.transform.rotation.toRotationMatrix().eulerAngles(1, 0, 2) * Real(180 / kPi);
    float angles[3] = {float(euler[0]), float(euler[1]), float(euler[2])};
    const char* const names[3] = {"body 1 yaw (deg)", "body 1 pitch (deg)", "body 1 roll (deg)"};
    bool turned = false;
    for (int i = 0; i < 3; ++i) turned = panel.sliderFloat(names[i], angles[i], -180.0f, 180.0f) || turned;
    if (turned) {
        const Real toRadians = kPi / 180;
        body.transform.rotation = Quat(angleAxis(Real(angles[0]) * toRadians, Vec3::UnitY()) *
                                       angleAxis(Real(angles[1]) * toRadians, Vec3::UnitX()) *
                                       angleAxis(Real(angles[2]) * toRadians, Vec3::UnitZ()));
        moved = true;
    }
    if (moved) animate_ = false;
    if (!motion) return;
    // Pausing keeps the scripted velocities to give back when the user lets go.
    if (wasAnimating && !animate_) {
        savedLinear_ = motion->linearVelocity;
        savedAngular_ = motion->angularVelocity;
        motion->linearVelocity.setZero();
        motion->angularVelocity.setZero();
    } else if (!wasAnimating && animate_) {
        motion->linearVelocity = savedLinear_;
        motion->angularVelocity = savedAngular_;
    }
}

void GjkView::draw(const World& world, DebugDraw& draw) const { drawGjkOverlay(world, draw, mode(), overlayAnchor_); }

/// A fresh GjkView, its overlay above the bodies at `overlayAnchor`, at every load.
static SceneViewFactory gjkView(Vec3 overlayAnchor) {
    return [overlayAnchor] { return std::unique_ptr<SceneView>(std::make_unique<GjkView>(overlayAnchor)); };
}

}  // namespace

std::vector<Vec3> minkowskiPoints(const Body& a, const Body& b, SupportMode mode) {
    // Each shape as points: a polytope by its corners, a round shape by support points in
    // directions spread over the sphere (as many as keep the total within what buildConvexHull
    // takes). A - B is the hull of all their differences.
    std::vector<Vec3> pointsA = worldCorners(a);
    std::vector<Vec3> pointsB = worldCorners(b);
    auto sample = [&](const Body& body, int count) {
        const ConvexProxy proxy = makeProxy(body, mode);
        std::vector<Vec3> samples;
        const Real golden = kPi * (3 - std::sqrt(Real(5)));  // Fibonacci sphere of directions
        for (int i = 0; i < count; ++i) {
            const Real y = 1 - 2 * (Real(i) + Real(0.5)) / Real(count);
            const Real r = std::sqrt(std::max(Real(0), 1 - y * y));
            samples.push_back(proxy.support(Vec3(r * math::cos(golden * Real(i)), y, r * math::sin(golden * Real(i)))));
        }
        return samples;
    };
    if (pointsA.empty() && pointsB.empty()) {
        pointsA = sample(a, 11);
        pointsB = sample(b, 11);
    } else if (pointsA.empty()) {
        pointsA = sample(a, std::max(4, kMaxHullPoints / int(pointsB.size())));
    } else if (pointsB.empty()) {
        pointsB = sample(b, std::max(4, kMaxHullPoints / int(pointsA.size())));
    }
    std::vector<Vec3> points;
    for (const Vec3& onA : pointsA)
        for (const Vec3& onB : pointsB) points.push_back(onA - onB);
    return points;
}

// [ch02-overlay]
void drawGjkOverlay(const World& world, DebugDraw& draw, SupportMode mode, const Vec3& anchor) {
    if (world.bodies.size() < 2) return;
    const Body& a = world.bodies[0];
    const Body& b = world.bodies[1];
    const GjkResult result = gjkIntersect(makeProxy(a, mode), makeProxy(b, mode));
    const Color pairColor = result.intersect ? colors::kRed : colors::kGreen;
    drawBody(draw, a, pairColor, Fill::Wire);
    drawBody(draw, b, pairColor, Fill::Wire);

    // A - B around the anchor: its points, its hull, and the origin it may or may not hold.
    const std::vector<Vec3> points = minkowskiPoints(a, b, mode);
    for (const Vec3& point : points) draw.point(anchor + point, 4, colors::kGrey);
    try {
        draw.hull(Transform{anchor, Quat::Identity()}, buildConvexHull(points), pairColor, Fill::Wire);
    } catch (const HullError&) {
        // A flat difference (a zero-size shape) has no hull to draw; the points still show it.
    }
    const Real mark = Real(0.15);
    for (int axis = 0; axis < 3; ++axis)
        draw.line(anchor - mark * Vec3::Unit(axis), anchor + mark * Vec3::Unit(axis), colors::kWhite);
    draw.text(anchor + Vec3(0, -mark, 0), "origin", colors::kWhite);

    // The final simplex: its vertices and every edge between them.
    const Simplex& simplex = result.simplex;
    for (int i = 0; i < simplex.count; ++i) {
        draw.point(anchor + simplex.vertices[i].w, 8, colors::kYellow);
        for (int j = i + 1; j < simplex.count; ++j)
            draw.line(anchor + simplex.vertices[i].w, anchor + simplex.vertices[j].w, colors::kYellow);
    }
    draw.text(anchor + Vec3(0, Real(1.8), 0), describe(result), pairColor);
}
// [ch02-overlay]

void addChapter02Scenes(Registry& registry) {
    const char* const category = "GJK";
    registry.addScene({"gjk-two-boxes", 2, category, prose(R"(
        The plank's end sweeps through the cube: both turn red exactly while they overlap, and above them
        the origin (white cross) enters the Minkowski difference A - B, caught by a yellow tetrahedron.)"),
        buildGjkTwoBoxes, gjkView(Vec3(0, Real(4.5), 0))});
    registry.addScene({"gjk-sphere-diamond", 2, category, prose(R"(
        Each tip of the spinning diamond dips into the sphere and the pair turns red; above, A - B is the
        diamond grown by the sphere, and the label counts GJK's support points.)"),
        buildGjkSphereDiamond, gjkView(Vec3(0, Real(3), 0))});
}

}  // namespace stepwise
