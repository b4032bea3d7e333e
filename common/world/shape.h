#pragma once
// Collision shapes and their exact mass properties. Every shape is centred on its body's
// origin except a convex hull, whose centre of mass is wherever its vertices put it.

#include "math/math.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace stepwise {

enum class ShapeType { Box, Sphere, Capsule, Convex };

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

struct Shape {
    ShapeType type = ShapeType::Sphere;
    Vec3 halfExtents = Vec3::Zero();          // box
    Real radius = 0;                          // sphere, capsule
    Real halfHeight = 0;                      // capsule: half the segment length along +Y
    std::shared_ptr<const ConvexHull> hull;   // convex

    static Shape box(const Vec3& halfExtents);
    static Shape sphere(Real radius);
    static Shape capsule(Real radius, Real halfHeight);
    static Shape convex(const std::vector<Vec3>& points);
};

const char* toString(ShapeType type);

struct MassProperties {
    Real mass = 0;
    Vec3 localCenter = Vec3::Zero();   // centre of mass in the body frame
    Mat3 inertia = Mat3::Zero();       // about the centre of mass, body axes
};

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
