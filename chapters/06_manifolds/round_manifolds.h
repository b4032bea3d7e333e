#pragma once
// Manifolds of round shapes, in closed form. A sphere touches anything at one point. A capsule
// is a segment with a radius: lying along another capsule or on a face it touches along a
// stretch, whose two ends are its two points (Box2D's capsule manifolds do the same).

#include "03_epa/narrowphase.h"
#include "06_manifolds/manifold_point.h"
#include "world/shape.h"

namespace stepwise {

/// Capsule axes closer to parallel than this (|cos| of the angle) touch along a stretch.
constexpr Real kParallelCapsules = Real(0.995);

/// How much shallower (m) than chapter 3's depth a capsule's two ends may read and still be the
/// manifold: a capsule whose deepest part lies beyond the edge of the face it was clipped against
/// (or two capsules that cross) has ends that read apart where the shapes overlap by centimetres,
/// and its contact is chapter 3's single point instead. Half a millimetre: above the query's
/// round-off, as chapter 6's face tolerance (polytope_manifold.h) is for polytopes.
constexpr Real kRoundEndsTolerance = Real(0.0005);

/// The candidate points when A or B is a sphere or a capsule, from chapter 3's query (same frame).
/// False when no point is within keepDistance.
bool roundManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                   const ContactQuery& query, Real keepDistance, ManifoldCandidates& out);

/// The query's one point as a candidate (chapter 3's contact).
ManifoldPoint singlePoint(const ContactQuery& query);

}  // namespace stepwise
