#pragma once
// One frame on the GPU: clear, the 3D scene, the ImGui shell, and (offscreen) the readback.

#include "camera.h"
#include "demo_state.h"
#include "scene_renderer.h"

struct ImDrawData;

namespace stepwise::render {

/// Per-frame constants from the camera and view options for a target of the given size.
FrameConstants frameConstants(const Camera& camera, const ViewOptions& view, int width, int height);

/// Records a whole frame into the device's open command list. `offscreen` also records the
/// copy into its readback buffer.
void recordFrame(Device& device, SceneRenderer& renderer, const TargetView& target, const FrameConstants& constants,
                 const DrawList& list, ImDrawData* ui, class OffscreenTarget* offscreen);

/// Dear ImGui set-up shared by both modes: no imgui.ini, dark style, DX12 backend.
void initImGui(Device& device);
void shutdownImGui();

}  // namespace stepwise::render
