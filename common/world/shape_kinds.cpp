// The shapes of worlds to stand on (chapter 13): cylinders, compounds, triangle meshes and height
// fields, as data: how they are built and checked, their mass properties and their boxes. How
// bodies collide with them is chapter 13's.
#include "world/contact_round.h"
#include "world/shape.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace stepwise {

namespace {

std::string triangleName(std::size_t index) { return "triangle " + std::to_string(index); }

// A triangle whose area is this small a fraction of its longest edge squared has no normal a
// float can trust (a sliver or a repeated corner).
constexpr Real kDegenerateTriangle = Real(1e-7);

}  // namespace

Shape Shape::cylinder(Real radius, Real halfHeight) {
    Shape shape;
    shape.type = ShapeType::Cylinder;
    shape.radius = radius;
    shape.halfHeight = halfHeight;
    return shape;
}

Shape Shape::compoundOf(std::vector<CompoundChild> children) {
    if (children.empty()) throw ShapeError("a compound needs at least one child");
    auto compound = std::make_shared<CompoundShape>();
    for (std::size_t i = 0; i < children.size(); ++i) {
        const CompoundChild& child = children[i];
        const std::string name = "child " + std::to_string(i);
        if (!isConvexKind(child.shape.type))
            throw ShapeError(name + " is a " + toString(child.shape.type) +
                             "; a compound's children are convex (box, sphere, capsule, convex, cylinder)");
        if (!child.transform.position.allFinite() || !child.transform.rotation.coeffs().allFinite())
            throw ShapeError(name + " has a pose that is not finite");
        compound->vertexRadius =
            std::max(compound->vertexRadius, child.transform.position.norm() + boundingRadius(child.shape));
    }
    for (CompoundChild& child : children) child.transform.rotation.normalize();
    compound->children = std::move(children);
    Shape shape;
    shape.type = ShapeType::Compound;
    shape.compound = std::move(compound);
    return shape;
}

Shape Shape::triangleMesh(std::vector<Vec3> vertices, std::vector<std::array<int, 3>> triangles) {
    if (triangles.empty()) throw ShapeError("a mesh needs at least one triangle");
    auto mesh = std::make_shared<TriangleMesh>();
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (!vertices[i].allFinite()) throw ShapeError("vertex " + std::to_string(i) + " is not finite");
        mesh->bounds.grow(vertices[i]);
        mesh->vertexRadius = std::max(mesh->vertexRadius, vertices[i].norm());
    }
    const int count = static_cast<int>(vertices.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
        const std::array<int, 3>& corners = triangles[t];
        for (int corner : corners)
            if (corner < 0 || corner >= count)
                throw ShapeError(triangleName(t) + " names vertex " + std::to_string(corner) + " of " +
                                 std::to_string(count));
        const Vec3& a = vertices[static_cast<std::size_t>(corners[0])];
        const Vec3& b = vertices[static_cast<std::size_t>(corners[1])];
        const Vec3& c = vertices[static_cast<std::size_t>(corners[2])];
        const Real longest = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
        if (!((b - a).cross(c - a).norm() > kDegenerateTriangle * longest))
            throw ShapeError(triangleName(t) + " is degenerate (its corners are on one line)");
    }
    mesh->vertices = std::move(vertices);
    mesh->triangles = std::move(triangles);
    Shape shape;
    shape.type = ShapeType::Mesh;
    shape.mesh = std::move(mesh);
    return shape;
}

Shape Shape::heightFieldOf(int rows, int columns, Real cellSize, std::vector<Real> heights) {
    if (rows < 2 || columns < 2) throw ShapeError("a height field needs at least 2 rows and 2 columns");
    if (!(cellSize > 0) || !std::isfinite(cellSize)) throw ShapeError("cell_size must be > 0");
    if (heights.size() != static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns))
        throw ShapeError("has " + std::to_string(heights.size()) + " heights; rows * columns is " +
                         std::to_string(static_cast<long long>(rows) * columns));
    auto field = std::make_shared<HeightField>();
    bool any = false;
    for (std::size_t i = 0; i < heights.size(); ++i) {
        const Real height = heights[i];
        if (std::isinf(height)) throw ShapeError("height " + std::to_string(i) + " is infinite");
        if (std::isnan(height)) continue;  // a hole
        field->lowest = any ? std::min(field->lowest, height) : height;
        field->highest = any ? std::max(field->highest, height) : height;
        any = true;
    }
    if (!any) throw ShapeError("every height is a hole");
    field->rows = rows;
    field->columns = columns;
    field->cellSize = cellSize;
    field->heights = std::move(heights);
    Shape shape;
    shape.type = ShapeType::HeightField;
    shape.heightField = std::move(field);
    return shape;
}

Aabb transformedBox(const Aabb& local, const Transform& transform) {
    Aabb box;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 point((corner & 1) ? local.max.x() : local.min.x(), (corner & 2) ? local.max.y() : local.min.y(),
                         (corner & 4) ? local.max.z() : local.min.z());
        box.grow(transform.apply(point));
    }
    return box;
}

Aabb heightFieldBounds(const HeightField& field) {
    Aabb box;
    box.min = Vec3(0, field.lowest, 0);
    box.max = Vec3(static_cast<Real>(field.columns - 1) * field.cellSize, field.highest,
                   static_cast<Real>(field.rows - 1) * field.cellSize);
    return box;
}

Real compoundVolume(const CompoundShape& compound) {
    Real volume = 0;
    for (const CompoundChild& child : compound.children) volume += shapeVolume(child.shape);
    return volume;
}

// [common-compound-mass]
MassProperties compoundMassProperties(const CompoundShape& compound, Real density) {
    // In double: a table's legs are a thousandth of its top's inertia about its own centre, and
    // the sum should be exact to float rounding once cast back.
    using Vector = Eigen::Vector3d;  // not Vec3d: shape.cpp's alias, and unity builds join the files
    using Matrix = Eigen::Matrix3d;
    double mass = 0;
    Vector weighted = Vector::Zero();
    std::vector<MassProperties> parts;
    for (const CompoundChild& child : compound.children) {
        parts.push_back(computeMassProperties(child.shape, density));
        const Vector center = child.transform.apply(parts.back().localCenter).cast<double>();
        mass += parts.back().mass;
        weighted += double(parts.back().mass) * center;
    }
    MassProperties props;
    if (!(mass > 0)) return props;
    const Vector centerOfMass = weighted / mass;
    Matrix inertia = Matrix::Zero();
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const CompoundChild& child = compound.children[i];
        const Matrix rotation = child.transform.rotation.toRotationMatrix().cast<double>();
        const Vector offset = child.transform.apply(parts[i].localCenter).cast<double>() - centerOfMass;
        inertia += rotation * parts[i].inertia.cast<double>() * rotation.transpose() +
                   double(parts[i].mass) * (offset.squaredNorm() * Matrix::Identity() - offset * offset.transpose());
    }
    props.mass = static_cast<Real>(mass);
    props.localCenter = centerOfMass.cast<Real>();
    props.inertia = inertia.cast<Real>();
    return props;
}
// [common-compound-mass]

Real contactRoundRadius(const Shape& shape, const Transform& pose, const Vec3& normal) {
    if (isRound(shape)) return shape.radius;
    if (shape.type != ShapeType::Cylinder) return 0;
    return std::abs(pose.rotate(Vec3::UnitY()).dot(normal)) < kRollingSideCosine ? shape.radius : Real(0);
}

}  // namespace stepwise
