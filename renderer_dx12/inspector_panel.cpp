#include "inspector_panel.h"

#include <imgui.h>

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

/// Euler angles in degrees, R = Rx(a) Ry(b) Rz(c) (Eigen's eulerAngles(0, 1, 2) convention).
void toEuler(const Quat& rotation, float degrees[3]) {
    const Vec3 angles = rotation.toRotationMatrix().eulerAngles(0, 1, 2);
    for (int i = 0; i < 3; ++i) degrees[i] = float(angles[i]) * kDegrees;
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

    bool changed = false;
    changed |= dragVec3("position (m)", draft.transform.position, 0.01f);
    float q[4] = {float(draft.transform.rotation.w()), float(draft.transform.rotation.x()), float(draft.transform.rotation.y()),
                  float(draft.transform.rotation.z())};
    if (ImGui::InputFloat4("rotation (w x y z)", q, "%.4f")) {
        draft.transform.rotation = Quat(Real(q[0]), Real(q[1]), Real(q[2]), Real(q[3]));
        changed = true;
    }
    if (ImGui::DragFloat3("rotation (deg, x y z)", inspector.eulerDegrees, 0.5f, 0.0f, 0.0f, "%.1f")) {
        draft.transform.rotation = fromEuler(inspector.eulerDegrees);
        changed = true;
    }
    inspector.eulerActive = ImGui::IsItemActive();
    if (moving) {
        changed |= dragVec3("velocity (m/s)", draft.linearVelocity, 0.01f);
        changed |= dragVec3("angular vel. (rad/s)", draft.angularVelocity, 0.01f);
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
        if (ImGui::InputFloat3("inertia diag (kg m2)", d, "%.4g")) {
            for (int i = 0; i < 3; ++i) draft.inertiaLocal(i, i) = Real(d[i]);
            changed = true;
        }
        const Mat3& I = draft.inertiaLocal;
        ImGui::TextDisabled("products: xy %.4g  xz %.4g  yz %.4g", double(I(0, 1)), double(I(0, 2)), double(I(1, 2)));
    } else if (shown.type == BodyType::Kinematic) {
        ImGui::TextDisabled("kinematic: moved by its velocity, no mass");
    }

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
