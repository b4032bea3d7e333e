#pragma once
// Chapter 13's scenes and the builders its tests and bench share: a table and a chair as compounds,
// a floor of triangles, a height-field terrain, and the piles that fall on them.

#include "app/registry.h"
#include "world/world.h"

#include <functional>

namespace stepwise {

/// A table: a top of `width` x `depth` x `thickness` on four square legs of `leg` x `leg` at its
/// corners, `height` tall overall, the body's origin on the floor under the top's centre.
Shape tableShape(Real width, Real depth, Real height, Real thickness, Real leg);

/// A chair: a seat on four legs and a back, the body's origin on the floor under the seat.
Shape chairShape();

/// A surface of `cells` x `cells` squares of `size` m as a triangle mesh: the grid point (r, c) at
/// x = c * size, z = r * size and y = height(x, z), each square split into two triangles along the
/// diagonal from (r, c) to (r + 1, c + 1), as a height field's cells are (height_field_cells.h),
/// fronts up.
Shape gridMesh(int cells, Real size, const std::function<Real(Real x, Real z)>& height);

/// A flat floor at y = 0 made of `tiles` x `tiles` squares of `size` m, two triangles each,
/// starting at the origin and running along +x and +z.
Shape tiledFloor(int tiles, Real size);

/// The same floor as a height field of (tiles + 1) x (tiles + 1) heights, all zero.
Shape flatHeightField(int tiles, Real size);

/// The rolling hills' height at (x, z) in the terrain's own frame, m: sums of sines of amplitude
/// `amplitude`.
Real hillsHeight(Real x, Real z, Real amplitude);

/// The same hills as a triangle mesh (gridMesh of hillsHeight): `cells` x `cells` squares of `size` m,
/// 2 cells^2 triangles, running along +x and +z from the body's origin.
Shape hillsMesh(int cells, Real size, Real amplitude);

/// Rolling hills: a height field of `cells` x `cells` cells of `size` m, heights from sums of
/// sines (amplitude `amplitude` m), centred on the origin.
World buildTerrain(int cells, Real size, Real amplitude);

/// Cylinders standing, stacked and one rolling on its side, a table and a chair, on a floor.
World buildCylinderScene();

/// Two frictionless boxes sliding at 5 m/s over 30 m of 1 m tiles, one on a mesh floor and one on a
/// height field beside it, and a ball rolling down a 15-degree height-field ramp (the seam scene;
/// Settings::activeEdges false slows the ball by a fifth).
World buildSeamScene();

/// A mixed pile of `bodies` boxes, spheres, capsules, cylinders and tables dropped onto hills.
World buildTerrainPile(int bodies, unsigned seed = 13);

/// The shapes of buildMeshTerrainPile, by body: boxes, balls, capsules and cans in turn, every
/// 40th a table (a compound of five boxes).
Shape meshPileShape(int index);

/// `bodies` of meshPileShape's mix in columns 1.2 m apart, about ten levels deep (1.2 m apart
/// from 4 m up), each turned at random, the balls and capsules with chapter 10's
/// kPileRollingResistance, dropped onto hills (amplitude 1.5 m) as a triangle mesh (hillsMesh) of
/// `cells` x `cells` squares of 1 m centred on the origin: the scene of `stepwise bench worlds`.
World buildMeshTerrainPile(int cells, int bodies, unsigned seed = 13);

void addChapter13Scenes(Registry& registry);

}  // namespace stepwise
