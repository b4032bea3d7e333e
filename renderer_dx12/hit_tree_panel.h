#pragma once
// The hit result tree as an ImGui tree: pairs, their manifold, its points (chapter 9's describe*
// lines). Clicking a node selects it and the scene highlights it; a contact clicked in the scene
// (state.revealSelection) opens the tree down to its node and scrolls to it.

#include "demo_state.h"

namespace stepwise::render {

void hitTreeSection(DemoState& state);

}  // namespace stepwise::render
