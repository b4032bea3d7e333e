#pragma once
// The hit result tree: every touching pair, its manifold, and each manifold's points with depth,
// normal and the solver's impulses, as plain data a panel can list and a test can check. A
// selection names one node (a pair, a manifold or a point); the demo highlights the selected
// point in the scene, and picking a point in the scene selects its node in the tree.

#include "09_debug/ray_cast.h"
#include "world/debug_draw.h"
#include "world/world.h"

#include <cstdint>
#include <string>
#include <vector>

namespace stepwise {

// [ch09-hit-tree]
struct HitPoint {
    Vec3 position = Vec3::Zero();   // midway between the two surface points, world
    Vec3 pointA = Vec3::Zero();     // on A's surface
    Vec3 pointB = Vec3::Zero();     // on B's surface
    Real depth = 0;                 // m; < 0 a speculative point (a gap)
    Real normalImpulse = 0;         // N s, of the last solve
    Real tangentImpulse[2] = {0, 0};
    std::uint32_t featureId = 0;
    bool persisted = false;
};

struct HitManifold {
    Vec3 normal = Vec3::UnitY();    // unit, A towards B
    std::vector<HitPoint> points;
};

struct HitPair {
    int bodyA = -1;
    int bodyB = -1;
    std::string nameA, nameB;
    std::vector<HitManifold> manifolds;   // one per contact record (this engine keeps one a pair)
};

struct HitTree {
    std::vector<HitPair> pairs;     // in the contact cache's order (sorted by pair)
    int pointCount() const;
};
// [ch09-hit-tree]

/// The tree of the world's contact cache: the pairs with at least one point.
HitTree buildHitTree(const World& world);

/// One node of the tree: a pair (manifold and point -1), a manifold (point -1) or a point.
struct HitSelection {
    int pair = -1;
    int manifold = -1;
    int point = -1;
    bool empty() const { return pair < 0; }
    bool operator==(const HitSelection& other) const {
        return pair == other.pair && manifold == other.manifold && point == other.point;
    }
};

/// The selected point, or nullptr when the selection is not a point of this tree.
const HitPoint* selectedPoint(const HitTree& tree, const HitSelection& selection);

/// The point nearest the ray among those within `radius` (m) of it, ahead of its origin, or an
/// empty selection: clicking a contact in the scene selects it in the tree.
HitSelection pickHitPoint(const HitTree& tree, const Ray& ray, Real radius);

/// The node for a pair of bodies (in either order), or empty.
HitSelection findPair(const HitTree& tree, int bodyA, int bodyB);

/// One line per node, for the panel and the tests: "crate-1 / ground", "normal (0, 1, 0)",
/// "#2 depth 3.1 mm, impulse 0.41 N s".
std::string describePair(const HitPair& pair);
std::string describeManifold(const HitManifold& manifold);
std::string describePoint(int index, const HitPoint& point);

}  // namespace stepwise
