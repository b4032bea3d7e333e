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

/// Writes what a test should find in a screenshot (tests/render/check_png.cpp reads it):
/// where the ground and each body's centre land on screen and in which colour, the rectangle
/// of the shell's panel, and the screen rectangle of the box the camera was framed from.
void writeExpectations(const std::string& path, const DemoState& state, const Camera& camera, int width, int height);

}  // namespace stepwise::render
