#pragma once
// Chapter 13's pipeline: chapter 12's, with the shapes of worlds to stand on collided. Meshes and
// height fields (static ground), compounds and cylinders are taken apart into convex parts near
// each body (world_manifold.h); chapter 6 builds, keeps and matches their manifolds as it does
// every other pair's, and the fast step solves them like any contact. A scene with none of these
// shapes runs chapter 12's step unchanged (the run report says so).

#include "12_planner/chapter.h"
#include "13_worlds/world_manifold.h"

namespace stepwise {

/// Chapter 13's switches over chapter 12's.
struct WorldOptions {
    SpeedOptions speed;
    bool internalEdgeFix = true;  // false: triangle contacts keep the normals of inactive edges (A/B),
                                  // whatever Settings::activeEdges says
};

Pipeline makeChapter13Pipeline(const World& world);
Pipeline makeChapter13Pipeline(const World& world, const WorldOptions& options);

/// How many bodies of each of chapter 13's kinds the world holds, for the plan note.
std::string worldShapesNote(const World& world);

}  // namespace stepwise
