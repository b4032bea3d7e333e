#pragma once
// A check of the narrowphase from outside it: a contact point is never deeper than its two shapes
// overlap. Each manifold's deepest point is compared with the pair's true overlap, found afresh by
// chapter 3's query (closed forms, or GJK and EPA) at the bodies' poses. A manifold kept from an
// earlier frame, a clipped face or a normal turned the wrong way shows up as depth the shapes do
// not have, and such depth pushes bodies apart that rest together (bench speed's depth column).

#include "world/world.h"

namespace stepwise {

/// Over the world's contacts between two convex shapes (compounds, meshes and height fields are
/// left out: their parts answer for them), the most a reported point depth exceeds the pair's true
/// overlap, m; 0 when none does.
Real deepestBeyondTrueOverlap(const World& world);

}  // namespace stepwise
