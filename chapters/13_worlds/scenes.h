#pragma once
// Chapter 13's scenes and the builders its tests and bench share: a table and a chair as compounds,
// a floor of triangles, a height-field terrain, and the piles that fall on them.

#include "app/registry.h"
#include "world/world.h"

namespace stepwise {

/// A table: a top of `width` x `depth` x `thickness` on four square legs of `leg` x `leg` at its
/// corners, `height` tall overall, the body's origin on the floor under the top's centre.
Shape tableShape(Real width, Real depth, Real height, Real thickness, Real leg);

/// A chair: a seat on four legs and a back, the body's origin on the floor under the seat.
Shape chairShape();

/// A flat floor at y = 0 made of `tiles` x `tiles` squares of `size` m, two triangles each,
/// starting at the origin and running along +x and +z.
Shape tiledFloor(int tiles, Real size);

/// The same floor as a height field of (tiles + 1) x (tiles + 1) heights, all zero.
Shape flatHeightField(int tiles, Real size);

/// Rolling hills: a height field of `cells` x `cells` cells of `size` m, heights from sums of
/// sines (amplitude `amplitude` m), centred on the origin.
World buildTerrain(int cells, Real size, Real amplitude);

/// Cylinders standing, stacked and one rolling on its side, a table and a chair, on a floor.
World buildCylinderScene();

/// Two frictionless boxes sliding at 5 m/s over 30 m of 1 m tiles: one on a mesh floor, one on a
/// height field beside it (the seam scene; Settings::activeEdges false shows the bump).
World buildSeamScene();

/// A mixed pile of `bodies` boxes, spheres, capsules, cylinders and tables dropped onto hills.
World buildTerrainPile(int bodies, unsigned seed = 13);

void addChapter13Scenes(Registry& registry);

}  // namespace stepwise
