#include "world/shape.h"

#include "world/enum_names.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stepwise {

namespace {

using Vec3d = Eigen::Vector3d;
using Mat3d = Eigen::Matrix3d;

struct Plane {
    Vec3d normal;
    double offset;
};

// Orders the points of one face counter-clockwise around its outward normal and drops the
// ones inside the face polygon (Andrew's monotone chain in the face's own 2D basis).
std::vector<int> orderFacePolygon(const std::vector<Vec3d>& points, const std::vector<int>& onPlane,
                                  const Vec3d& normal) {
    const Vec3d axisU = std::abs(normal.x()) > 0.57 ? Vec3d(normal.y(), -normal.x(), 0).normalized()
                                                     : Vec3d(0, normal.z(), -normal.y()).normalized();
    const Vec3d axisV = normal.cross(axisU);
    struct Projected {
        double u, v;
        int index;
    };
    std::vector<Projected> projected;
    for (int index : onPlane) projected.push_back({points[index].dot(axisU), points[index].dot(axisV), index});
    std::sort(projected.begin(), projected.end(),
              [](const Projected& a, const Projected& b) { return a.u < b.u || (a.u == b.u && a.v < b.v); });
    auto cross = [](const Projected& o, const Projected& a, const Projected& b) {
        return (a.u - o.u) * (b.v - o.v) - (a.v - o.v) * (b.u - o.u);
    };
    std::vector<Projected> chain(2 * projected.size());
    size_t count = 0;
    for (size_t i = 0; i < projected.size(); ++i) {  // lower chain
        while (count >= 2 && cross(chain[count - 2], chain[count - 1], projected[i]) <= 0) --count;
        chain[count++] = projected[i];
    }
    for (size_t i = projected.size() - 1, lower = count + 1; i-- > 0;) {  // upper chain
        while (count >= lower && cross(chain[count - 2], chain[count - 1], projected[i]) <= 0) --count;
        chain[count++] = projected[i];
    }
    std::vector<int> polygon;
    for (size_t i = 0; i + 1 < count; ++i) polygon.push_back(chain[i].index);
    return polygon;  // counter-clockwise about axisU x axisV = normal
}

}  // namespace

// Brute force over point triples: a triple spans a hull face plane when every point lies on
// one side of it. O(n^4) at build time, which is why hulls are capped at kMaxHullPoints; the
// simplicity buys exact coplanar-face merging, which quickhull needs extra care for.
ConvexHull buildConvexHull(const std::vector<Vec3>& inputPoints) {
    const int count = static_cast<int>(inputPoints.size());
    if (count < 4) throw HullError("needs at least 4 points, got " + std::to_string(count));
    if (count > kMaxHullPoints)
        throw HullError("has " + std::to_string(count) + " points; at most " + std::to_string(kMaxHullPoints) + " are supported");
    std::vector<Vec3d> points;
    for (int i = 0; i < count; ++i) {
        if (!inputPoints[i].allFinite()) throw HullError("point " + std::to_string(i) + " is not finite");
        points.push_back(inputPoints[i].cast<double>());
    }
    Vec3d low = points[0], high = points[0];
    for (const Vec3d& point : points) low = low.cwiseMin(point), high = high.cwiseMax(point);
    const double size = (high - low).maxCoeff();
    if (!(size > 0)) throw HullError("all points coincide");
    const double tolerance = 1e-6 * size;

    std::vector<Plane> planes;
    for (int i = 0; i < count; ++i)
        for (int j = i + 1; j < count; ++j)
            for (int k = j + 1; k < count; ++k) {
                Vec3d normal = (points[j] - points[i]).cross(points[k] - points[i]);
                if (normal.norm() < 1e-9 * size * size) continue;
                normal.normalize();
                const double offset = normal.dot(points[i]);
                bool anyAbove = false, anyBelow = false;
                for (int m = 0; m < count && !(anyAbove && anyBelow); ++m) {
                    const double distance = normal.dot(points[m]) - offset;
                    anyAbove |= distance > tolerance;
                    anyBelow |= distance < -tolerance;
                }
                if (anyAbove && anyBelow) continue;
                if (!anyAbove && !anyBelow) throw HullError("points are coplanar: they span no volume");
                const Plane plane = anyAbove ? Plane{-normal, -offset} : Plane{normal, offset};
                const bool known = std::any_of(planes.begin(), planes.end(), [&](const Plane& other) {
                    return other.normal.dot(plane.normal) > 1 - 1e-9 && std::abs(other.offset - plane.offset) < tolerance;
                });
                if (!known) planes.push_back(plane);
            }
    if (planes.size() < 4) throw HullError("points are coplanar: they span no volume");

    ConvexHull hull;
    std::vector<int> remap(count, -1);
    for (const Plane& plane : planes) {
        std::vector<int> onPlane;
        for (int m = 0; m < count; ++m)
            if (std::abs(plane.normal.dot(points[m]) - plane.offset) <= tolerance) onPlane.push_back(m);
        HullFace face;
        for (int index : orderFacePolygon(points, onPlane, plane.normal)) {
            if (remap[index] < 0) {
                remap[index] = static_cast<int>(hull.vertices.size());
                hull.vertices.push_back(inputPoints[index]);
            }
            face.vertexIndices.push_back(remap[index]);
        }
        if (face.vertexIndices.size() < 3) continue;  // a sliver plane through an edge
        face.normal = plane.normal.cast<Real>();
        face.offset = static_cast<Real>(plane.offset);
        hull.faces.push_back(std::move(face));
    }
    for (const Vec3& vertex : hull.vertices) hull.vertexRadius = std::max(hull.vertexRadius, vertex.norm());
    return hull;
}

Shape Shape::box(const Vec3& halfExtents) {
    Shape shape;
    shape.type = ShapeType::Box;
    shape.halfExtents = halfExtents;
    return shape;
}

Shape Shape::sphere(Real radius) {
    Shape shape;
    shape.type = ShapeType::Sphere;
    shape.radius = radius;
    return shape;
}

Shape Shape::capsule(Real radius, Real halfHeight) {
    Shape shape;
    shape.type = ShapeType::Capsule;
    shape.radius = radius;
    shape.halfHeight = halfHeight;
    return shape;
}

Shape Shape::convex(const std::vector<Vec3>& points) {
    Shape shape;
    shape.type = ShapeType::Convex;
    shape.hull = std::make_shared<const ConvexHull>(buildConvexHull(points));
    return shape;
}

const char* toString(ShapeType type) {
    static const Names<ShapeType> names = {
        {"box", ShapeType::Box},           {"sphere", ShapeType::Sphere},   {"capsule", ShapeType::Capsule},
        {"convex", ShapeType::Convex},     {"cylinder", ShapeType::Cylinder}, {"compound", ShapeType::Compound},
        {"mesh", ShapeType::Mesh},         {"heightfield", ShapeType::HeightField}};
    return nameOf(names, type);
}

namespace {

struct HullIntegrals {
    double volume = 0;
    Vec3d center = Vec3d::Zero();
    Mat3d covariance = Mat3d::Zero();  // integral of x x^T dV about the centre, unit density
};

// Each face is fanned into triangles, each triangle with the reference point makes a
// tetrahedron; the canonical tetrahedron's covariance is mapped through the linear map that
// takes it to each tetrahedron (Blow and Binstock 2004).
HullIntegrals integrateHull(const ConvexHull& hull) {
    Vec3d reference = Vec3d::Zero();
    for (const Vec3& vertex : hull.vertices) reference += vertex.cast<double>();
    reference /= static_cast<double>(hull.vertices.size());

    Mat3d canonical;
    canonical << 2, 1, 1, 1, 2, 1, 1, 1, 2;
    canonical /= 120.0;

    HullIntegrals result;
    Vec3d weightedCenter = Vec3d::Zero();
    Mat3d covariance = Mat3d::Zero();
    for (const HullFace& face : hull.faces) {
        const Vec3d first = hull.vertices[face.vertexIndices[0]].cast<double>() - reference;
        for (size_t i = 1; i + 1 < face.vertexIndices.size(); ++i) {
            Mat3d edges;
            edges.col(0) = first;
            edges.col(1) = hull.vertices[face.vertexIndices[i]].cast<double>() - reference;
            edges.col(2) = hull.vertices[face.vertexIndices[i + 1]].cast<double>() - reference;
            const double determinant = edges.determinant();
            const double volume = determinant / 6.0;
            result.volume += volume;
            weightedCenter += volume * (edges.col(0) + edges.col(1) + edges.col(2)) / 4.0;
            covariance += determinant * edges * canonical * edges.transpose();
        }
    }
    const Vec3d centerFromReference = weightedCenter / result.volume;
    result.center = reference + centerFromReference;
    result.covariance = covariance - result.volume * centerFromReference * centerFromReference.transpose();
    return result;
}

}  // namespace

Real shapeVolume(const Shape& shape) {
    switch (shape.type) {
        case ShapeType::Box: return 8 * shape.halfExtents.prod();
        case ShapeType::Sphere: return Real(4.0 / 3.0) * kPi * shape.radius * shape.radius * shape.radius;
        case ShapeType::Capsule:
            return kPi * shape.radius * shape.radius * (2 * shape.halfHeight + Real(4.0 / 3.0) * shape.radius);
        case ShapeType::Convex: return static_cast<Real>(integrateHull(*shape.hull).volume);
        case ShapeType::Cylinder: return 2 * kPi * shape.radius * shape.radius * shape.halfHeight;
        case ShapeType::Compound: return compoundVolume(*shape.compound);
        case ShapeType::Mesh:
        case ShapeType::HeightField: return 0;  // a surface, not a solid: static only
    }
    return 0;
}

MassProperties computeMassProperties(const Shape& shape, Real density) {
    MassProperties props;
    switch (shape.type) {
        case ShapeType::Box: {
            props.mass = density * shapeVolume(shape);
            const Vec3 squared = shape.halfExtents.cwiseProduct(shape.halfExtents);
            props.inertia.diagonal() = props.mass / 3 * Vec3(squared.y() + squared.z(), squared.x() + squared.z(),
                                                             squared.x() + squared.y());
            break;
        }
        case ShapeType::Sphere:
            props.mass = density * shapeVolume(shape);
            props.inertia.diagonal().setConstant(Real(0.4) * props.mass * shape.radius * shape.radius);
            break;
        case ShapeType::Capsule: {
            // A cylinder plus two hemispheres; each hemisphere's centre of mass sits 3r/8 from
            // its flat face, which the parallel-axis term below accounts for.
            const double radius = shape.radius, height = 2.0 * shape.halfHeight;
            const double cylinderMass = density * 3.14159265358979323846 * radius * radius * height;
            const double sphereMass = density * 4.0 / 3.0 * 3.14159265358979323846 * radius * radius * radius;
            const double axial = cylinderMass * radius * radius / 2 + sphereMass * 0.4 * radius * radius;
            const double transverse = cylinderMass * (radius * radius / 4 + height * height / 12) +
                                      sphereMass * (0.4 * radius * radius + height * height / 4 + 3 * height * radius / 8);
            props.mass = static_cast<Real>(cylinderMass + sphereMass);
            props.inertia.diagonal() = Vec3d(transverse, axial, transverse).cast<Real>();
            break;
        }
        case ShapeType::Convex: {
            const HullIntegrals integrals = integrateHull(*shape.hull);
            props.mass = static_cast<Real>(density * integrals.volume);
            props.localCenter = integrals.center.cast<Real>();
            const Mat3d covariance = density * integrals.covariance;
            props.inertia = (covariance.trace() * Mat3d::Identity() - covariance).cast<Real>();
            break;
        }
        case ShapeType::Cylinder: {
            // I_axis = m r^2 / 2, I_across = m (3 r^2 + (2h)^2) / 12.
            const double radius = shape.radius, height = 2.0 * shape.halfHeight;
            const double mass = density * 3.14159265358979323846 * radius * radius * height;
            const double across = mass * (3 * radius * radius + height * height) / 12;
            props.mass = static_cast<Real>(mass);
            props.inertia.diagonal() = Vec3d(across, mass * radius * radius / 2, across).cast<Real>();
            break;
        }
        case ShapeType::Compound: return compoundMassProperties(*shape.compound, density);
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // no mass: static only
    }
    return props;
}

Aabb computeAabb(const Shape& shape, const Transform& transform) {
    Aabb box;
    switch (shape.type) {
        case ShapeType::Box: {
            const Mat3 rotation = transform.rotation.toRotationMatrix();
            const Vec3 reach = rotation.cwiseAbs() * shape.halfExtents;
            box.min = transform.position - reach;
            box.max = transform.position + reach;
            break;
        }
        case ShapeType::Sphere:
            box.min = transform.position - Vec3::Constant(shape.radius);
            box.max = transform.position + Vec3::Constant(shape.radius);
            break;
        case ShapeType::Capsule: {
            const Vec3 tip = transform.rotate(Vec3(0, shape.halfHeight, 0)).cwiseAbs() + Vec3::Constant(shape.radius);
            box.min = transform.position - tip;
            box.max = transform.position + tip;
            break;
        }
        case ShapeType::Convex:
            for (const Vec3& vertex : shape.hull->vertices) box.grow(transform.apply(vertex));
            break;
        case ShapeType::Cylinder: {
            // Along world axis i the disc of radius r reaches r sqrt(1 - a_i^2), a the axis.
            const Vec3 axis = transform.rotate(Vec3::UnitY());
            const Vec3 disc = (Vec3::Ones() - axis.cwiseProduct(axis)).cwiseMax(Real(0)).cwiseSqrt();
            const Vec3 reach = shape.halfHeight * axis.cwiseAbs() + shape.radius * disc;
            box.min = transform.position - reach;
            box.max = transform.position + reach;
            break;
        }
        case ShapeType::Compound:
            for (const CompoundChild& child : shape.compound->children)
                box.grow(computeAabb(child.shape, compose(transform, child.transform)));
            break;
        case ShapeType::Mesh: box = transformedBox(shape.mesh->bounds, transform); break;
        case ShapeType::HeightField: box = transformedBox(heightFieldBounds(*shape.heightField), transform); break;
    }
    return box;
}

Real boundingRadius(const Shape& shape) {
    switch (shape.type) {
        case ShapeType::Box: return shape.halfExtents.norm();
        case ShapeType::Sphere: return shape.radius;
        case ShapeType::Capsule: return shape.halfHeight + shape.radius;
        case ShapeType::Convex: return shape.hull ? shape.hull->vertexRadius : 0;
        case ShapeType::Cylinder: return math::hypot(shape.radius, shape.halfHeight);
        case ShapeType::Compound: return shape.compound ? shape.compound->vertexRadius : 0;
        case ShapeType::Mesh: return shape.mesh ? shape.mesh->vertexRadius : 0;
        case ShapeType::HeightField: {
            if (!shape.heightField) return 0;
            const Aabb bounds = heightFieldBounds(*shape.heightField);
            return bounds.min.cwiseAbs().cwiseMax(bounds.max.cwiseAbs()).norm();
        }
    }
    return 0;
}

Real maxLeverArm(const Shape& shape, const Vec3& localCenter) { return boundingRadius(shape) + localCenter.norm(); }

}  // namespace stepwise
