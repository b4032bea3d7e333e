#pragma once
// The chapter's draw hook: every contact point with the impulse the solver gave it, as arrows.

#include "world/debug_draw.h"
#include "world/world.h"

namespace stepwise {

/// Draws, for each point in World::contacts, a dot at the contact, a yellow arrow for the normal
/// impulse and an orange one for the friction impulse. Impulses are shown as the mean force over
/// the last substep (impulse / dt), scaled by `metresPerNewton`.
void drawContactImpulses(const World& world, DebugDraw& draw, Real metresPerNewton = Real(0.05));

}  // namespace stepwise
