#pragma once
// Collision shapes and their exact mass properties. Every shape is centred on its body's
// origin except a convex hull, whose centre of mass is wherever its vertices put it.

#include "math/math.h"

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace stepwise {

/// The convex kinds (box, sphere, capsule, convex hull; the cylinder from chapter 13) move; a
/// compound is a rigid set of convex children; meshes and height fields are the static ground
/// (chapter 13), never on a body that moves.
enum class ShapeType { Box, Sphere, Capsule, Convex, Cylinder, Compound, Mesh, HeightField };
/// How many kinds there are (tables indexed by ShapeType).
constexpr int kShapeTypeCount = static_cast<int>(ShapeType::HeightField) + 1;

/// One face of a convex hull: a planar polygon, counter-clockwise seen from outside.
struct HullFace {
    std::vector<int> vertexIndices;
    Vec3 normal = Vec3::Zero();  // outward unit normal
    Real offset = 0;             // plane: dot(normal, x) = offset
};

/// A convex polyhedron: the hull of the points it was built from (interior points dropped).
struct ConvexHull {
    std::vector<Vec3> vertices;
    std::vector<HullFace> faces;
    /// The largest distance of a vertex from the origin, m: buildConvexHull sets it once, because
    /// the broadphase and the speculative margin ask for it every step.
    Real vertexRadius = 0;
};

constexpr int kMaxHullPoints = 128;

struct HullError : std::runtime_error {
    explicit HullError(const std::string& reason) : std::runtime_error(reason), message(reason) {}
    std::string message;
};

/// Builds the hull of a point cloud. Throws HullError when the points do not span a volume
/// (fewer than 4 points, all coplanar, non-finite) or exceed kMaxHullPoints.
ConvexHull buildConvexHull(const std::vector<Vec3>& points);

/// Static level geometry: triangles over shared vertices, body frame. A triangle's front is where
/// its corners run counter-clockwise; contacts push bodies out of its front.
struct TriangleMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    Aabb bounds;              // of the vertices, body frame
    Real vertexRadius = 0;    // largest distance of a vertex from the origin, m
};

/// A grid of heights, body frame: the surface's y at x = c * cellSize, z = r * cellSize is
/// heights[r * columns + c]. A NaN height is a hole: the cells around it have no surface. Each
/// cell is two triangles split along the diagonal from (r, c) to (r + 1, c + 1).
struct HeightField {
    int rows = 0;
    int columns = 0;
    Real cellSize = 1;
    std::vector<Real> heights;
    Real lowest = 0, highest = 0;  // over the heights that are not holes
};

/// What a mesh, a height field or a compound can be refused for: the reason names the
/// triangle, the height or the child.
struct ShapeError : std::runtime_error {
    explicit ShapeError(const std::string& reason) : std::runtime_error(reason) {}
};

struct CompoundShape;
struct CompoundChild;

struct Shape {
    ShapeType type = ShapeType::Sphere;
    Vec3 halfExtents = Vec3::Zero();          // box
    Real radius = 0;                          // sphere, capsule, cylinder
    Real halfHeight = 0;                      // capsule: half the segment length along +Y; cylinder: half its height along +Y
    std::shared_ptr<const ConvexHull> hull;   // convex
    std::shared_ptr<const CompoundShape> compound;
    std::shared_ptr<const TriangleMesh> mesh;
    std::shared_ptr<const HeightField> heightField;

    static Shape box(const Vec3& halfExtents);
    static Shape sphere(Real radius);
    static Shape capsule(Real radius, Real halfHeight);
    static Shape convex(const std::vector<Vec3>& points);
    static Shape cylinder(Real radius, Real halfHeight);
    /// Throws ShapeError: no children, a child that is not convex (a compound, a mesh, a height
    /// field), a non-finite child pose.
    static Shape compoundOf(std::vector<CompoundChild> children);
    /// Throws ShapeError: no triangles, an index out of range, a triangle of (nearly) zero area,
    /// a non-finite vertex.
    static Shape triangleMesh(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles);
    /// Throws ShapeError: fewer than 2 rows or columns, a count of heights other than rows *
    /// columns, a cell size that is not positive, an infinite height, no height that is not a hole.
    static Shape heightFieldOf(int rows, int columns, Real cellSize, std::vector<Real> heights);
};

/// One child of a compound: a convex shape at a pose in the compound body's frame.
struct CompoundChild {
    Shape shape;
    Transform transform;
};

struct CompoundShape {
    std::vector<CompoundChild> children;
    Real vertexRadius = 0;  // farthest a child's point reaches from the body's origin, m
};

/// Whether the shape is one that moves with a body: not a mesh or a height field.
inline bool canMove(const Shape& shape) { return shape.type != ShapeType::Mesh && shape.type != ShapeType::HeightField; }

/// Whether the shape is a single convex set (what GJK and EPA take).
inline bool isConvexKind(ShapeType type) {
    return type == ShapeType::Box || type == ShapeType::Sphere || type == ShapeType::Capsule ||
           type == ShapeType::Convex || type == ShapeType::Cylinder;
}

const char* toString(ShapeType type);

struct MassProperties {
    Real mass = 0;
    Vec3 localCenter = Vec3::Zero();   // centre of mass in the body frame
    Mat3 inertia = Mat3::Zero();       // about the centre of mass, body axes
};

/// `outer` after `inner`: a child's pose in the world from its body's pose and its own in the body.
inline Transform compose(const Transform& outer, const Transform& inner) {
    Transform result;
    result.position = outer.apply(inner.position);
    result.rotation = outer.rotation * inner.rotation;
    return result;
}

/// The world box of a body-frame box under a transform (its eight corners'; exact when the
/// transform does not turn).
Aabb transformedBox(const Aabb& local, const Transform& transform);

/// A height field's box in its body's frame.
Aabb heightFieldBounds(const HeightField& field);

/// A compound's volume: its children's, summed (children that overlap count twice, as their mass
/// does).
Real compoundVolume(const CompoundShape& compound);

/// A compound's mass properties at a uniform density: each child's mass at its centre, each
/// child's inertia turned into the body's axes and moved to the common centre of mass
/// (parallel-axis theorem, I + m (|d|^2 1 - d d^T)).
MassProperties compoundMassProperties(const CompoundShape& compound, Real density);

/// Volume of the shape in m^3.
Real shapeVolume(const Shape& shape);

/// Exact mass properties for a uniform density (kg/m^3). Hulls are split into tetrahedra
/// and summed through their covariance matrices (Blow and Binstock 2004, "How to find the
/// inertia tensor (or other mass properties) of a 3D solid body represented by a triangle
/// mesh"), which is exact for polyhedra.
MassProperties computeMassProperties(const Shape& shape, Real density);

/// The world-space box that bounds the shape placed at a transform.
Aabb computeAabb(const Shape& shape, const Transform& transform);

/// Radius of the smallest origin-centred sphere holding the shape (for CCD and culling).
Real boundingRadius(const Shape& shape);

/// Farthest a point of the shape can be from the centre of mass at `localCenter` (body frame):
/// the origin's ball, boundingRadius, grown by the centre's offset |c|. The lever arm of every
/// bound on how fast the body's points move: a body's velocity is its centre of mass's, and it
/// turns about that centre, so an arm measured from the origin alone falls short for a shape
/// whose mass sits off its origin (most hulls).
Real maxLeverArm(const Shape& shape, const Vec3& localCenter);

/// Whether the shape is round: a sphere or a capsule, a core (a point, a segment) grown by its
/// radius. A point on a round surface does not turn with its body (a rolling ball's lowest point
/// stays lowest).
inline bool isRound(const Shape& shape) { return shape.type == ShapeType::Sphere || shape.type == ShapeType::Capsule; }

/// How far the surface lies outside the core: a round shape's radius, 0 for shapes with corners.
inline Real roundRadius(const Shape& shape) { return isRound(shape) ? shape.radius : Real(0); }

}  // namespace stepwise
