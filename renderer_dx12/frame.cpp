#include "frame.h"

#include "targets.h"

#include <imgui.h>
#include <imgui_impl_dx12.h>

#include <algorithm>

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

}  // namespace stepwise::render
