// The peer's shapes (bullet_shapes.h): convex shapes, compounds, meshes and height fields as
// Bullet's, in Bullet's body frame.

#include "peers/bullet_shapes.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <utility>

namespace stepwise::peers::detail {

namespace {

/// A hull's collision margin, m. btConvexHullShape rounds its hull outward by the margin, so the
/// default 0.04 would make every hull 4 cm fatter than the engine's; 1 mm keeps the geometry
/// within a millimetre. Boxes keep Bullet's default: btBoxShape puts its margin inside the
/// extents (the corners are rounded by 4 cm, the faces are where the engine has them).
constexpr btScalar kHullMargin = btScalar(0.001);

/// A convex shape in the frame whose axes are `axes` and origin `center` in the shape's frame.
/// Only a hull can be built there directly (its points are moved); the others are built in their
/// own frame, and the caller places them (identity `axes` and zero `center` for those).
std::unique_ptr<btCollisionShape> convexShape(const Shape& shape, const Mat3& axes, const Vec3& center) {
    switch (shape.type) {
        case ShapeType::Box: return std::make_unique<btBoxShape>(btVec(shape.halfExtents));
        case ShapeType::Sphere: return std::make_unique<btSphereShape>(btScalar(shape.radius));
        // The engine's capsule runs along its +Y axis, as btCapsuleShape's does; Bullet's height
        // is the segment's whole length.
        case ShapeType::Capsule: return std::make_unique<btCapsuleShape>(btScalar(shape.radius), btScalar(2 * shape.halfHeight));
        case ShapeType::Convex: {
            auto hull = std::make_unique<btConvexHullShape>();
            for (const Vec3& point : shape.hull->vertices) hull->addPoint(btVec(axes.transpose() * (point - center)), false);
            hull->recalcLocalAabb();
            hull->setMargin(kHullMargin);
            return hull;
        }
        // The engine's cylinder runs along +Y, as btCylinderShape's does (half extents r, h, r).
        case ShapeType::Cylinder:
            return std::make_unique<btCylinderShape>(
                btVector3(btScalar(shape.radius), btScalar(shape.halfHeight), btScalar(shape.radius)));
        case ShapeType::Compound:
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;
    }
    return nullptr;
}

btCollisionShape* keep(ShapeStore& store, std::unique_ptr<btCollisionShape> shape) {
    store.shapes.push_back(std::move(shape));
    return store.shapes.back().get();
}

/// A compound's children at their poses seen from Bullet's body frame (the principal frame: the
/// engine's mass and inertia are given to the body, so Bullet's compound computes none).
btCollisionShape* compoundShape(ShapeStore& store, const CompoundShape& compound, const PrincipalFrame& frame) {
    auto made = std::make_unique<btCompoundShape>();
    for (const CompoundChild& child : compound.children) {
        btCollisionShape* shape = keep(store, convexShape(child.shape, Mat3::Identity(), Vec3::Zero()));
        const Mat3 rotation = child.transform.rotation.normalized().toRotationMatrix();
        const Vec3 position = frame.axes.transpose() * (child.transform.position - frame.center);
        made->addChildShape(btPose(frame.axes.transpose() * rotation, position), shape);
    }
    return keep(store, std::move(made));
}

/// A static triangle mesh over arrays the store keeps: Bullet's BVH over the engine's triangles.
/// With `internalEdges`, Bullet's own edge information (btGenerateInternalEdgeInfo), which
/// adjustInternalEdgeContact reads.
btCollisionShape* triangleMeshShape(ShapeStore& store, std::vector<btScalar> vertices, std::vector<int> indices,
                                    bool internalEdges) {
    const int vertexCount = static_cast<int>(vertices.size() / 3), triangleCount = static_cast<int>(indices.size() / 3);
    store.vertices.push_back(std::move(vertices));
    store.indices.push_back(std::move(indices));
    store.meshes.push_back(std::make_unique<btTriangleIndexVertexArray>(
        triangleCount, store.indices.back().data(), int(3 * sizeof(int)), vertexCount, store.vertices.back().data(),
        int(3 * sizeof(btScalar))));
    auto shape = std::make_unique<btBvhTriangleMeshShape>(store.meshes.back().get(), true, true);
    if (internalEdges) {
        store.edgeInfos.push_back(std::make_unique<btTriangleInfoMap>());
        btGenerateInternalEdgeInfo(shape.get(), store.edgeInfos.back().get());
    }
    return keep(store, std::move(shape));
}

btCollisionShape* meshShape(ShapeStore& store, const TriangleMesh& mesh, bool internalEdges) {
    std::vector<btScalar> vertices;
    vertices.reserve(3 * mesh.vertices.size());
    for (const Vec3& vertex : mesh.vertices)
        for (int axis = 0; axis < 3; ++axis) vertices.push_back(btScalar(vertex[axis]));
    std::vector<int> indices;
    indices.reserve(3 * mesh.triangles.size());
    for (const std::array<int, 3>& triangle : mesh.triangles) indices.insert(indices.end(), triangle.begin(), triangle.end());
    return triangleMeshShape(store, std::move(vertices), std::move(indices), internalEdges);
}

bool heightFieldHasHoles(const HeightField& field) {
    return std::any_of(field.heights.begin(), field.heights.end(), [](Real height) { return std::isnan(height); });
}

/// A height field with holes as a triangle mesh: each cell that is not a hole gives the two
/// triangles chapter 13 gives it (height_field_cells.h: split from (r, c) to (r + 1, c + 1), fronts
/// up), and a hole's cell (a NaN at a corner) gives none, so a body falls through it.
btCollisionShape* heightFieldMeshShape(ShapeStore& store, const HeightField& field, bool internalEdges) {
    std::vector<btScalar> vertices;
    vertices.reserve(3 * field.heights.size());
    for (int row = 0; row < field.rows; ++row)
        for (int column = 0; column < field.columns; ++column) {
            const Real height = field.heights[std::size_t(row * field.columns + column)];
            // A hole's grid point is in no triangle; a finite height keeps Bullet's bounds finite.
            vertices.insert(vertices.end(), {btScalar(Real(column) * field.cellSize),
                                             btScalar(std::isnan(height) ? field.lowest : height),
                                             btScalar(Real(row) * field.cellSize)});
        }
    const auto at = [&field](int row, int column) { return row * field.columns + column; };
    const auto hole = [&](int row, int column) {
        return std::isnan(field.heights[std::size_t(at(row, column))]);
    };
    std::vector<int> indices;
    for (int row = 0; row + 1 < field.rows; ++row)
        for (int column = 0; column + 1 < field.columns; ++column) {
            if (hole(row, column) || hole(row, column + 1) || hole(row + 1, column) || hole(row + 1, column + 1)) continue;
            const int a = at(row, column), b = at(row, column + 1), c = at(row + 1, column), d = at(row + 1, column + 1);
            indices.insert(indices.end(), {a, d, b, a, c, d});
        }
    if (indices.empty()) return nullptr;  // every cell a hole
    return triangleMeshShape(store, std::move(vertices), std::move(indices), internalEdges);
}

/// A height field without holes as btHeightfieldTerrainShape: Y up, the quads split along the
/// same diagonal as the engine's (flipQuadEdges: (x, j) to (x + 1, j + 1), x the column, j the row),
/// scaled by the cell size. Bullet centres the grid on its box's middle; `frame.center` is that
/// middle in the engine's frame, so the body's pose puts every grid point where the engine has it.
btCollisionShape* heightFieldShape(ShapeStore& store, const HeightField& field, PrincipalFrame& frame, bool internalEdges) {
    store.heights.emplace_back(field.heights.begin(), field.heights.end());
    const btScalar lowest = btScalar(field.lowest), highest = btScalar(field.highest);
    auto shape = std::make_unique<btHeightfieldTerrainShape>(field.columns, field.rows, store.heights.back().data(), lowest,
                                                             highest, 1, true);
    shape->setLocalScaling(btVector3(btScalar(field.cellSize), 1, btScalar(field.cellSize)));
    // The middle as Bullet computes it (in btScalar), so the offset it subtracts is the one added back.
    const btScalar middle = btScalar(0.5) * (lowest + highest);
    frame.center = Vec3(Real(field.columns - 1) * field.cellSize / 2, Real(middle), Real(field.rows - 1) * field.cellSize / 2);
    if (internalEdges) {
        store.edgeInfos.push_back(std::make_unique<btTriangleInfoMap>());
        btGenerateInternalEdgeInfo(shape.get(), store.edgeInfos.back().get());
    }
    return keep(store, std::move(shape));
}

/// The same contact seen from the other body: the normal reversed, A's points and B's exchanged.
void swapSides(btManifoldPoint& point) {
    point.m_normalWorldOnB = -point.m_normalWorldOnB;
    std::swap(point.m_positionWorldOnA, point.m_positionWorldOnB);
    std::swap(point.m_localPointA, point.m_localPointB);
}

}  // namespace

btMatrix3x3 btMat(const Mat3& m) {
    return btMatrix3x3(btScalar(m(0, 0)), btScalar(m(0, 1)), btScalar(m(0, 2)), btScalar(m(1, 0)), btScalar(m(1, 1)),
                       btScalar(m(1, 2)), btScalar(m(2, 0)), btScalar(m(2, 1)), btScalar(m(2, 2)));
}

Mat3 mat(const btMatrix3x3& m) {
    Mat3 out;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out(r, c) = Real(m[r][c]);
    return out;
}

PrincipalFrame principalFrame(const Motion* motion) {
    PrincipalFrame frame;
    if (!motion) return frame;
    frame.center = motion->localCenter;
    if (motion->mass <= 0) return frame;
    const Mat3 inertia = Real(0.5) * (motion->inertiaLocal + motion->inertiaLocal.transpose());
    const Real offDiagonal = std::max({std::abs(inertia(0, 1)), std::abs(inertia(0, 2)), std::abs(inertia(1, 2))});
    if (offDiagonal <= Real(1e-6) * inertia.trace()) {
        frame.inertia = inertia.diagonal();
        return frame;
    }
    // Eigen-decomposition in double: the principal moments and axes of a symmetric tensor.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia.cast<double>());
    Eigen::Matrix3d axes = solver.eigenvectors();
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2);  // a rotation, not a reflection
    frame.axes = axes.cast<Real>();
    frame.inertia = solver.eigenvalues().cast<Real>();
    return frame;
}

BulletShape makeBodyShape(ShapeStore& store, const Shape& shape, PrincipalFrame& frame, bool internalEdges,
                          const std::string& label) {
    switch (shape.type) {
        case ShapeType::Compound: return {compoundShape(store, *shape.compound, frame), false};
        case ShapeType::Mesh: return {meshShape(store, *shape.mesh, internalEdges), internalEdges};
        case ShapeType::HeightField: {
            const HeightField& field = *shape.heightField;
            if (!heightFieldHasHoles(field)) return {heightFieldShape(store, field, frame, internalEdges), internalEdges};
            btCollisionShape* mesh = heightFieldMeshShape(store, field, internalEdges);
            if (!mesh) throw BulletUnsupported(label + ".shape (heightfield): every cell has a hole: nothing for Bullet to collide");
            return {mesh, internalEdges};
        }
        case ShapeType::Convex:  // hull points straight into the principal frame: no compound needed
            return {keep(store, convexShape(shape, frame.axes, frame.center)), false};
        case ShapeType::Box:
        case ShapeType::Sphere:
        case ShapeType::Capsule:
        case ShapeType::Cylinder: break;
    }
    btCollisionShape* own = keep(store, convexShape(shape, Mat3::Identity(), Vec3::Zero()));
    if (frame.identity()) return {own, false};
    // The shape's origin seen from the principal frame.
    auto compound = std::make_unique<btCompoundShape>();
    compound->addChildShape(btPose(frame.axes.transpose(), -(frame.axes.transpose() * frame.center)), own);
    return {keep(store, std::move(compound)), false};
}

bool adjustInternalEdgeContact(btManifoldPoint& point, const btCollisionObjectWrapper* a, int partA, int indexA,
                               const btCollisionObjectWrapper* b, int partB, int indexB) {
    // Bullet's utility reads the point as the triangle's B side (m_localPointB on the triangle,
    // m_normalWorldOnB pointing from it to the other body). The manifold's A is whichever body
    // the broadphase met first, often the ground: then the point is turned round for the call.
    if (b->getCollisionShape()->getShapeType() == TRIANGLE_SHAPE_PROXYTYPE) {
        btAdjustInternalEdgeContacts(point, b, a, partB, indexB);
    } else if (a->getCollisionShape()->getShapeType() == TRIANGLE_SHAPE_PROXYTYPE) {
        swapSides(point);
        btAdjustInternalEdgeContacts(point, a, b, partA, indexA);
        swapSides(point);
    }
    return true;  // Bullet ignores the value
}

}  // namespace stepwise::peers::detail
