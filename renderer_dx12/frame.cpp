#include "frame.h"

#include "targets.h"
#include "ui_shell.h"
#include "world/shape.h"

#include <imgui.h>
#include <imgui_impl_dx12.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace stepwise::render {

FrameConstants frameConstants(const Camera& camera, const ViewOptions& view, int width, int height) {
    FrameConstants constants = {};
    const Mat4f viewProjection = camera.viewProjection(static_cast<float>(width) / static_cast<float>(std::max(height, 1)));
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) constants.viewProjRows[row][col] = viewProjection(row, col);
    const Vec3f eye = camera.eye();
    const Vec3f light = Vec3f(0.35f, 0.85f, 0.40f).normalized();
    for (int i = 0; i < 3; ++i) {
        constants.cameraPosition[i] = eye[i];
        constants.lightDirection[i] = light[i];
    }
    constants.viewport[0] = static_cast<float>(width);
    constants.viewport[1] = static_cast<float>(height);
    constants.viewport[2] = view.lineWidth;
    constants.viewport[3] = camera.nearPlane;
    return constants;
}

void recordFrame(Device& device, SceneRenderer& renderer, const TargetView& target, const FrameConstants& constants,
                 const DrawList& list, ImDrawData* ui, OffscreenTarget* offscreen) {
    ID3D12GraphicsCommandList* commands = device.list();
    transition(commands, target.color, target.idleState, D3D12_RESOURCE_STATE_RENDER_TARGET);
    commands->ClearRenderTargetView(target.rtv, clearColor(), 0, nullptr);
    commands->ClearDepthStencilView(target.dsv, D3D12_CLEAR_FLAG_DEPTH, 1.0f, 0, 0, nullptr);
    commands->OMSetRenderTargets(1, &target.rtv, FALSE, &target.dsv);
    renderer.record(device, target, constants, list);
    if (ui) {
        ID3D12DescriptorHeap* heaps[] = {device.imguiHeap()};
        commands->SetDescriptorHeaps(1, heaps);
        ImGui_ImplDX12_RenderDrawData(ui, commands);
    }
    transition(commands, target.color, D3D12_RESOURCE_STATE_RENDER_TARGET, target.idleState);
    if (offscreen) offscreen->recordReadback(commands);
}

void initImGui(Device& device) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // every run starts with the same layout (and screenshots match)
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 4;
    // One pixel less between rows than the default: chapter 4's panel then fits a 720-pixel
    // image without a scroll bar.
    ImGui::GetStyle().ItemSpacing.y = 3;
    ImGui_ImplDX12_Init(device.device(), Device::kFramesInFlight, kColorFormat, device.imguiHeap(),
                        device.imguiHeap()->GetCPUDescriptorHandleForHeapStart(),
                        device.imguiHeap()->GetGPUDescriptorHandleForHeapStart());
}

void shutdownImGui() {
    ImGui_ImplDX12_Shutdown();
    ImGui::DestroyContext();
}

void writeExpectations(const std::string& path, const DemoState& state, const Camera& camera, int width, int height) {
    std::ofstream out(path);
    out << "# Written by the demo with its screenshot: kind name x y r g b minShade (see tests/render/check_png.cpp)\n";
    out << "size " << width << ' ' << height << '\n';
    float panel[4] = {0, 0, 0, 0};
    const bool hasPanel = shellRect(panel);
    if (hasPanel) out << "panel " << panel[0] << ' ' << panel[1] << ' ' << panel[2] << ' ' << panel[3] << '\n';
    auto inside = [&](float x, float y) {
        const bool onScreen = x >= 4 && y >= 4 && x < width - 4 && y < height - 4;
        const bool underPanel = hasPanel && x >= panel[0] - 4 && x <= panel[2] + 4 && y >= panel[1] - 4 && y <= panel[3] + 4;
        return onScreen && !underPanel;
    };
    auto emit = [&](const char* kind, const std::string& name, const Vec3& at, Color color, float minShade) {
        float x = 0, y = 0;
        if (!at.allFinite() || !camera.project(at.cast<float>(), float(width), float(height), x, y) || !inside(x, y)) return;
        std::string safe = name.empty() ? "-" : name;
        for (char& c : safe) if (c == ' ') c = '_';
        out << kind << ' ' << safe << ' ' << static_cast<int>(x) << ' ' << static_cast<int>(y) << ' '
            << static_cast<int>(std::lround(color.r * 255)) << ' ' << static_cast<int>(std::lround(color.g * 255)) << ' '
            << static_cast<int>(std::lround(color.b * 255)) << ' ' << minShade << '\n';
    };
    // Where the box the camera was framed from (the scene at frame 0, overlay included) lands:
    // the test wants all of it on screen and clear of the panel.
    const Aabb& framed = state.initialFraming().bounds;
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
    // Same colours as drawWorld (common/world/debug_draw.cpp).
    for (size_t i = 0; i < state.world.bodies.size(); ++i) {
        const Body& body = state.world.bodies[i];
        const Aabb box = computeAabb(body.shape, body.transform);
        if (body.type == BodyType::Static) {
            const Vec3 size = box.max - box.min;
            if (size.y() < Real(0.5) * std::max(size.x(), size.z())) {
                // Points spread over the top face of a ground-like static body: some are bare.
                for (Real fx : {Real(-0.6), Real(0), Real(0.6)})
                    for (Real fz : {Real(-0.6), Real(0), Real(0.6)}) {
                        const Vec3 top(box.center().x() + fx * box.extents().x(), box.max.y(),
                                       box.center().z() + fz * box.extents().z());
                        emit("ground", body.name, top, colors::kGrey, 0.55f);
                    }
            }
            continue;
        }
        const Color color = body.type == BodyType::Kinematic ? colors::kBlue : bodyColor(static_cast<int>(i));
        emit("body", body.name, box.center(), color, 0.25f);
    }
}

}  // namespace stepwise::render
