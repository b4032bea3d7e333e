#include "13_worlds/world_manifold.h"

#include "06_manifolds/reduction.h"
#include "10_skip_work/box_box.h"
#include "13_worlds/cylinder_manifold.h"
#include "13_worlds/height_field_cells.h"
#include "13_worlds/triangle_prism.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

namespace {

/// Points of two part contacts this close (m) are one point (a tenth of chapter 6's slop).
constexpr Real kSamePoint = Real(0.0005);

/// A triangle contact whose normal is more than 60 degrees from the triangle's front came out of
/// its prism's side face: an edge contact on a ridge up to 60 degrees stays within it.
constexpr Real kPrismSideCosine = Real(0.5);

/// One convex piece of a shape, placed in the world: a compound's child, a triangle's prism, or a
/// whole convex shape (key 0).
struct ConvexPart {
    Shape shape;
    Transform transform;
    std::uint32_t key = 0;          // child or triangle index + 1
    bool triangle = false;
    Vec3 corners[3];                // a triangle's, world
    std::array<bool, 3> active = {true, true, true};
};

Transform inverse(const Transform& pose) {
    Transform result;
    result.rotation = pose.rotation.conjugate();
    result.position = -(result.rotation * pose.position);
    return result;
}

void addTriangle(const Vec3 local[3], const Transform& pose, std::uint32_t key, const std::array<bool, 3>& active,
                 std::vector<ConvexPart>& parts) {
    ConvexPart part;
    part.shape = trianglePrism(local[0], local[1], local[2]);
    part.transform = pose;
    part.key = key;
    part.triangle = true;
    for (int k = 0; k < 3; ++k) part.corners[k] = pose.apply(local[k]);
    part.active = active;
    parts.push_back(std::move(part));
}

// [ch13-parts]
/// The parts of `shape` (at `pose`) whose boxes reach `near` (a world box).
void collectParts(WorldShapesCache& cache, const Shape& shape, const Transform& pose, const Aabb& near,
                  std::vector<ConvexPart>& parts) {
    parts.clear();
    thread_local std::vector<int> triangles;
    triangles.clear();
    switch (shape.type) {
        case ShapeType::Compound:
            for (std::size_t i = 0; i < shape.compound->children.size(); ++i) {
                const CompoundChild& child = shape.compound->children[i];
                const Transform placed = compose(pose, child.transform);
                if (computeAabb(child.shape, placed).overlaps(near))
                    parts.push_back({child.shape, placed, static_cast<std::uint32_t>(i + 1), false, {}, {true, true, true}});
            }
            return;
        case ShapeType::Mesh: {
            const WorldShapesCache::MeshEntry& entry = cache.entry(shape.mesh);
            queryMeshTree(entry.tree, *shape.mesh, transformedBox(near, inverse(pose)), triangles);
            for (const int t : triangles) {
                const auto& corners = shape.mesh->triangles[static_cast<std::size_t>(t)];
                const Vec3 local[3] = {shape.mesh->vertices[static_cast<std::size_t>(corners[0])],
                                       shape.mesh->vertices[static_cast<std::size_t>(corners[1])],
                                       shape.mesh->vertices[static_cast<std::size_t>(corners[2])]};
                addTriangle(local, pose, static_cast<std::uint32_t>(t + 1), entry.edges.active[static_cast<std::size_t>(t)],
                            parts);
            }
            return;
        }
        case ShapeType::HeightField:
            queryHeightField(*shape.heightField, transformedBox(near, inverse(pose)), triangles);
            for (const int t : triangles) {
                Vec3 local[3];
                heightFieldTriangle(*shape.heightField, t, local);
                addTriangle(local, pose, static_cast<std::uint32_t>(t + 1), heightFieldActiveEdges(*shape.heightField, t),
                            parts);
            }
            return;
        default: parts.push_back({shape, pose, 0, false, {}, {true, true, true}}); return;
    }
}
// [ch13-parts]

/// The point of a round body (a sphere, a capsule) that touches a plane of outward normal
/// `towards` nearest `near`: its core's point nearest `near`, moved out by the radius. A round
/// body touches a plane at one point of its core, wherever the triangle's edge said it touched.
Vec3 roundContactPoint(const ConvexPart& body, const Vec3& near, const Vec3& towards) {
    const Shape& shape = body.shape;
    if (!isRound(shape)) return near;
    Vec3 core = body.transform.position;
    if (shape.type == ShapeType::Capsule) {
        const Vec3 axis = body.transform.rotate(Vec3::UnitY());
        core += std::clamp(axis.dot(near - core), -shape.halfHeight, shape.halfHeight) * axis;
    }
    return core + shape.radius * towards;
}

// [ch13-internal-edges]
/// A triangle part's contact whose normal is not the triangle's own, where the triangle's edge
/// there is inactive (a seam between coplanar triangles), becomes a contact with the triangle's
/// face: the normal its front's, each depth how far the body's point is below the front.
void correctInternalEdge(const ConvexPart& triangle, const ConvexPart& body, bool triangleIsA,
                         ManifoldCandidates& candidates) {
    if (candidates.points.empty()) return;
    const Vec3 front = (triangle.corners[1] - triangle.corners[0]).cross(triangle.corners[2] - triangle.corners[0]).normalized();
    const Vec3 outOfTriangle = triangleIsA ? candidates.normal : Vec3(-candidates.normal);
    const ManifoldPoint& deepest = *std::max_element(
        candidates.points.begin(), candidates.points.end(),
        [](const ManifoldPoint& x, const ManifoldPoint& y) { return x.depth < y.depth; });
    // The point on the prism (on a side face just below an edge) taken to the triangle's plane.
    const Vec3 onPrism = triangleIsA ? deepest.pointA : deepest.pointB;
    const Vec3 onTriangle = onPrism - (front.dot(onPrism - triangle.corners[0])) * front;
    const Vec3 corrected = correctedNormal(triangle.corners, triangle.active, onTriangle, outOfTriangle);
    // A prism's side face is no surface of the ground (the next triangle's prism lies beyond it, or
    // nothing does): a normal that far from the front is the side's, whatever the edge.
    const bool side = outOfTriangle.dot(front) < kPrismSideCosine;
    if ((corrected.dot(front) < kSameNormalCos && !side) || outOfTriangle.dot(front) >= kSameNormalCos) return;
    const Real offset = front.dot(triangle.corners[0]);
    candidates.normal = triangleIsA ? front : Vec3(-front);
    for (ManifoldPoint& point : candidates.points) {
        const Vec3 onBody = roundContactPoint(body, triangleIsA ? point.pointB : point.pointA, -front);
        (triangleIsA ? point.pointB : point.pointA) = onBody;
        const Real separation = front.dot(onBody) - offset;
        const Vec3 onFront = onBody - separation * front;
        point.depth = -separation;
        (triangleIsA ? point.pointA : point.pointB) = onFront;
    }
}
// [ch13-internal-edges]

/// The candidates of one pair of parts; false when they are farther apart than keepDistance.
bool partContact(const WorldShapesCache& cache, const ConvexPart& a, const ConvexPart& b, Real keepDistance,
                 ManifoldCandidates& out, bool& intersect) {
    CollideOptions collide;
    collide.separationDistance = true;
    const ContactQuery query = fastContactQuery(a.shape, a.transform, b.shape, b.transform, collide);
    if (query.routine == std::string("invalid") || !(query.intersect || -query.depth < keepDistance)) return false;
    intersect = intersect || query.intersect;
    const bool cylinder = a.shape.type == ShapeType::Cylinder || b.shape.type == ShapeType::Cylinder;
    if (!(cylinder && cylinderManifold(a.shape, a.transform, b.shape, b.transform, query, keepDistance, out))) {
        Contact built;
        if (!buildManifold(a.shape, a.transform, b.shape, b.transform, query, keepDistance, ManifoldOptions{}, built, nullptr))
            return false;
        out.normal = built.normal;
        out.points.clear();
        for (int i = 0; i < built.pointCount; ++i)
            out.points.push_back({built.points[i].pointA, built.points[i].pointB, built.points[i].depth, built.points[i].featureId});
    }
    if (cache.internalEdgeFix && a.triangle) correctInternalEdge(a, b, true, out);
    if (cache.internalEdgeFix && b.triangle) correctInternalEdge(b, a, false, out);
    return !out.points.empty();
}

/// Each point's feature id names its two parts too (a corner of child 2 on triangle 17 is not the
/// same corner on triangle 18).
std::uint32_t partFeature(std::uint32_t featureId, std::uint32_t keyA, std::uint32_t keyB) {
    return featureId ^ (keyA * 2654435761u) ^ (keyB * 40503u);
}

Real deepestOf(const ManifoldCandidates& candidates) {
    Real deepest = -kRealMax;
    for (const ManifoldPoint& point : candidates.points) deepest = std::max(deepest, point.depth);
    return deepest;
}

}  // namespace

const WorldShapesCache::MeshEntry& WorldShapesCache::entry(const std::shared_ptr<const TriangleMesh>& mesh) {
    auto found = meshes.find(mesh.get());
    if (found != meshes.end()) return found->second;
    MeshEntry fresh;
    fresh.mesh = mesh;
    fresh.tree = buildMeshTree(*mesh);
    fresh.edges = findTriangleEdges(*mesh);
    return meshes.emplace(mesh.get(), std::move(fresh)).first->second;
}

bool isWorldPair(const Shape& a, const Shape& b) {
    const auto world = [](ShapeType type) {
        return type == ShapeType::Compound || type == ShapeType::Mesh || type == ShapeType::HeightField ||
               type == ShapeType::Cylinder;
    };
    return world(a.type) || world(b.type);
}

// [ch13-world-manifold]
PairManifold worldManifold(WorldShapesCache& cache, const Shape& a, const Transform& ta, const Shape& b,
                           const Transform& tb, Real keepDistance, const Contact* previous, Contact& contact) {
    PairManifold result;
    if (!isWorldPair(a, b)) return result;
    result.handled = true;
    contact.pointCount = 0;
    contact.referenceSide = 0;
    const Vec3 margin = Vec3::Constant(std::max(keepDistance, Real(0)));
    Aabb nearA = computeAabb(b, tb), nearB = computeAabb(a, ta);
    nearA.min -= margin, nearA.max += margin, nearB.min -= margin, nearB.max += margin;
    thread_local std::vector<ConvexPart> partsA, partsB;
    collectParts(cache, a, ta, nearA, partsA);
    collectParts(cache, b, tb, nearB, partsB);
    // Every pair of parts: its candidates, their parts' names in their feature ids.
    thread_local std::vector<ManifoldCandidates> found;
    found.clear();
    ManifoldCandidates candidates;
    thread_local std::vector<Aabb> boxesB;
    boxesB.clear();
    for (const ConvexPart& partB : partsB) boxesB.push_back(computeAabb(partB.shape, partB.transform));
    for (const ConvexPart& partA : partsA) {
        Aabb reach = computeAabb(partA.shape, partA.transform);  // grown by the margin: parts that may touch
        reach.min -= margin, reach.max += margin;
        for (std::size_t j = 0; j < partsB.size(); ++j) {
            const ConvexPart& partB = partsB[j];
            if (!reach.overlaps(boxesB[j])) continue;
            if (!partContact(cache, partA, partB, keepDistance, candidates, result.intersect)) continue;
            for (ManifoldPoint& point : candidates.points) point.featureId = partFeature(point.featureId, partA.key, partB.key);
            found.push_back(candidates);
        }
    }
    if (found.empty()) return result;
    // The deepest part contact's normal, and the points of those that agree with it.
    const auto deepest = std::max_element(found.begin(), found.end(), [](const ManifoldCandidates& x, const ManifoldCandidates& y) {
        return deepestOf(x) < deepestOf(y);
    });
    ManifoldCandidates merged;
    merged.normal = deepest->normal;
    for (const ManifoldCandidates& part : found) {
        const Real agreement = part.normal.dot(merged.normal);
        if (agreement < math::cos(kMergeAngle)) continue;
        for (ManifoldPoint point : part.points) {
            point.depth *= agreement;  // along the common normal
            // Two triangles a ball rests on at their seam find the same point: keep it once.
            const auto same = std::find_if(merged.points.begin(), merged.points.end(), [&](const ManifoldPoint& kept) {
                return (kept.pointA - point.pointA).norm() < kSamePoint && (kept.pointB - point.pointB).norm() < kSamePoint;
            });
            if (same == merged.points.end())
                merged.points.push_back(point);
            else if (point.depth > same->depth)
                *same = point;
        }
    }
    int chosen[kMaxManifoldPoints];
    const int count = reduceManifold(merged.points, merged.normal, chosen);
    contact.normal = merged.normal;
    for (int i = 0; i < count; ++i) {
        const ManifoldPoint& candidate = merged.points[static_cast<std::size_t>(chosen[i])];
        if (!candidate.pointA.allFinite() || !candidate.pointB.allFinite() || !std::isfinite(candidate.depth)) continue;
        ContactPoint& point = contact.points[contact.pointCount++];
        point = ContactPoint{};
        point.pointA = candidate.pointA;
        point.pointB = candidate.pointB;
        point.localAnchorA = ta.applyInverse(point.pointA);
        point.localAnchorB = tb.applyInverse(point.pointB);
        point.depth = candidate.depth;
        point.featureId = candidate.featureId;
    }
    (void)previous;  // persistence matches the points afterwards (chapter 6's matchContactPoints)
    result.built = contact.pointCount > 0 && contact.normal.allFinite();
    return result;
}
// [ch13-world-manifold]

PairManifoldFunction worldManifoldFunction(std::shared_ptr<WorldShapesCache> cache) {
    return [cache](const Shape& a, const Transform& ta, const Shape& b, const Transform& tb, Real keepDistance,
                   const Contact* previous, Contact& contact) {
        return worldManifold(*cache, a, ta, b, tb, keepDistance, previous, contact);
    };
}

}  // namespace stepwise
