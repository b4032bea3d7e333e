#pragma once
// The Expanding Polytope Algorithm: how deep two overlapping convex shapes are, along which
// normal, and where. GJK (chapter 2) ends with a simplex of the Minkowski difference A - B that
// holds the origin; EPA grows it into a polytope whose closest face to the origin converges to
// the boundary point of A - B nearest the origin. That point is the penetration vector.
//
// Sources: G. van den Bergen, "Proximity Queries and Penetration Depth Computation on 3D Game
// Objects" (GDC 2001) and "Collision Detection in Interactive 3D Environments" (2003), ch. 4.3;
// the horizon walk follows Bullet's gjkepa2.cpp (N. Nasser), the barycentric contact is
// Ericson, "Real-Time Collision Detection" (2005), 3.4.

#include "02_gjk/gjk.h"
#include "02_gjk/support.h"

#include <vector>

namespace stepwise {

// [ch03-settings]
/// The support gap at which EPA stops, as a fraction of the pair's size: 10 micrometres on a
/// metre-sized pair. Ten times the float round-off floor (the code never asks for less than
/// that floor), and far below anything a contact solver can tell apart (see bench-epa.svg for
/// what tighter or looser values cost and buy).
constexpr Real kEpaDefaultRelativeTolerance = Real(1e-5);

struct EpaSettings {
    int maxIterations = 50;                              // expansions before giving up
    Real relativeTolerance = kEpaDefaultRelativeTolerance;  // support gap, as a fraction of size
    int maxExpansions = -1;    // step-by-step mode for the demo: stop after this many (-1: off)
    bool keepPolytope = false; // copy the final polytope into the result (debug drawing)
};
// [ch03-settings]

/// Why EPA stopped. Every exit still leaves a finite result behind.
enum class EpaExit {
    Converged,       // the support point lies within the tolerance of the closest face
    IterationCap,    // maxIterations expansions, returned the best face so far
    StepLimit,       // maxExpansions reached (the demo's stepping)
    NoProgress,      // the support point is already a vertex, or the horizon broke: round-off
    Degenerate       // no tetrahedron around the origin could be built: touching contact
};

const char* toString(EpaExit exit);

/// One triangle of the polytope. Its vertices run counter-clockwise seen from outside, and
/// neighbours[i] is the face across the edge vertices[i] -> vertices[(i + 1) % 3].
struct EpaFace {
    int vertices[3] = {0, 0, 0};
    int neighbours[3] = {-1, -1, -1};
    Vec3 normal = Vec3::UnitY();   // outward, unit
    Real distance = 0;             // of the face's plane from the origin
    bool removed = false;
};

struct EpaPolytope {
    std::vector<SupportPoint> vertices;
    std::vector<EpaFace> faces;    // removed faces stay in the list, flagged
};

struct EpaResult {
    Real depth = 0;                       // >= 0, m
    Vec3 normal = Vec3::UnitY();          // unit, from A towards B: moving B by depth*normal separates
    Vec3 pointA = Vec3::Zero();           // deepest point of A inside B, world frame
    Vec3 pointB = Vec3::Zero();           // deepest point of B inside A; pointA - pointB = depth*normal
    int iterations = 0;                   // expansions done
    EpaExit exit = EpaExit::Degenerate;
    SupportPoint closestFace[3];          // the face that produced the contact (debug drawing)
    Vec3 barycentric = Vec3(1, 0, 0);     // of the origin's projection on that face
    EpaPolytope polytope;                 // only with EpaSettings::keepPolytope
};

/// Penetration of two overlapping shapes, seeded with the final simplex of gjkIntersect()
/// (any number of points: fewer than four are grown into a tetrahedron first).
EpaResult epaPenetration(const ConvexProxy& a, const ConvexProxy& b, const Simplex& simplex,
                         const EpaSettings& settings = EpaSettings{});

}  // namespace stepwise
