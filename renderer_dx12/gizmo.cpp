#include "gizmo.h"

#include "09_debug/body_edit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace stepwise::render {

namespace {

constexpr float kArmPixels = 90;      // arrow length on screen
constexpr float kRingPixels = 70;     // ring radius on screen
constexpr float kGrabPixels = 7;      // how close the cursor must be to a handle
constexpr int kRingSegments = 48;

const ImU32 kAxisColors[3] = {IM_COL32(230, 60, 60, 255), IM_COL32(80, 210, 90, 255), IM_COL32(70, 120, 245, 255)};
const ImU32 kActiveColor = IM_COL32(250, 220, 60, 255);

ImVec2 sub(ImVec2 a, ImVec2 b) { return ImVec2(a.x - b.x, a.y - b.y); }
float dot(ImVec2 a, ImVec2 b) { return a.x * b.x + a.y * b.y; }
float length(ImVec2 a) { return std::sqrt(dot(a, a)); }

float distanceToSegment(ImVec2 p, ImVec2 a, ImVec2 b) {
    const ImVec2 ab = sub(b, a), ap = sub(p, a);
    const float t = std::clamp(dot(ap, ab) / std::max(dot(ab, ab), 1e-6f), 0.0f, 1.0f);
    return length(sub(ap, ImVec2(t * ab.x, t * ab.y)));
}

struct Projector {
    const Camera& camera;
    float width, height;
    bool operator()(const Vec3f& world, ImVec2& screen) const {
        return camera.project(world, width, height, screen.x, screen.y);
    }
};

/// A ring of the rotate gizmo: its points on screen (empty when any is behind the eye) and in
/// the world.
struct Ring {
    std::vector<ImVec2> screen;
    std::vector<Vec3f> world;
};

Ring ringOf(const Projector& project, const Vec3f& center, int axis, float radius) {
    Ring ring;
    const Vec3f u = Vec3f::Unit((axis + 1) % 3), v = Vec3f::Unit((axis + 2) % 3);
    for (int i = 0; i <= kRingSegments; ++i) {
        const float angle = 2.0f * float(kPi) * float(i) / float(kRingSegments);
        const Vec3f at = center + radius * (std::cos(angle) * u + std::sin(angle) * v);
        ImVec2 screen;
        if (!project(at, screen)) return Ring();
        ring.world.push_back(at);
        ring.screen.push_back(screen);
    }
    return ring;
}

/// Distance from the cursor to the ring on screen, and the ring point nearest it.
float ringDistance(const Ring& ring, ImVec2 mouse, Vec3f& nearest) {
    float best = 1e30f;
    for (std::size_t i = 0; i + 1 < ring.screen.size(); ++i) {
        const float d = distanceToSegment(mouse, ring.screen[i], ring.screen[i + 1]);
        if (d < best) best = d, nearest = ring.world[i];
    }
    return best;
}

void applyPose(DemoState& state, int body, const Transform& pose) {
    try {
        state.edit(moveEdit(state.world(), body, pose));
    } catch (const std::invalid_argument&) {
        // A pose the edit refuses (a drag to infinity) is skipped; the next mouse move tries again.
    }
}

}  // namespace

bool updateGizmo(Gizmo& gizmo, DemoState& state, const Camera& camera, float width, float height) {
    const int body = state.selectedBody;
    if (body < 0 || body >= static_cast<int>(state.world().bodies.size())) {
        gizmo.axis = -1;
        return false;
    }
    const ImGuiIO& io = ImGui::GetIO();
    const Projector project{camera, width, height};
    const Vec3f center = state.world().bodies[static_cast<std::size_t>(body)].transform.position.cast<float>();
    ImVec2 centerScreen;
    if (!project(center, centerScreen)) return gizmo.axis >= 0;
    const float metresPerPixel = camera.metresPerPixel(center, height);
    const bool mouseFree = !io.WantCaptureMouse || gizmo.axis >= 0;

    // Hover: the handle nearest the cursor within kGrabPixels.
    int hovered = -1;
    float hoveredDistance = kGrabPixels;
    ImVec2 ends[3];
    Ring rings[3];
    Vec3f grabPoint[3];
    for (int axis = 0; axis < 3; ++axis) {
        if (gizmo.mode == Gizmo::Mode::Translate) {
            if (!project(center + kArmPixels * metresPerPixel * Vec3f::Unit(axis), ends[axis])) continue;
            const float d = distanceToSegment(io.MousePos, centerScreen, ends[axis]);
            if (mouseFree && d < hoveredDistance) hoveredDistance = d, hovered = axis;
        } else {
            rings[axis] = ringOf(project, center, axis, kRingPixels * metresPerPixel);
            if (rings[axis].screen.empty()) continue;
            const float d = ringDistance(rings[axis], io.MousePos, grabPoint[axis]);
            if (mouseFree && d < hoveredDistance) hoveredDistance = d, hovered = axis;
        }
    }

    // Grab: how a pixel along the handle's screen direction maps to the world.
    if (gizmo.axis < 0 && hovered >= 0 && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        ImVec2 along;
        if (gizmo.mode == Gizmo::Mode::Translate) {
            along = sub(ends[hovered], centerScreen);
            gizmo.pixelsPerMetre = length(along) / (kArmPixels * metresPerPixel);
        } else {
            // Turning by a small angle moves the grabbed ring point along the ring's tangent.
            const Vec3f radial = grabPoint[hovered] - center;
            const Vec3f tangent = Vec3f::Unit(hovered).cross(radial).normalized();
            const float step = 0.1f * radial.norm();
            ImVec2 grabbed, ahead;
            if (project(grabPoint[hovered], grabbed) && project(grabPoint[hovered] + step * tangent, ahead)) {
                along = sub(ahead, grabbed);
                gizmo.pixelsPerMetre = length(along) / step;
            }
            gizmo.ringRadius = radial.norm();
        }
        // An arrow pointing at the eye (or a ring seen edge-on at the grab point) has no screen
        // direction to drag along: it cannot be grabbed from this view.
        if (length(along) > 3.0f) {
            gizmo.axis = hovered;
            gizmo.body = body;
            gizmo.grabMouse = io.MousePos;
            gizmo.grabPose = state.world().bodies[static_cast<std::size_t>(body)].transform;
            gizmo.screenDirection = ImVec2(along.x / length(along), along.y / length(along));
        }
    }

    // Drag: the mouse's travel along the handle's screen direction, turned into metres.
    bool owned = hovered >= 0;
    if (gizmo.axis >= 0) {
        owned = true;
        const float travel = dot(sub(io.MousePos, gizmo.grabMouse), gizmo.screenDirection) / std::max(gizmo.pixelsPerMetre, 1e-3f);
        Transform next = gizmo.grabPose;
        if (gizmo.mode == Gizmo::Mode::Translate) {
            next.position += static_cast<Real>(travel) * Vec3::Unit(gizmo.axis);
        } else {
            const Real angle = static_cast<Real>(travel / std::max(gizmo.ringRadius, 1e-6f));
            next.rotation = (Quat(Eigen::AngleAxis<Real>(angle, Vec3::Unit(gizmo.axis))) * gizmo.grabPose.rotation).normalized();
        }
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f) || ImGui::IsMouseReleased(ImGuiMouseButton_Left))
            applyPose(state, gizmo.body, next);
        if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) gizmo.axis = -1;
    }

    // Draw: the active or hovered handle in yellow, thicker.
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    for (int axis = 0; axis < 3; ++axis) {
        const bool lit = axis == gizmo.axis || (gizmo.axis < 0 && axis == hovered);
        const ImU32 color = lit ? kActiveColor : kAxisColors[axis];
        const float thickness = lit ? 4.0f : 2.5f;
        if (gizmo.mode == Gizmo::Mode::Translate) {
            const ImVec2 shaft = sub(ends[axis], centerScreen);
            const float shaftLength = length(shaft);
            if (shaftLength < 1.0f) continue;
            draw->AddLine(centerScreen, ends[axis], color, thickness);
            // An arrow head 12 px long, 5 px either side of the shaft.
            const ImVec2 unit(shaft.x / shaftLength, shaft.y / shaftLength), normal(-unit.y, unit.x);
            const ImVec2 base(ends[axis].x - 12 * unit.x, ends[axis].y - 12 * unit.y);
            draw->AddTriangleFilled(ends[axis], ImVec2(base.x + 5 * normal.x, base.y + 5 * normal.y),
                                    ImVec2(base.x - 5 * normal.x, base.y - 5 * normal.y), color);
        } else if (!rings[axis].screen.empty()) {
            draw->AddPolyline(rings[axis].screen.data(), static_cast<int>(rings[axis].screen.size()), color, 0, thickness);
        }
    }
    draw->AddCircleFilled(centerScreen, 3.5f, IM_COL32(255, 255, 255, 255));
    return owned;
}

}  // namespace stepwise::render
