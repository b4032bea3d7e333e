#include "13_worlds/bench_terrain.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stepwise {

GridTerrain::GridTerrain(const Body& ground) : corner_(ground.transform.position) {
    if (ground.shape.type != ShapeType::Mesh) throw std::invalid_argument("the terrain is not a mesh");
    mesh_ = ground.shape.mesh.get();
    const std::size_t vertices = mesh_->vertices.size();
    const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(vertices))));
    cells_ = side - 1;
    if (cells_ < 1 || static_cast<std::size_t>(side * side) != vertices ||
        mesh_->triangles.size() != 2 * static_cast<std::size_t>(cells_ * cells_))
        throw std::invalid_argument("the terrain is not a square grid mesh (gridMesh)");
    size_ = mesh_->vertices[1].x() - mesh_->vertices[0].x();
    lowest_ = mesh_->bounds.min.y() + corner_.y();
}

bool GridTerrain::covers(Real x, Real z) const {
    const Real u = (x - corner_.x()) / size_, v = (z - corner_.z()) / size_;
    return u >= 0 && v >= 0 && u <= Real(cells_) && v <= Real(cells_);
}

namespace {

/// The grid line at or below `t`, clamped to [0, cells - 1] before it becomes an int: a body flung
/// far away, or a NaN, must not overflow the conversion.
int gridCell(Real t, int cells) {
    const Real line = std::floor(t);
    if (!(line >= 0)) return 0;
    if (!(line <= Real(cells - 1))) return cells - 1;
    return static_cast<int>(line);
}

}  // namespace

Real GridTerrain::heightAt(Real x, Real z, Vec3* normal) const {
    const Real u = (x - corner_.x()) / size_, v = (z - corner_.z()) / size_;
    const int c = gridCell(u, cells_), r = gridCell(v, cells_);
    const auto at = [this](int row, int column) { return mesh_->vertices[std::size_t(row * (cells_ + 1) + column)]; };
    const Vec3 a = at(r, c), b = at(r, c + 1), cRow = at(r + 1, c), d = at(r + 1, c + 1);
    const Real fu = std::clamp(u - Real(c), Real(0), Real(1)), fv = std::clamp(v - Real(r), Real(0), Real(1));
    // Counter-clockwise seen from +y, as gridMesh winds them: (a, d, b) where fu >= fv, else (a, c', d).
    const bool first = fu >= fv;
    if (normal) *normal = (first ? (d - a).cross(b - a) : (cRow - a).cross(d - a)).normalized();
    const Real height = first ? a.y() + fu * (b.y() - a.y()) + fv * (d.y() - b.y())
                              : a.y() + fv * (cRow.y() - a.y()) + fu * (d.y() - cRow.y());
    return height + corner_.y();
}

namespace {

/// How many steps of at most `spacing` cover `length` (at least 1).
int stepsOver(Real length, Real spacing) { return std::max(1, static_cast<int>(std::ceil(length / spacing))); }

/// Points spread evenly over a sphere of `radius` about `center` (Fibonacci lattice, about one per
/// spacing^2 of area), those with y * side >= 0 only when `side` is not 0 (a capsule's ends).
void addSphere(std::vector<Vec3>& out, const Vec3& center, Real radius, Real spacing, int side) {
    const int count = std::max(8, static_cast<int>(std::ceil(4 * kPi * radius * radius / (spacing * spacing))));
    const double golden = 3.14159265358979323846 * (3 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double y = 1 - 2 * (i + 0.5) / count, ring = std::sqrt(1 - y * y), turn = golden * i;
        const Vec3 unit(Real(ring * math::cos(turn)), Real(y), Real(ring * math::sin(turn)));
        if (side * unit.y() >= 0) out.push_back(center + radius * unit);
    }
}

/// Circles of `radius` about the Y axis at heights from -halfHeight to halfHeight (a cylinder's side).
void addSide(std::vector<Vec3>& out, Real radius, Real halfHeight, Real spacing) {
    const int rings = stepsOver(2 * halfHeight, spacing), around = stepsOver(2 * kPi * radius, spacing);
    for (int i = 0; i <= rings; ++i)
        for (int k = 0; k < around; ++k) {
            const Real angle = 2 * kPi * Real(k) / Real(around);
            const Real y = -halfHeight + 2 * halfHeight * Real(i) / Real(rings);
            out.emplace_back(radius * math::cos(angle), y, radius * math::sin(angle));
        }
}

/// A disc of `radius` at height y about the Y axis, as concentric circles (a cylinder's end).
void addDisc(std::vector<Vec3>& out, Real radius, Real y, Real spacing) {
    const int circles = stepsOver(radius, spacing);
    out.emplace_back(0, y, 0);
    for (int i = 1; i <= circles; ++i) {
        const Real rho = radius * Real(i) / Real(circles);
        const int around = stepsOver(2 * kPi * rho, spacing);
        for (int k = 0; k < around; ++k) {
            const Real angle = 2 * kPi * Real(k) / Real(around);
            out.emplace_back(rho * math::cos(angle), y, rho * math::sin(angle));
        }
    }
}

/// A triangle's points on a grid of barycentric steps at most `spacing` apart.
void addTriangle(std::vector<Vec3>& out, const Vec3& a, const Vec3& b, const Vec3& c, Real spacing) {
    const int n = stepsOver(std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()}), spacing);
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) out.push_back(a + Real(i) / Real(n) * (b - a) + Real(j) / Real(n) * (c - a));
}

void addBox(std::vector<Vec3>& out, const Vec3& half, Real spacing) {
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        const int nu = stepsOver(2 * half[u], spacing), nv = stepsOver(2 * half[v], spacing);
        for (const Real sign : {Real(-1), Real(1)})
            for (int i = 0; i <= nu; ++i)
                for (int j = 0; j <= nv; ++j) {
                    Vec3 point;
                    point[axis] = sign * half[axis];
                    point[u] = -half[u] + 2 * half[u] * Real(i) / Real(nu);
                    point[v] = -half[v] + 2 * half[v] * Real(j) / Real(nv);
                    out.push_back(point);
                }
    }
}

}  // namespace

std::vector<Vec3> surfaceSamples(const Shape& shape, Real spacing) {
    std::vector<Vec3> out;
    switch (shape.type) {
        case ShapeType::Box: addBox(out, shape.halfExtents, spacing); break;
        case ShapeType::Sphere: addSphere(out, Vec3::Zero(), shape.radius, spacing, 0); break;
        case ShapeType::Capsule:
            addSide(out, shape.radius, shape.halfHeight, spacing);
            addSphere(out, Vec3(0, shape.halfHeight, 0), shape.radius, spacing, 1);
            addSphere(out, Vec3(0, -shape.halfHeight, 0), shape.radius, spacing, -1);
            break;
        case ShapeType::Cylinder:
            addSide(out, shape.radius, shape.halfHeight, spacing);
            addDisc(out, shape.radius, shape.halfHeight, spacing);
            addDisc(out, shape.radius, -shape.halfHeight, spacing);
            break;
        case ShapeType::Convex:
            for (const HullFace& face : shape.hull->faces)
                for (std::size_t k = 1; k + 1 < face.vertexIndices.size(); ++k)
                    addTriangle(out, shape.hull->vertices[std::size_t(face.vertexIndices[0])],
                                shape.hull->vertices[std::size_t(face.vertexIndices[k])],
                                shape.hull->vertices[std::size_t(face.vertexIndices[k + 1])], spacing);
            break;
        case ShapeType::Compound:
            for (const CompoundChild& child : shape.compound->children)
                for (const Vec3& point : surfaceSamples(child.shape, spacing)) out.push_back(child.transform.apply(point));
            break;
        case ShapeType::Mesh:
        case ShapeType::HeightField: break;  // the ground itself
    }
    return out;
}

Real depthBelow(const GridTerrain& terrain, const std::vector<Vec3>& samples, const Transform& pose) {
    const Mat3 rotation = pose.rotation.normalized().toRotationMatrix();
    Real deepest = 0;
    Vec3 normal;
    for (const Vec3& local : samples) {
        const Vec3 point = pose.position + rotation * local;
        if (!terrain.covers(point.x(), point.z())) continue;
        const Real below = terrain.heightAt(point.x(), point.z(), &normal) - point.y();
        if (below > 0) deepest = std::max(deepest, below * normal.y());  // vertical to perpendicular
    }
    return deepest;
}

void judgeTunnelling(const World& start, const GridTerrain& terrain, const std::vector<Transform>& poses,
                     TerrainJudgement& judgement) {
    for (const Motion& motion : start.motions) {
        const std::size_t i = static_cast<std::size_t>(motion.bodyIndex);
        if (start.bodies[i].type != BodyType::Dynamic) continue;
        const Vec3 center = poses[i].apply(motion.localCenter);
        if (!terrain.covers(center.x(), center.z())) {
            ++judgement.leftTerrain;
            continue;
        }
        const Real reach = maxLeverArm(start.bodies[i].shape, motion.localCenter);
        if (center.y() < terrain.heightAt(center.x(), center.z()) - reach || center.y() < terrain.lowest()) {
            ++judgement.tunnelled;
            judgement.tunnelledNames.push_back(start.bodies[i].name);
        }
    }
}

void judgeDepth(const World& start, const GridTerrain& terrain, const std::vector<std::vector<Vec3>>& samples,
                const std::vector<Transform>& poses, Real bound, TerrainJudgement& judgement) {
    int overBound = 0;
    for (std::size_t i = 0; i < start.bodies.size(); ++i) {
        const Body& body = start.bodies[i];
        if (body.type != BodyType::Dynamic) continue;
        const Real depth = depthBelow(terrain, samples[i], poses[i]);
        overBound += depth > bound ? 1 : 0;
        Real& byShape = judgement.deepestByShape[static_cast<std::size_t>(body.shape.type)];
        byShape = std::max(byShape, depth);
        if (depth <= judgement.deepest) continue;
        judgement.deepest = depth;
        judgement.deepestBody = body.name + " (" + toString(body.shape.type) + ")";
    }
    judgement.mostOverBound = std::max(judgement.mostOverBound, overBound);
}

}  // namespace stepwise
