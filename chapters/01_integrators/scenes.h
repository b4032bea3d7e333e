#pragma once
// Chapter 1's demo scenes. The builders are public so tests and benches use the very scenes
// the demo shows (one definition, three users).

#include "world/world.h"

namespace stepwise {

class Registry;

/// Three two-body spring chains hanging side by side, one per integrator (per-body override).
World buildIntegratorsSideBySide();

/// A box with three distinct half extents spun about its intermediate axis, without gravity:
/// the Dzhanibekov (tennis racket) flip.
World buildTHandle(GyroscopicMode gyroscopic = GyroscopicMode::Implicit);

/// Three balls launched alike under gravity, one per integrator, next to the exact parabola.
World buildProjectile();

/// Registers the scenes above with their observe line, draw hook and panel.
void addChapter01Scenes(Registry& registry);

}  // namespace stepwise
