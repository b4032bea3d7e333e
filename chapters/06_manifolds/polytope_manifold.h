#pragma once
// Manifolds of two polytopes (boxes, hulls): a face contact by clipping, or an edge-edge contact
// of one point with the speculative guards of the faces that meet next. Chapter 3's query
// supplies the normal; the faces and edges are found from it.

#include "03_epa/narrowphase.h"
#include "06_manifolds/manifold_point.h"
#include "world/shape.h"

namespace stepwise {

/// How much worse (m) a face's separation may be than the best axis's and still make a face
/// contact: faces are preferred, since their points span an area, and the preference keeps the
/// choice from flipping between steps (Box2D's and Box3D's linear slop tolerances play this part).
constexpr Real kFaceTolerance = Real(0.0005);

/// Hysteresis of the reference face, m: a pair keeps last step's reference body while the other
/// body's face separates the shapes by less than this much more. Tilting a box by half a degree
/// moves the two faces' separations apart by a few millimetres; without it the reference face
/// would flip back and forth and the points' feature ids with it, losing their warm start
/// (Box3D caches its last separating axis per pair for the same reason). The held face reads depth
/// along its own normal, which can be this much deeper than the shapes overlap; it is held only
/// while its points read within kFaceTolerance of the overlap (polytopeManifold).
constexpr Real kReferenceHysteresis = Real(0.01);

/// Which body owns the reference face of a face contact.
enum class ReferenceSide { None, A, B };

/// The candidate points of two polytopes whose chapter 3 query (in the same frame) is `query`.
/// Keeps points at most keepDistance above the reference face (speculative ones). `preferred`:
/// last step's reference side, kept within kReferenceHysteresis while its points read no deeper
/// than the best of SAT's three axes says the shapes overlap (+ kFaceTolerance). False when no
/// point is that close or the input is degenerate.
bool polytopeManifold(const Shape& a, const Transform& ta, const Shape& b, const Transform& tb,
                      const ContactQuery& query, Real keepDistance, ManifoldCandidates& out,
                      ReferenceSide preferred = ReferenceSide::None);

}  // namespace stepwise
