#pragma once
// What `stepwise bench worlds` reads off the bodies' poses: how far each body is into the terrain,
// and whether it went through it. Measured from the poses and the shapes alone, so both engines
// are judged by one yardstick (each engine's own contact depths are its narrowphase's opinion:
// chapter 13's internal-edge correction measures a body past a seam against the plane of the
// triangle it left, Bullet's margins round its shapes).
//
// The terrain is a grid mesh (gridMesh in scenes.h): vertex (r, c) at index r (cells + 1) + c,
// each square split along the diagonal from (r, c) to (r + 1, c + 1), so the surface is a height
// function y = h(x, z), linear on each triangle. A body's depth is the deepest of points spread
// over its surface below that function, taken along the triangle's normal there.

#include "world/world.h"

#include <array>
#include <string>
#include <vector>

namespace stepwise {

/// A grid mesh's surface as a height function, world frame (the mesh's body does not turn).
class GridTerrain {
public:
    /// Throws std::invalid_argument when `ground` is not a square grid mesh of gridMesh's layout.
    explicit GridTerrain(const Body& ground);
    /// Whether (x, z) lies over the grid.
    bool covers(Real x, Real z) const;
    /// The surface's height at (x, z), clamped to the grid, and the unit normal there (up).
    Real heightAt(Real x, Real z, Vec3* normal = nullptr) const;
    Real lowest() const { return lowest_; }

private:
    const TriangleMesh* mesh_;
    Vec3 corner_;
    int cells_ = 0;
    Real size_ = 1;
    Real lowest_ = 0;
};

/// Points on a shape's surface, body frame, at most about `spacing` m apart: a box's faces as
/// grids, a ball, a capsule's and a cylinder's sides and ends as rings, a hull's faces as grids, a
/// compound's children's. (The deepest point of a body in a bent surface need not be a corner: a
/// box lying across a ridge touches it along a line through its face.)
std::vector<Vec3> surfaceSamples(const Shape& shape, Real spacing);

/// How far the body's samples (placed at `pose`) reach below the surface, m, along the normal of
/// the triangle under the deepest: 0 when none does.
Real depthBelow(const GridTerrain& terrain, const std::vector<Vec3>& samples, const Transform& pose);

/// What the poses of a run's last frames showed, judged against the terrain.
struct TerrainJudgement {
    int tunnelled = 0;                   // bodies under the ground (judgeTunnelling)
    int leftTerrain = 0;                 // bodies beyond its edge, not judged
    std::vector<std::string> tunnelledNames;
    Real deepest = 0;                    // m, the deepest body into the ground (depthBelow)
    std::string deepestBody;             // "body17 (box)"; empty when none is in it
    std::array<Real, kShapeTypeCount> deepestByShape{};  // m, the same by the bodies' shape type
    int mostOverBound = 0;               // the most bodies deeper than the bound in one frame
};

/// Counts the dynamic bodies of `start` that went through the terrain: the centre of mass below
/// the surface under it by more than the body's reach (the farthest its points are from that
/// centre: all of it under the ground), or below the terrain's lowest point. A body beyond the
/// terrain's edge has left it and is counted apart.
void judgeTunnelling(const World& start, const GridTerrain& terrain, const std::vector<Transform>& poses,
                     TerrainJudgement& judgement);

/// The deepest of `start`'s dynamic bodies at `poses` into the terrain (depthBelow), into
/// `judgement` when deeper, and how many are deeper than `bound` (m). `samples` holds each body's
/// surfaceSamples (empty for static bodies).
void judgeDepth(const World& start, const GridTerrain& terrain, const std::vector<std::vector<Vec3>>& samples,
                const std::vector<Transform>& poses, Real bound, TerrainJudgement& judgement);

}  // namespace stepwise
