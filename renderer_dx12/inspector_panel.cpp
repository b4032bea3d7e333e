#include "inspector_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stepwise::render {

namespace {

constexpr float kDegrees = 180.0f / 3.14159265358979f;

/// Float widgets over Real fields (Real may be double): edit a float copy, write back on change.
bool dragVec3(const char* label, Vec3& value, float speed, const char* format = "%.3f") {
    float v[3] = {float(value.x()), float(value.y()), float(value.z())};
    if (!ImGui::DragFloat3(label, v, speed, 0.0f, 0.0f, format)) return false;
    value = Vec3(Real(v[0]), Real(v[1]), Real(v[2]));
    return true;
}

/// Euler angles in degrees, R = Rx(a) Ry(b) Rz(c), with a and c in [-180, 180] and b in
/// [-90, 90]: from R's first row and last column (R02 = sin b, R12 = -sin a cos b,
/// R22 = cos a cos b, R01 = -cos b sin c, R00 = cos b cos c). Eigen's eulerAngles() picks
/// a in [0, 180] instead, which shows a 45 degree turn about z as (180, 180, -135).
void toEuler(const Quat& rotation, float degrees[3]) {
    const Mat3 r = rotation.toRotationMatrix();
    degrees[0] = float(std::atan2(-r(1, 2), r(2, 2))) * kDegrees;
    degrees[1] = float(std::asin(std::clamp(r(0, 2), Real(-1), Real(1)))) * kDegrees;
    degrees[2] = float(std::atan2(-r(0, 1), r(0, 0))) * kDegrees;
}

Quat fromEuler(const float degrees[3]) {
    const auto about = [&](int axis) { return Eigen::AngleAxis<Real>(Real(degrees[axis] / kDegrees), Vec3::Unit(axis)); };
    return Quat(about(0) * about(1) * about(2));
}

}  // namespace

void inspectorSection(Inspector& inspector, DemoState& state) {
    World& world = state.world();
    const int body = state.selectedBody;
    if (body < 0 || body >= static_cast<int>(world.bodies.size())) {
        ImGui::TextDisabled("click a body in the scene to inspect it");
        inspector.body = -1;
        inspector.pending = false;
        return;
    }
    // A new selection, or no refused change waiting: the fields show the body as it is now.
    if (inspector.body != body || !inspector.pending) {
        inspector.body = body;
        inspector.pending = false;
        inspector.problem.clear();
        inspector.draft = currentState(world, body);
    }
    BodyEdit& draft = inspector.draft;
    if (!inspector.eulerActive) toEuler(draft.transform.rotation, inspector.eulerDegrees);

    const Body& shown = world.bodies[static_cast<std::size_t>(body)];
    ImGui::Text("#%d '%s'  %s", body, shown.name.c_str(), toString(shown.type));
    ImGui::SameLine();
    if (ImGui::SmallButton("deselect")) {
        state.selectedBody = -1;
        return;
    }
    const bool dynamic = shown.type == BodyType::Dynamic;
    const bool moving = shown.type != BodyType::Static;

    // Narrow fields, so the labels (with their units) fit in the debugger's width.
    ImGui::PushItemWidth(190);
    bool changed = false;
    changed |= dragVec3("position (m)", draft.transform.position, 0.01f);
    float q[4] = {float(draft.transform.rotation.w()), float(draft.transform.rotation.x()), float(draft.transform.rotation.y()),
                  float(draft.transform.rotation.z())};
    if (ImGui::InputFloat4("rotation wxyz", q, "%.3f")) {
        draft.transform.rotation = Quat(Real(q[0]), Real(q[1]), Real(q[2]), Real(q[3]));
        changed = true;
    }
    if (ImGui::DragFloat3("rotation xyz (deg)", inspector.eulerDegrees, 0.5f, 0.0f, 0.0f, "%.1f")) {
        draft.transform.rotation = fromEuler(inspector.eulerDegrees);
        changed = true;
    }
    inspector.eulerActive = ImGui::IsItemActive();
    if (moving) {
        changed |= dragVec3("velocity (m/s)", draft.linearVelocity, 0.01f);
        changed |= dragVec3("ang. vel. (rad/s)", draft.angularVelocity, 0.01f);
    }
    if (dynamic) {
        float mass = float(draft.mass);
        if (ImGui::InputFloat("mass (kg)", &mass, 0.0f, 0.0f, "%.4g")) {
            draft.mass = Real(mass);
            changed = true;
        }
        // The principal moments are edited; the products of inertia (zero for a box in its own
        // axes, not for a hull) are shown so a reader can see the matrix is not always diagonal.
        Vec3 diagonal = draft.inertiaLocal.diagonal();
        float d[3] = {float(diagonal.x()), float(diagonal.y()), float(diagonal.z())};
        if (ImGui::InputFloat3("inertia (kg m2)", d, "%.4g")) {
            for (int i = 0; i < 3; ++i) draft.inertiaLocal(i, i) = Real(d[i]);
            changed = true;
        }
        const Mat3& I = draft.inertiaLocal;
        ImGui::TextDisabled("products: xy %.2g  xz %.2g  yz %.2g", double(I(0, 1)), double(I(0, 2)), double(I(1, 2)));
    } else if (shown.type == BodyType::Kinematic) {
        ImGui::TextDisabled("kinematic: moved by its velocity, no mass");
    }
    ImGui::PopItemWidth();

    if (changed) {
        inspector.problem = validateEdit(world, draft);
        inspector.pending = !inspector.problem.empty();
        if (!inspector.pending) {
            try {
                state.edit(draft);
            } catch (const std::invalid_argument& error) {
                inspector.problem = error.what();
                inspector.pending = true;
            }
        }
    }
    if (inspector.pending) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", inspector.problem.c_str());
        ImGui::PopStyleColor();
        if (ImGui::Button("Revert")) inspector.pending = false;
    }
    ImGui::TextDisabled("edits this run: %d%s", static_cast<int>(state.session().edits().size()),
                        state.session().rewound() ? "  (rewound: edits are speculative)" : "");
}

}  // namespace stepwise::render
