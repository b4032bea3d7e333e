#include "03_epa/scenes.h"

#include "02_gjk/chapter.h"
#include "03_epa/narrowphase.h"
#include "app/panel.h"
#include "app/registry.h"
#include "world/contact_draw.h"
#include "world/debug_draw.h"

#include <cstdio>
#include <memory>
#include <string>

namespace stepwise {

namespace {

const Vec3 kPolytopeAnchor(Real(3), Real(1.5), 0);  // where the stepper draws A - B's origin
constexpr Real kPolytopeScale = Real(0.5);            // A - B is drawn at half size beside the bodies

/// A static A (drawn grey) and a dynamic B (drawn in its own colour) that turns in zero gravity:
/// chapter 3 has no solver, so B simply turns through A and the contact moves.
int addPairBody(World& world, const std::string& name, const Shape& shape, const Vec3& position, const Quat& rotation,
            const Vec3& spin) {
    BodyDef def;
    def.name = name;
    def.type = spin.isZero() ? BodyType::Static : BodyType::Dynamic;
    def.shape = shape;
    def.transform.position = position;
    def.transform.rotation = rotation;
    def.angularVelocity = spin;
    return addBody(world, def);
}

Quat tilt(Real x, Real y, Real z) {
    return (angleAxis(x, Vec3::UnitX()) * angleAxis(y, Vec3::UnitY()) *
            angleAxis(z, Vec3::UnitZ()))
        .normalized();
}

std::string describe(const char* format, double value) {
    char text[96];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

/// The stepper's view: how far EPA runs in the picture, and whether box b turns.
class EpaStepperView : public SceneView {
public:
    void draw(const World& world, DebugDraw& draw) const override {
        drawEpaStep(world, 0, 1, shownExpansions(), kPolytopeAnchor, draw);
    }
    bool hasPanel() const override { return true; }
    void panel(World& world, Panel& panel) override;

private:
    int shownExpansions() const { return converged_ ? -1 : expansions_; }
    int expansions_ = 0;
    bool converged_ = false;  // show the finished polytope instead of `expansions_`
    bool spin_ = true;
};

}  // namespace

World buildEpaStepper() {
    World world = emptyWorld("epa-step-by-step", Vec3::Zero());
    addPairBody(world, "a", Shape::box(Vec3(Real(0.8), Real(0.5), Real(0.6))), Vec3(0, 1, 0), tilt(0, Real(0.3), 0),
                 Vec3::Zero());
    addPairBody(world, "b", Shape::box(Vec3(Real(0.5), Real(0.4), Real(0.5))), Vec3(Real(0.7), Real(1.6), Real(0.2)),
                 tilt(Real(0.5), Real(0.2), Real(0.7)), Vec3(Real(0.1), Real(0.25), 0));
    return world;
}

World buildContactGallery() {
    World world = emptyWorld("epa-contact-gallery", Vec3::Zero());
    const Shape box = Shape::box(Vec3(Real(0.5), Real(0.35), Real(0.4)));
    const Shape sphere = Shape::sphere(Real(0.45));
    const Shape capsule = Shape::capsule(Real(0.25), Real(0.45));
    const Shape hull = Shape::convex({Vec3(0, Real(0.6), 0), Vec3(Real(0.5), Real(-0.3), Real(0.3)),
                                      Vec3(Real(-0.5), Real(-0.3), Real(0.3)), Vec3(0, Real(-0.3), Real(-0.55)),
                                      Vec3(0, Real(-0.1), Real(0.6))});
    // One pair per lane along x; B sits a little too close to A and turns, so the contact moves.
    const Shape lanes[6][2] = {{box, box}, {box, sphere}, {sphere, sphere}, {capsule, capsule}, {capsule, box}, {hull, box}};
    const char* names[6] = {"box-box", "box-sphere", "sphere-sphere", "capsule-capsule", "capsule-box", "hull-box"};
    for (int lane = 0; lane < 6; ++lane) {
        const Vec3 base(Real(2.2) * (lane - Real(2.5)), 1, 0);
        const std::string name = names[lane];
        addPairBody(world, name + "-a", lanes[lane][0], base, tilt(Real(0.2), Real(0.1) * lane, 0), Vec3::Zero());
        addPairBody(world, name + "-b", lanes[lane][1], base + Vec3(Real(0.15), Real(0.75), Real(0.1)),
                     tilt(Real(0.4), 0, Real(0.3)), Vec3(Real(0.2), Real(0.5), Real(0.1)));
    }
    return world;
}

std::optional<EpaResult> epaStoppedAfter(const World& world, int bodyA, int bodyB, int expansions) {
    const ConvexProxy a = makeProxy(world.bodies[bodyA]);
    const ConvexProxy b = makeProxy(world.bodies[bodyB]);
    const GjkResult gjk = gjkIntersect(a, b);
    if (!gjk.intersect) return std::nullopt;
    EpaSettings settings;
    settings.maxExpansions = expansions;
    settings.keepPolytope = true;
    return epaPenetration(a, b, gjk.simplex, settings);
}

// [ch03-demo-draw]
EpaResult drawEpaStep(const World& world, int bodyA, int bodyB, int expansions, const Vec3& polytopeAnchor,
                      DebugDraw& draw) {
    const std::optional<EpaResult> stopped = epaStoppedAfter(world, bodyA, bodyB, expansions);
    if (!stopped) {
        draw.text(polytopeAnchor, "GJK: separated, nothing for EPA to do", colors::kWhite);
        return EpaResult{};
    }
    const EpaResult& epa = *stopped;

    // The polytope lives in the space of A - B, around its origin; draw it beside the bodies.
    const auto place = [&](const Vec3& w) { return Vec3(polytopeAnchor + kPolytopeScale * w); };
    for (const EpaFace& face : epa.polytope.faces) {
        if (face.removed) continue;
        for (int i = 0; i < 3; ++i) {
            draw.line(place(epa.polytope.vertices[face.vertices[i]].w),
                      place(epa.polytope.vertices[face.vertices[(i + 1) % 3]].w), colors::kGrey);
        }
    }
    draw.triangle(place(epa.closestFace[0].w), place(epa.closestFace[1].w), place(epa.closestFace[2].w),
                  colors::kBlue);
    draw.point(polytopeAnchor, 8, colors::kWhite);
    draw.arrow(polytopeAnchor, place(epa.depth * epa.normal), colors::kYellow);
    draw.text(polytopeAnchor + Vec3(0, Real(-1.3), 0),
              "A - B after " + std::to_string(epa.iterations) + " expansions (" + toString(epa.exit) + ")" +
                  describe(", depth %.5f m", double(epa.depth)),
              colors::kWhite);

    // Back in the world: the two contact points and the normal from A to B.
    drawContact(draw, epa.pointA, epa.pointB, epa.normal);
    return epa;
}
// [ch03-demo-draw]

void EpaStepperView::panel(World& world, Panel& panel) {
    const int maxExpansions = EpaSettings{}.maxIterations;
    panel.sliderInt("EPA expansions", expansions_, 0, maxExpansions);
    if (panel.button("step")) expansions_ = std::min(expansions_ + 1, maxExpansions);
    if (panel.button("reset")) expansions_ = 0;
    panel.checkbox("run to convergence", converged_);
    if (panel.checkbox("turn box b", spin_))
        world.motionOf(1)->angularVelocity = spin_ ? Vec3(Real(0.1), Real(0.25), 0) : Vec3(Vec3::Zero());
    // What the picture shows, recomputed rather than remembered from the last draw.
    const EpaResult shown = epaStoppedAfter(world, 0, 1, shownExpansions()).value_or(EpaResult{});
    panel.text(std::string("EPA stopped: ") + toString(shown.exit) + " after " + std::to_string(shown.iterations) +
               " expansions");
    panel.text(describe("depth %.6f m", double(shown.depth)));
}

namespace {

// Labels each lane with the routine that found its contact and marks the contact.
void drawGallery(const World& world, DebugDraw& draw) {
    for (std::size_t i = 0; i + 1 < world.bodies.size(); i += 2) {
        const Body& a = world.bodies[i];
        const Body& b = world.bodies[i + 1];
        const ContactQuery query = collideShapes(a.shape, a.transform, b.shape, b.transform);
        const Vec3 label = a.transform.position + Vec3(0, Real(-1.1), 0);
        draw.text(label, std::string(query.routine) + (query.intersect ? describe(" %.3f m", double(query.depth)) : " apart"),
                  colors::kWhite);
        if (query.intersect) drawContact(draw, query.pointA, query.pointB, query.normal);
    }
}

}  // namespace

void addChapter03Scenes(Registry& registry) {
    const char* const category = "Contacts";
    registry.addScene({"epa-step-by-step", 3, category, prose(R"(
        Step EPA one expansion at a time: the blue closest face of the grey polytope (A - B, right, half
        size) closes in on the boundary; red cubes mark the contact points inside the overlap (Z:
        wireframe), the yellow arrow the normal.)"),
        buildEpaStepper, viewOfType<EpaStepperView>()});
    registry.addScene({"epa-contact-gallery", 3, category, prose(R"(
        Six shape pairs turning into each other; each label names the routine that found the contact (closed
        form or GJK + EPA), red cubes mark the points (Z: wireframe), yellow arrows the normals.)"),
        buildContactGallery, statelessView(drawGallery)});
}

}  // namespace stepwise
