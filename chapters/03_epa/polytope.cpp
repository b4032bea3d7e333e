// The polytope EPA grows: a closed surface of triangles that know their neighbours, expanded
// one support point at a time across its horizon (see polytope.h).
#include "03_epa/polytope.h"

#include <algorithm>
#include <cmath>

namespace stepwise::epa_polytope {

namespace {

/// Index of `vertex` among the face's corners, so that the edge starting there is known.
int cornerOf(const EpaFace& face, int vertex) {
    for (int i = 0; i < 3; ++i) {
        if (face.vertices[i] == vertex) return i;
    }
    return -1;
}

}  // namespace

/// Fills a face's plane. False when the triangle is too thin for its normal to mean anything.
bool setPlane(const EpaPolytope& polytope, EpaFace& face, Real scale) {
    const Vec3& p0 = polytope.vertices[face.vertices[0]].w;
    const Vec3& p1 = polytope.vertices[face.vertices[1]].w;
    const Vec3& p2 = polytope.vertices[face.vertices[2]].w;
    const Vec3 normal = (p1 - p0).cross(p2 - p0);
    const Real length = normal.norm();
    const Real longestEdge =
        std::sqrt(std::max({(p1 - p0).squaredNorm(), (p2 - p1).squaredNorm(), (p0 - p2).squaredNorm()}));
    if (!(length > kThinFace * kRoundOff * scale * longestEdge)) return false;
    face.normal = normal / length;
    // The mean of the three vertices' offsets: no vertex's round-off is favoured.
    face.distance = face.normal.dot(p0 + p1 + p2) / 3;
    face.removed = false;
    return true;
}

/// Builds the four faces of a tetrahedron, ordered so that every face's normal points out.
bool initPolytope(EpaPolytope& polytope, SupportPoint points[4], Real scale) {
    const Vec3 e1 = points[1].w - points[0].w, e2 = points[2].w - points[0].w, e3 = points[3].w - points[0].w;
    if (e1.cross(e2).dot(e3) > 0) std::swap(points[0], points[1]);  // vertex 3 behind face 012
    polytope.vertices.assign(points, points + 4);
    static const int kFaces[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    polytope.faces.resize(4);
    for (int f = 0; f < 4; ++f) {
        std::copy(kFaces[f], kFaces[f] + 3, polytope.faces[f].vertices);
        if (!setPlane(polytope, polytope.faces[f], scale)) return false;
    }
    // Each edge a->b of one face is b->a of exactly one other: that face is its neighbour.
    for (int f = 0; f < 4; ++f) {
        for (int edge = 0; edge < 3; ++edge) {
            const int from = polytope.faces[f].vertices[edge], to = polytope.faces[f].vertices[(edge + 1) % 3];
            for (int g = 0; g < 4; ++g) {
                const int corner = cornerOf(polytope.faces[g], to);
                if (g != f && corner >= 0 && polytope.faces[g].vertices[(corner + 1) % 3] == from) {
                    polytope.faces[f].neighbours[edge] = g;
                }
            }
        }
    }
    return true;
}

int closestFace(const EpaPolytope& polytope) {
    int best = -1;
    for (int f = 0; f < static_cast<int>(polytope.faces.size()); ++f) {
        const EpaFace& face = polytope.faces[f];
        if (!face.removed && (best < 0 || face.distance < polytope.faces[best].distance)) best = f;
    }
    return best;
}

// [ch03-horizon]
/// Depth-first walk over the faces visible from `point`, entered from a removed neighbour
/// across the face's edge `edge`. Visible faces are removed; the first invisible face met across
/// an edge contributes that edge to the horizon. Walking each face's remaining two edges in
/// order yields the horizon as one closed loop, in order (Bullet's gjkepa2 `expand`).
static void walkHorizon(EpaPolytope& polytope, int faceIndex, int edge, const Vec3& point, Real slack,
                        ExpansionScratch& scratch) {
    EpaFace& face = polytope.faces[faceIndex];
    if (face.removed) return;
    const bool seen = face.normal.dot(point) - face.distance > slack ||
                      std::find(scratch.inPlane.begin(), scratch.inPlane.end(), faceIndex) != scratch.inPlane.end();
    if (!seen) {  // cannot see the point: horizon
        scratch.horizon.push_back({face.vertices[(edge + 1) % 3], face.vertices[edge], faceIndex});
        return;
    }
    face.removed = true;
    scratch.removed.push_back(faceIndex);
    for (int step = 1; step <= 2; ++step) {
        const int next = (edge + step) % 3;
        const int neighbour = face.neighbours[next];
        walkHorizon(polytope, neighbour, cornerOf(polytope.faces[neighbour], face.vertices[(next + 1) % 3]),
                    point, slack, scratch);
    }
}

namespace {

enum class Expansion { Done, PointInPlane, Broken };

/// One try at adding `point` (expandPolytope): the faces it sees, plus those in
/// `scratch.inPlane`, are removed and a fan of new faces closes the hole.
Expansion tryExpand(EpaPolytope& polytope, int seenFace, const SupportPoint& point, Real scale,
                    ExpansionScratch& scratch) {
    scratch.horizon.clear();
    scratch.removed.clear();
    const Real slack = kRoundOff * scale;
    // A convex polytope that holds the origin only grows, so no new face may come nearer than the
    // one it replaces. The starting tetrahedron may leave the origin up to its containment slack
    // outside (GJK's touching tolerance), most often on an edge or face through the origin when
    // the shapes share a centre; then a new face through that edge may lie up to that slack on
    // the far side, and only that is the floor.
    const Real closestDistance = polytope.faces[seenFace].distance;
    const Real floor = closestDistance >= 0 ? closestDistance : -tolerance::kSeedContainment * scale;
    polytope.faces[seenFace].removed = true;
    scratch.removed.push_back(seenFace);
    for (int edge = 0; edge < 3; ++edge) {
        const EpaFace& seen = polytope.faces[seenFace];
        const int neighbour = seen.neighbours[edge];
        walkHorizon(polytope, neighbour, cornerOf(polytope.faces[neighbour], seen.vertices[(edge + 1) % 3]),
                    point.w, slack, scratch);
    }
    const auto undo = [&](Expansion outcome) {
        for (int f : scratch.removed) polytope.faces[f].removed = false;
        return outcome;
    };
    // The horizon must be one loop that passes each vertex once, or the fan would not close.
    const std::vector<HorizonEdge>& horizon = scratch.horizon;
    const int count = static_cast<int>(horizon.size());
    if (count < 3) return undo(Expansion::Broken);
    for (int i = 0; i < count; ++i) {
        if (horizon[i].to != horizon[(i + 1) % count].from) return undo(Expansion::Broken);
        for (int j = 0; j < i; ++j) {
            if (horizon[j].from == horizon[i].from) return undo(Expansion::Broken);
        }
    }

    // New faces reuse the removed slots first; build them aside so that they can still be undone.
    const int newVertex = static_cast<int>(polytope.vertices.size());
    const int removedCount = static_cast<int>(scratch.removed.size());
    polytope.vertices.push_back(point);
    scratch.slots.resize(count);
    scratch.fan.resize(count);
    for (int i = 0; i < count; ++i) {
        scratch.slots[i] = i < removedCount ? scratch.removed[i] : static_cast<int>(polytope.faces.size()) + i - removedCount;
        EpaFace& face = scratch.fan[i];
        face.vertices[0] = horizon[i].from;
        face.vertices[1] = horizon[i].to;
        face.vertices[2] = newVertex;
        if (!setPlane(polytope, face, scale) || face.distance < floor - slack) {
            // A sliver, or a face turned inwards: the point lies in line with this horizon edge
            // or beyond it, in the plane of the face across it within round-off. That face
            // goes too, and the next try fans around it.
            polytope.vertices.pop_back();
            scratch.inPlane.push_back(horizon[i].outside);
            return undo(Expansion::PointInPlane);
        }
    }
    // Stitch: edge 0 borders the face outside the horizon, edges 1 and 2 the fan's neighbours.
    for (int i = 0; i < count; ++i) {
        EpaFace& face = scratch.fan[i];
        face.neighbours[0] = horizon[i].outside;
        face.neighbours[1] = scratch.slots[(i + 1) % count];
        face.neighbours[2] = scratch.slots[(i + count - 1) % count];
        EpaFace& outside = polytope.faces[horizon[i].outside];
        outside.neighbours[cornerOf(outside, horizon[i].to)] = scratch.slots[i];
    }
    if (count > removedCount) polytope.faces.resize(polytope.faces.size() + (count - removedCount));
    for (int i = 0; i < count; ++i) polytope.faces[scratch.slots[i]] = scratch.fan[i];
    return Expansion::Done;
}

}  // namespace

/// Adds `point` to the polytope: removes the faces it sees, starting with the closest face
/// `seenFace`, and fans new faces from it to the horizon. A point in the plane of a face it
/// does not quite see (two nearly equal boxes give A - B many such faces) makes a fan face that
/// is a sliver or turns inwards, nearer the origin than the face it replaces, which is
/// impossible for an exact convex polytope, which only grows: the face across that horizon edge
/// is then removed too, a few times at most. Round-off can also make the polytope a hair
/// non-convex so that the horizon is not one simple loop. What cannot be mended leaves the
/// polytope as it was and returns false: EPA then stops with the best face it has rather than
/// with a worse one.
bool expandPolytope(EpaPolytope& polytope, int seenFace, const SupportPoint& point, Real scale,
                    ExpansionScratch& scratch) {
    constexpr int kInPlaneTries = 4;
    scratch.inPlane.clear();
    for (int attempt = 0; attempt < kInPlaneTries; ++attempt) {
        const Expansion outcome = tryExpand(polytope, seenFace, point, scale, scratch);
        if (outcome != Expansion::PointInPlane) return outcome == Expansion::Done;
    }
    return false;
}
// [ch03-horizon]

bool isDuplicate(const EpaPolytope& polytope, const Vec3& point, Real scale) {
    const Real limit = kRoundOff * scale;
    for (const SupportPoint& vertex : polytope.vertices) {
        if ((vertex.w - point).squaredNorm() <= limit * limit) return true;
    }
    return false;
}

/// Barycentric coordinates of the origin's projection onto a face's plane (ratios of signed
/// sub-triangle areas, Ericson 3.4). All >= 0 when the projection lies inside the face.
Vec3 projectionWeights(const EpaPolytope& polytope, const EpaFace& face) {
    const Vec3& p0 = polytope.vertices[face.vertices[0]].w;
    const Vec3& p1 = polytope.vertices[face.vertices[1]].w;
    const Vec3& p2 = polytope.vertices[face.vertices[2]].w;
    const Vec3 projection = face.normal * face.distance;
    const Real area = face.normal.dot((p1 - p0).cross(p2 - p0));
    return Vec3(face.normal.dot((p1 - projection).cross(p2 - projection)) / area,
                face.normal.dot((p2 - projection).cross(p0 - projection)) / area,
                face.normal.dot((p0 - projection).cross(p1 - projection)) / area);
}

}  // namespace stepwise::epa_polytope
