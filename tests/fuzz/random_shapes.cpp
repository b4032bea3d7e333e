#include "random_shapes.h"

#include <array>
#include <limits>

#include <algorithm>
#include <cmath>
#include <vector>

namespace stepwise::fuzz {

namespace {

using Vec3d = Eigen::Vector3d;

Vec3d randomPointInCube(FuzzInput& input) {
    return input.vector(-1, 1);
}

/// 4 to 64 points in one of the hard families a hull builder and GJK/EPA meet in practice.
std::vector<Vec3d> hullPoints(FuzzInput& input) {
    const int count = input.integer(4, 64);
    const int family = input.integer(0, 5);
    std::vector<Vec3d> points;
    switch (family) {
    case 0:  // a plain cloud
        for (int i = 0; i < count; ++i) points.push_back(randomPointInCube(input));
        break;
    case 1: {  // a plate: one axis 1e-4..1e-1 of the others
        const double thickness = input.logUniform(1e-4, 1e-1);
        for (int i = 0; i < count; ++i) points.push_back(randomPointInCube(input).cwiseProduct(Vec3d(1, thickness, 1)));
        break;
    }
    case 2: {  // a needle: two axes 1e-2..1e-1 of the third. Thinner needles (1e-3) still defeat GJK
               // near their axis: it stops on a flat tetrahedron and answers "separated" for an
               // overlap (docs/reliability.md, "What the fuzzers found"), a known open case.
        const double width = input.logUniform(1e-2, 1e-1);
        for (int i = 0; i < count; ++i) points.push_back(randomPointInCube(input).cwiseProduct(Vec3d(width, 1, width)));
        break;
    }
    case 3: {  // duplicates: half the points repeated exactly or within 1e-7
        const int unique = std::max(4, count / 2);
        for (int i = 0; i < unique; ++i) points.push_back(randomPointInCube(input));
        const double jitter = input.flag() ? 0.0 : 1e-7;
        for (int i = unique; i < count; ++i) {
            const Vec3d copy = points[std::size_t(input.integer(0, unique - 1))];
            points.push_back(copy + jitter * randomPointInCube(input));
        }
        break;
    }
    case 4: {  // nearly coplanar: points on the faces of a cube, off their plane by up to 1e-6..1e-3
        const double offPlane = input.logUniform(1e-6, 1e-3);
        for (int i = 0; i < count; ++i) {
            Vec3d point = randomPointInCube(input);
            const int axis = input.integer(0, 2);
            const double side = input.flag() ? 1 : -1;
            point[axis] = side * (1 + offPlane * input.uniform(-1, 1));
            points.push_back(point);
        }
        break;
    }
    default:  // on a sphere: many faces, nearly parallel neighbours
        for (int i = 0; i < count; ++i) {
            Vec3d point = randomPointInCube(input);
            if (point.norm() < 1e-3) point = Vec3d(1, 0, 0);
            points.push_back(point.normalized());
        }
        break;
    }
    return points;
}

}  // namespace

Quat randomRotation(FuzzInput& input) {
    const Eigen::Vector3d xyz = input.vector(-1, 1);
    Eigen::Vector4d q(xyz.x(), xyz.y(), xyz.z(), input.uniform(-1, 1));
    if (q.norm() < 1e-3) q = Eigen::Vector4d(0, 0, 0, 1);
    q.normalize();
    return Quat(Real(q.w()), Real(q.x()), Real(q.y()), Real(q.z())).normalized();
}

std::optional<Shape> randomShape(FuzzInput& input, double size) {
    switch (input.integer(0, 4)) {
    case 0: {
        const double x = size * input.logUniform(0.01, 1);
        const double y = size * input.logUniform(0.01, 1);
        const double z = size * input.logUniform(0.01, 1);
        const Vec3 halfExtents = Vec3(Real(x), Real(y), Real(z));
        return Shape::box(halfExtents);
    }
    case 1: return Shape::sphere(Real(size));
    case 2: {
        const double radius = size * input.logUniform(0.01, 1);
        return Shape::capsule(Real(radius), Real(size * input.logUniform(0.01, 1)));
    }
    case 3: {  // a can, from a flat disc to a tall thin rod
        const double radius = size * input.logUniform(0.01, 1);
        return Shape::cylinder(Real(radius), Real(size * input.logUniform(0.01, 1)));
    }
    default: {
        std::vector<Vec3> points;
        for (const Vec3d& point : hullPoints(input)) points.push_back((size * point).cast<Real>());
        try {
            return Shape::convex(points);
        } catch (const HullError&) {
            return std::nullopt;
        }
    }
    }
}

std::optional<Shape> randomBodyShape(FuzzInput& input, double size) {
    if (input.integer(0, 5) != 0) return randomShape(input, size);
    // A compound of two or three convex children at random offsets and turns, touching or apart.
    std::vector<CompoundChild> children;
    const int count = input.integer(2, 3);
    for (int i = 0; i < count; ++i) {
        const std::optional<Shape> child = randomShape(input, size * input.uniform(0.2, 0.7));
        if (!child) continue;
        CompoundChild placed;
        placed.shape = *child;
        placed.transform.position = (size * input.vector(-0.6, 0.6)).cast<Real>();
        placed.transform.rotation = randomRotation(input);
        children.push_back(placed);
    }
    try {
        return Shape::compoundOf(children);
    } catch (const ShapeError&) {
        return std::nullopt;  // no children left, refused correctly
    }
}

std::optional<Shape> randomGround(FuzzInput& input) {
    const int kind = input.integer(0, 2);
    if (kind == 0) return std::nullopt;  // the caller's box
    // A 12 x 12 grid of 1..5 m cells over a 60 m square, heights up to +-amplitude, smooth or spiky.
    const int cells = 12;
    const double cell = input.uniform(1, 5);
    const double amplitude = input.logUniform(0.001, 3);
    std::vector<Real> heights;
    for (int i = 0; i < (cells + 1) * (cells + 1); ++i) heights.push_back(Real(amplitude * input.uniform(-1, 1)));
    try {
        if (kind == 1) {
            std::vector<Vec3> vertices;
            std::vector<std::array<int, 3>> triangles;
            for (int r = 0; r <= cells; ++r)
                for (int c = 0; c <= cells; ++c)
                    vertices.emplace_back(Real(c * cell), heights[std::size_t(r * (cells + 1) + c)], Real(r * cell));
            for (int r = 0; r < cells; ++r)
                for (int c = 0; c < cells; ++c) {
                    const int a = r * (cells + 1) + c, below = a + cells + 1;
                    triangles.push_back({a, below + 1, a + 1});
                    triangles.push_back({a, below, below + 1});
                }
            return Shape::triangleMesh(std::move(vertices), std::move(triangles));
        }
        for (Real& height : heights)
            if (input.integer(0, 15) == 0) height = std::numeric_limits<Real>::quiet_NaN();  // a hole
        return Shape::heightFieldOf(cells + 1, cells + 1, Real(cell), std::move(heights));
    } catch (const ShapeError&) {
        return std::nullopt;  // refused correctly (every height a hole)
    }
}

double signedDistance(const Shape& shape, const Eigen::Vector3d& p) {
    switch (shape.type) {
    case ShapeType::Sphere: return p.norm() - double(shape.radius);
    case ShapeType::Capsule: {
        const double h = double(shape.halfHeight);
        const Vec3d onSegment(0, std::clamp(p.y(), -h, h), 0);
        return (p - onSegment).norm() - double(shape.radius);
    }
    case ShapeType::Box: {
        const Vec3d q = p.cwiseAbs() - shape.halfExtents.cast<double>();
        return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
    }
    case ShapeType::Convex: {
        double distance = -1e300;
        for (const HullFace& face : shape.hull->faces)
            distance = std::max(distance, face.normal.cast<double>().dot(p) - double(face.offset));
        return distance;
    }
    case ShapeType::Cylinder: {  // the box's formula in (radial, axial) coordinates
        const Eigen::Vector2d q(std::hypot(p.x(), p.z()) - double(shape.radius), std::abs(p.y()) - double(shape.halfHeight));
        return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
    }
    case ShapeType::Compound:
    case ShapeType::Mesh:
    case ShapeType::HeightField: break;  // the fuzzers draw convex shapes
    }
    return 0;
}

}  // namespace stepwise::fuzz
