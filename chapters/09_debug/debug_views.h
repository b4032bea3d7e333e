#pragma once
// What the debugger can show on top of the bodies, each view a flag: colliders, the selected body
// and its pairs in wireframe, contact points as red cubes with yellow normals, the EPA face that
// gave a pair's normal in blue, the GJK simplex and the Minkowski difference of a chosen pair,
// bounds, joint frames and limits. All through DebugDraw: the renderer draws what this describes.

#include "02_gjk/gjk.h"
#include "09_debug/hit_tree.h"
#include "world/debug_draw.h"
#include "world/world.h"

#include <optional>
#include <vector>

namespace stepwise {

// [ch09-view-flags]
struct DebugViews {
    bool colliders = true;          // every body's shape (off: only what the other views draw)
    bool wireframeSelection = true; // the selected body and the moving bodies it touches as wireframes
    bool contactPoints = true;      // red cubes on both surfaces
    bool contactNormals = true;     // yellow arrows
    bool epaFace = false;           // the chosen pair's EPA face, blue, on both bodies
    bool gjkSimplex = false;        // the chosen pair's final GJK simplex in A - B (beside the bodies)
    bool minkowski = false;         // the chosen pair's A - B, its hull and the origin
    bool bounds = false;            // each body's bounding box
    bool joints = false;            // joint anchors, axes and limits (chapter 8's drawing)
};
// [ch09-view-flags]

/// What GJK and EPA make of one pair right now, for the views: recomputed from the poses, so it
/// shows what the narrowphase saw at the start of the next step.
struct PairDiagnosis {
    int bodyA = -1;
    int bodyB = -1;
    bool overlapping = false;
    Simplex simplex;                    // GJK's final simplex (A - B space)
    std::vector<Vec3> minkowskiPoints;  // A - B as points (corners or support samples)
    bool hasEpaFace = false;            // overlapping and EPA found a face
    SupportPoint epaFace[3];            // the face of A - B nearest the origin: w, and the points on A and B
    Vec3 normal = Vec3::UnitY();        // EPA's normal (A towards B) or GJK's separating direction
    Real depth = 0;                     // EPA's depth, or minus the distance when apart
};

/// Diagnoses the pair; an invalid pair (same body, out of range) gives bodyA = -1.
PairDiagnosis diagnosePair(const World& world, int bodyA, int bodyB);

/// Which pair the diagnostic views look at: the selected contact's pair, else the selected body
/// with the first body it touches, else the first two bodies (in most scenes the ground and the
/// first body on it). Empty (-1, -1) when the world has fewer than two bodies.
BodyPair chosenPair(const World& world, const HitTree& tree, const HitSelection& selection, int selectedBody);

/// Which bodies the selection wireframe view draws as wireframes (1) instead of solids: the
/// selected body, the moving bodies it touches, and both bodies of the selected contact's pair.
/// A static body a selected box rests on stays solid: drawn as a wireframe the floor would vanish.
std::vector<char> wireframeBodies(const World& world, int selectedBody, const HitTree& tree, const HitSelection& selection);

/// Where the A - B overlay goes: to the right of the moving bodies, clear of them by its own size,
/// so it never hides them.
Vec3 minkowskiAnchor(const World& world, const PairDiagnosis& diagnosis);

/// Draws the enabled views, the bodies themselves included (colliders): a demo draws this instead
/// of drawWorld, so the selected body and the bodies it touches can be drawn as wireframes rather
/// than solids. `selectedBody` (-1: none) and `selection` choose what is highlighted: the selected
/// contact point as a larger white cube, its pair's bodies as wireframes.
void drawDebugViews(DebugDraw& draw, const World& world, const DebugViews& views, int selectedBody,
                    const HitTree& tree, const HitSelection& selection);

}  // namespace stepwise
