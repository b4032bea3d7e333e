#pragma once
// What a render test should find in a screenshot, written by the demo next to it (IMAGE.txt) and
// read by tests/render/check_png.cpp: where the ground and each body's centre land on screen and
// in which colour, the rectangles of the panel and the debugger, the screen rectangle of the box
// the camera was framed from, and, per enabled debug view, the colour expected at the projected
// places the physics says it draws (contact points red, normals yellow, the EPA face blue...).
// Everything is computed from the world and the camera, never from the image.

#include "camera.h"
#include "demo_state.h"

#include <string>

namespace stepwise::render {

/// `viewMarks`: write the debug views' marks. Only a run told which views to show asks for them:
/// it chose a scene and frame where they are in sight, while a default view may well have its
/// contacts inside the overlap it shows (chapter 3's boxes).
void writeExpectations(const std::string& path, const DemoState& state, const Camera& camera, const Aabb& framed,
                       bool impulsesShown, bool viewMarks, int width, int height);

}  // namespace stepwise::render
