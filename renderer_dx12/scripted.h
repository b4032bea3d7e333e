#pragma once
// What an offscreen run can be told to do before its screenshot, so the render tests can show
// each debug view and check picking, selection and rewinding without a mouse:
//   --views contacts,normals,epa,...    exactly these views on (the rest off)
//   --select BODY                       select a body by name or index
//   --pick X,Y                          click at pixel (X, Y) once the camera is framed
//   --select-contact                    select the first point of the hit tree
//   --rewind K                          after the frames, rewind K frames
//   --open session,views,hits,...       open these sections of the debugger
//   --draw-every-frame                  draw every frame, so the performance monitor measures frames

#include "debug_panel.h"
#include "demo_state.h"

#include <string>

namespace stepwise::render {

/// The names --views takes, for its help text.
const char* viewListNames();

/// Turns on exactly the listed views (the rest off). Throws std::invalid_argument naming an
/// unknown view.
void applyViewList(const std::string& list, DemoState& state, ViewOptions& view);

/// Opens the listed debugger sections at the next frame. Throws std::invalid_argument on an
/// unknown section.
void openSections(const std::string& list, DebugTools& tools);

/// "X,Y" in pixels. Throws std::invalid_argument when it is not two numbers.
void parsePixel(const std::string& text, float& x, float& y);

/// A body by name, or by index when the text is a number; -1 when there is no such body.
int findBody(const World& world, const std::string& nameOrIndex);

}  // namespace stepwise::render
