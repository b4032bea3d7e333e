#pragma once
// The move and turn handles on the selected body: three axis arrows (translate) or three rings
// (rotate), drawn in screen space over the scene so the body never hides them. Dragging a handle
// moves the body along the world axis, or turns it about the axis, through DebugSession::edit
// with moveEdit, which also stops the body: a velocity kept from before the drag would fling it.

#include "camera.h"
#include "demo_state.h"

#include <imgui.h>

namespace stepwise::render {

struct Gizmo {
    enum class Mode { Translate, Rotate };
    Mode mode = Mode::Translate;

    // The drag in progress (axis -1: none): where it began, the body's pose then, and how a
    // pixel of mouse motion along `screenDirection` maps to metres (translate) or to metres of arc
    // on the ring (rotate).
    int axis = -1;
    int body = -1;
    ImVec2 grabMouse;
    Transform grabPose;
    ImVec2 screenDirection;
    float pixelsPerMetre = 1;
    float ringRadius = 1;   // m
};

/// Draws the gizmo of state.selectedBody and handles its drag. True while it owns the left mouse
/// button (a handle under the cursor, or a drag in progress or ending), so a click on a handle
/// does not also pick in the scene.
bool updateGizmo(Gizmo& gizmo, DemoState& state, const Camera& camera, float width, float height);

}  // namespace stepwise::render
