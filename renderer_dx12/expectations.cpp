#include "expectations.h"

#include "08_joints/joint_view.h"
#include "debug_panel.h"
#include "picking.h"
#include "ui_shell.h"
#include "world/contact_draw.h"
#include "world/shape.h"

#include <algorithm>
#include <cmath>
#include <fstream>

namespace stepwise::render {

namespace {

// Lit surfaces (boxes, triangles) darken to about 0.3 of their colour on the side away from the
// light; lines and points are drawn flat.
constexpr float kLitShade = 0.3f;
constexpr float kFlatShade = 0.85f;

class ExpectationWriter {
public:
    ExpectationWriter(const std::string& path, const Camera& camera, int width, int height)
        : out_(path), camera_(camera), width_(width), height_(height) {}

    std::ofstream& out() { return out_; }
    void setCovered(const float* panel, const float* debugger) {
        if (panel) std::copy(panel, panel + 4, panel_), hasPanel_ = true;
        if (debugger) std::copy(debugger, debugger + 4, debugger_), hasDebugger_ = true;
    }
    /// Where a world point lands, if on screen and not under the shell's windows.
    bool place(const Vec3& at, float& x, float& y) const {
        if (!at.allFinite() || !camera_.project(at.cast<float>(), float(width_), float(height_), x, y)) return false;
        const auto under = [&](const float* r) { return x >= r[0] - 4 && x <= r[2] + 4 && y >= r[1] - 4 && y <= r[3] + 4; };
        const bool onScreen = x >= 4 && y >= 4 && x < width_ - 4 && y < height_ - 4;
        return onScreen && !(hasPanel_ && under(panel_)) && !(hasDebugger_ && under(debugger_));
    }
    /// "KIND NAME x y r g b minShade": the colour (times a shade in [minShade, 1.15]) must show
    /// within a few pixels of (x, y). `kind` is body, ground, or "mark GROUP" for a debug view.
    void emit(const std::string& kind, const std::string& name, const Vec3& at, Color color, float minShade) {
        float x = 0, y = 0;
        if (!place(at, x, y)) return;
        std::string safe = name.empty() ? "-" : name;
        for (char& c : safe)
            if (c == ' ') c = '_';
        out_ << kind << ' ' << safe << ' ' << static_cast<int>(x) << ' ' << static_cast<int>(y) << ' '
             << static_cast<int>(std::lround(color.r * 255)) << ' ' << static_cast<int>(std::lround(color.g * 255)) << ' '
             << static_cast<int>(std::lround(color.b * 255)) << ' ' << minShade << '\n';
    }

private:
    std::ofstream out_;
    const Camera& camera_;
    int width_, height_;
    float panel_[4] = {0, 0, 0, 0}, debugger_[4] = {0, 0, 0, 0};
    bool hasPanel_ = false, hasDebugger_ = false;
};

Vec3 centroid(const Vec3& a, const Vec3& b, const Vec3& c) { return (a + b + c) / Real(3); }

/// The eight corners of a box shape at its pose.
std::vector<Vec3> boxCorners(const Body& body) {
    std::vector<Vec3> corners;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3& h = body.shape.halfExtents;
        corners.push_back(body.transform.apply(Vec3((corner & 1) ? h.x() : -h.x(), (corner & 2) ? h.y() : -h.y(), (corner & 4) ? h.z() : -h.z())));
    }
    return corners;
}

/// The bodies drawDebugViews draws as wireframes (no colour at their centres): the selected body,
/// the bodies it touches, and the selected contact's pair.
std::vector<char> wireBodies(const DemoState& state) {
    const World& world = state.world();
    if (!state.views.wireframeSelection) return std::vector<char>(world.bodies.size(), 0);
    return wireframeBodies(world, state.selectedBody, state.hitTree(), state.hitSelection());
}

void bodyExpectations(ExpectationWriter& writer, const DemoState& state) {
    // Same colours as drawDebugViews' colliders (and drawWorld).
    const World& world = state.world();
    const std::vector<char> wire = wireBodies(state);
    for (size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        if (wire[i]) continue;
        // A compound's box is mostly air (a table's, under its top): its largest child's instead.
        Aabb box = computeAabb(body.shape, body.transform);
        if (body.shape.type == ShapeType::Compound) {
            Real largest = -1;
            for (const CompoundChild& child : body.shape.compound->children)
                if (shapeVolume(child.shape) > largest) {
                    largest = shapeVolume(child.shape);
                    box = computeAabb(child.shape, compose(body.transform, child.transform));
                }
        }
        // Terrain's box top is air over every hollow: no points are expected on it.
        if (body.type == BodyType::Static && !canMove(body.shape)) continue;
        if (body.type == BodyType::Static) {
            const Vec3 size = box.max - box.min;
            if (size.y() < Real(0.5) * std::max(size.x(), size.z())) {
                // Points spread over the top face of a ground-like static body: some are bare.
                for (Real fx : {Real(-0.6), Real(0), Real(0.6)})
                    for (Real fz : {Real(-0.6), Real(0), Real(0.6)}) {
                        const Vec3 top(box.center().x() + fx * box.extents().x(), box.max.y(), box.center().z() + fz * box.extents().z());
                        writer.emit("ground", body.name, top, colors::kGrey, 0.55f);
                    }
            }
            continue;
        }
        writer.emit("body", body.name, box.center(), bodyTypeColor(world, static_cast<int>(i)), 0.25f);
    }
}

void viewExpectations(ExpectationWriter& writer, const DemoState& state, bool impulsesShown) {
    const World& world = state.world();
    const DebugViews& views = state.views;
    const HitTree& tree = state.hitTree();
    // drawContacts' markers sit on both surfaces; its normals are 0.6 m arrows from B's point.
    const Real normalLength = ContactDrawOptions().normalLength;
    for (size_t p = 0; p < tree.pairs.size(); ++p)
        for (const HitManifold& manifold : tree.pairs[p].manifolds)
            for (size_t i = 0; i < manifold.points.size(); ++i) {
                const HitPoint& point = manifold.points[i];
                const std::string name = "pair" + std::to_string(p) + "-point" + std::to_string(i);
                if (views.contactPoints) {
                    writer.emit("mark contact", name + "-A", point.pointA, colors::kRed, kLitShade);
                    writer.emit("mark contact", name + "-B", point.pointB, colors::kRed, kLitShade);
                }
                if (views.contactNormals && !impulsesShown)
                    for (Real along : {Real(0.25), Real(0.5), Real(0.75)})
                        writer.emit("mark normal", name, point.pointB + along * normalLength * manifold.normal, colors::kYellow,
                                    kFlatShade);
            }
    if (const HitPoint* point = selectedPoint(tree, state.hitSelection())) {
        // The highlight's white arrow (0.8 m along the normal from B's point), not its white cubes:
        // a lit white face is as grey as the ground, a flat white line is not.
        const HitSelection& selection = state.hitSelection();
        const Vec3& normal = tree.pairs[static_cast<size_t>(selection.pair)].manifolds[static_cast<size_t>(selection.manifold)].normal;
        for (Real along : {Real(0.2), Real(0.4), Real(0.6)})
            writer.emit("mark selected-contact", "arrow", point->pointB + along * normal, colors::kWhite, kFlatShade);
    }
    // Wireframe boxes meet at their corners: the selected body's in white, the bodies of its
    // pairs (or of the selected contact's) in their own colours. Static ones are left out: a
    // ground's corners are far off screen.
    const int selected = state.selectedBody;
    const std::vector<char> wire = wireBodies(state);
    for (size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        if (!wire[i] || body.shape.type != ShapeType::Box || body.type == BodyType::Static) continue;
        const Color color = static_cast<int>(i) == selected ? colors::kWhite : bodyTypeColor(world, static_cast<int>(i));
        for (const Vec3& corner : boxCorners(body)) writer.emit("mark selection", body.name, corner, color, kFlatShade);
    }
    if (views.bounds)
        for (const Body& body : world.bodies) {
            if (body.type == BodyType::Static) continue;
            const Aabb box = computeAabb(body.shape, body.transform);
            for (int corner = 0; corner < 8; ++corner)
                writer.emit("mark bounds", body.name,
                            Vec3((corner & 1) ? box.max.x() : box.min.x(), (corner & 2) ? box.max.y() : box.min.y(),
                                 (corner & 4) ? box.max.z() : box.min.z()),
                            colors::kCyan, kFlatShade);
        }
    if (views.joints) {
        // Chapter 8's joint drawing, recorded: its lines must show in their own colours.
        for (const JointDesc& joint : world.joints) {
            RecordingDraw recorded;
            drawJoint(recorded, world, joint);
            for (const RecordingDraw::Command& command : recorded.commands())
                if (command.kind == RecordingDraw::Kind::Line || command.kind == RecordingDraw::Kind::Arrow)
                    writer.emit("mark joint", "-", Real(0.5) * (command.a + command.b), command.color, kFlatShade);
        }
    }
    // The chapters' own views, recorded: their lines must show in their colours.
    for (const DemoState::OverlayView& overlay : state.chapterViews) {
        if (!overlay.on || !overlay.draw) continue;
        RecordingDraw recorded;
        overlay.draw(recorded, world, overlay.level);
        for (const RecordingDraw::Command& command : recorded.commands())
            if (command.kind == RecordingDraw::Kind::Line)
                writer.emit("mark " + overlay.overlay->name, "-", Real(0.5) * (command.a + command.b), command.color, kFlatShade);
    }
    if (!views.epaFace && !views.gjkSimplex && !views.minkowski) return;
    const BodyPair pair = chosenPair(world, tree, state.hitSelection(), selected);
    const PairDiagnosis diagnosis = diagnosePair(world, pair.bodyA, pair.bodyB);
    if (diagnosis.bodyA < 0) return;
    const SupportPoint* face = diagnosis.epaFace;
    const Vec3 anchor = minkowskiAnchor(world, diagnosis);
    if (views.epaFace && diagnosis.hasEpaFace) {
        writer.emit("mark epa", "on-A", centroid(face[0].onA, face[1].onA, face[2].onA), colors::kBlue, kLitShade);
        writer.emit("mark epa", "on-B", centroid(face[0].onB, face[1].onB, face[2].onB), colors::kBlue, kLitShade);
        if (views.minkowski)
            writer.emit("mark epa", "in-A-B", anchor + centroid(face[0].w, face[1].w, face[2].w), colors::kBlue, kLitShade);
    }
    if (views.gjkSimplex)
        for (int i = 0; i < diagnosis.simplex.count; ++i)
            writer.emit("mark simplex", "w" + std::to_string(i), anchor + diagnosis.simplex.vertices[i].w, colors::kMagenta, kFlatShade);
    if (views.minkowski) {
        // The hull is drawn through the extreme points; a few of the samples are its corners.
        const Color hull = diagnosis.overlapping ? colors::kRed : colors::kGreen;
        for (const Vec3& point : diagnosis.minkowskiPoints) writer.emit("mark minkowski", "-", anchor + point, hull, kFlatShade);
    }
}

/// Dynamic bodies a click at their centre's pixel picks: what the scripted pick test clicks.
void pickableBodies(ExpectationWriter& writer, const DemoState& state, const Camera& camera, int width, int height) {
    const World& world = state.world();
    for (size_t i = 0; i < world.bodies.size(); ++i) {
        const Body& body = world.bodies[i];
        if (body.type != BodyType::Dynamic) continue;
        float x = 0, y = 0;
        if (!writer.place(computeAabb(body.shape, body.transform).center(), x, y)) continue;
        const float px = std::floor(x) + 0.5f, py = std::floor(y) + 0.5f;
        if (pickBody(world, cursorRay(camera, px, py, float(width), float(height))) != static_cast<int>(i)) continue;
        std::string safe = body.name.empty() ? "-" : body.name;
        for (char& c : safe)
            if (c == ' ') c = '_';
        writer.out() << "pickable " << i << ' ' << safe << ' ' << static_cast<int>(x) << ' ' << static_cast<int>(y) << '\n';
    }
}

}  // namespace

void writeExpectations(const std::string& path, const DemoState& state, const Camera& camera, const Aabb& framed,
                       bool impulsesShown, bool viewMarks, int width, int height) {
    ExpectationWriter writer(path, camera, width, height);
    std::ofstream& out = writer.out();
    out << "# Written by the demo with its screenshot: kind name x y r g b minShade (see tests/render/check_png.cpp)\n";
    out << "size " << width << ' ' << height << '\n';
    float panel[4] = {0, 0, 0, 0}, debugger[4] = {0, 0, 0, 0};
    const bool hasPanel = shellRect(panel), hasDebugger = debuggerRect(debugger);
    if (hasPanel) out << "panel " << panel[0] << ' ' << panel[1] << ' ' << panel[2] << ' ' << panel[3] << '\n';
    if (hasDebugger) out << "debugger " << debugger[0] << ' ' << debugger[1] << ' ' << debugger[2] << ' ' << debugger[3] << '\n';
    writer.setCovered(hasPanel ? panel : nullptr, hasDebugger ? debugger : nullptr);
    // Where the box the camera was framed from (bodies and overlays) lands:
    // the test wants all of it on screen and clear of the panel and the debugger.
    if ((framed.min.array() <= framed.max.array()).all()) {
        float x0 = float(width), y0 = float(height), x1 = 0, y1 = 0;
        bool behind = false;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 at((corner & 1) ? framed.max.x() : framed.min.x(), (corner & 2) ? framed.max.y() : framed.min.y(),
                          (corner & 4) ? framed.max.z() : framed.min.z());
            float x = 0, y = 0;
            if (!camera.project(at.cast<float>(), float(width), float(height), x, y)) behind = true;
            x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
        }
        if (behind) out << "framed behind\n";
        else out << "framed " << x0 << ' ' << y0 << ' ' << x1 << ' ' << y1 << '\n';
    }
    if (state.views.colliders) bodyExpectations(writer, state);
    if (viewMarks) viewExpectations(writer, state, impulsesShown);
    pickableBodies(writer, state, camera, width, height);
}

}  // namespace stepwise::render
