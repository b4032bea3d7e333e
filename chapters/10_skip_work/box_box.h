#pragma once
// Box against box by separating axes: the query chapter 6's manifold builder starts from, for the
// commonest pair of a pile, without GJK and EPA. Two boxes are separated exactly when one of
// fifteen axes separates their projections: the three face normals of each box and the nine
// cross products of an edge of one with an edge of the other (Gottschalk, Lin and Manocha,
// "OBBTree", SIGGRAPH 1996; Ericson, "Real-Time Collision Detection", 4.4). Overlapping, the axis
// of least penetration is the one EPA finds for two boxes; apart, the axis of largest separation
// gives a lower bound of the distance, exact when a face separates them.

#include "03_epa/narrowphase.h"

namespace stepwise {

/// collideShapes' answer for two boxes, from their fifteen axes: depth (> 0 overlap, < 0 apart:
/// minus the largest separation), the normal from A towards B, and witness points with
/// pointA - pointB = depth * normal (on the supporting edges for an edge axis; a deepest vertex and
/// its drop onto the face for a face axis). `routine` is "box_box_sat"; a box with a non-finite or
/// non-positive size, or a non-finite pose, gives chapter 3's answer for it ("invalid").
ContactQuery boxBoxQuery(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb);

/// The query function chapter 10's narrowphase hands chapter 6's manifold builder: boxBoxQuery for
/// two boxes, collideShapes for every other pair.
ContactQuery fastContactQuery(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                              const CollideOptions& options);

}  // namespace stepwise
