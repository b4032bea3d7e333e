#pragma once
// The demo's "mesh-tree" view: the boxes of every static mesh's tree at one level, drawn in the
// mesh body's frame. Level 0 is the root's box; each level down halves the triangles a box holds
// (mesh_tree.h), so stepping the slider shows how the query narrows a body's box to a few
// triangles. A leaf that ends above the chosen level is drawn at its own level, so every triangle
// stays covered by exactly one drawn box.

#include "13_worlds/world_manifold.h"
#include "world/debug_draw.h"
#include "world/world.h"

namespace stepwise {

/// The levels the demo's slider offers: more than the deepest tree of a million triangles
/// (a median split halves the count per level, leaves hold up to 4).
constexpr int kTreeViewLevels = 20;

/// The boxes of one level of a tree: nodes at `level`, and leaves shallower than it.
std::vector<Aabb> meshTreeLevelBoxes(const MeshTree& tree, int level);

/// Draws the level's boxes of every mesh body's tree (built once per mesh and kept in `cache`),
/// coloured by level from dark red (the root) to yellow.
void drawMeshTreeLevel(DebugDraw& draw, const World& world, int level, WorldShapesCache& cache);

}  // namespace stepwise
