#pragma once
// The polytope EPA grows (epa.h has the algorithm around it): a closed surface of triangles,
// each knowing its three neighbours, that only ever grows by one support point at a time.
// Internal to chapter 3; the types it works on (EpaPolytope, EpaFace) are in epa.h so that the
// demo can draw them.

#include "02_gjk/tolerances.h"
#include "03_epa/epa.h"

#include <vector>

namespace stepwise::epa_polytope {

// Round-off thresholds, all relative to `scale`, the size of the pair (02_gjk/tolerances.h).
using tolerance::kRoundOff;
using tolerance::kThinFace;

/// One edge of the horizon: the border between the faces the new point sees and those it does
/// not. `from -> to` runs the way the removed face ran it; `outside` keeps the edge as `to -> from`.
struct HorizonEdge {
    int from = 0, to = 0;
    int outside = -1;
};

/// Memory one EPA query reuses for every expansion instead of allocating it each time.
struct ExpansionScratch {
    std::vector<HorizonEdge> horizon;
    std::vector<int> removed;
    std::vector<int> slots;
    std::vector<EpaFace> fan;
    std::vector<int> inPlane;  ///< faces removed although the point is only in their plane
};

/// Fills a face's plane. False when the triangle is too thin for its normal to mean anything.
bool setPlane(const EpaPolytope& polytope, EpaFace& face, Real scale);

/// The four faces of a tetrahedron, ordered so that every normal points out. False for a
/// tetrahedron with a sliver face.
bool initPolytope(EpaPolytope& polytope, SupportPoint points[4], Real scale);

/// The live face nearest the origin.
int closestFace(const EpaPolytope& polytope);

/// True when `point` is (within round-off) a vertex already.
bool isDuplicate(const EpaPolytope& polytope, const Vec3& point, Real scale);

/// Adds `point`, seen from the closest face `seenFace`; false (and nothing changed) when
/// round-off would have broken the polytope.
bool expandPolytope(EpaPolytope& polytope, int seenFace, const SupportPoint& point, Real scale,
                    ExpansionScratch& scratch);

/// Barycentric coordinates of the origin's projection onto a face's plane (ratios of signed
/// sub-triangle areas, Ericson 3.4). All >= 0 when the projection lies inside the face.
Vec3 projectionWeights(const EpaPolytope& polytope, const EpaFace& face);

}  // namespace stepwise::epa_polytope
