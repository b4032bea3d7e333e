// Figures for chapter 13, drawn from the engine's own structures: a mesh's tree over a patch of
// terrain and the triangles one body's box finds, and the seam between two floor triangles with
// the normal a box's corner gets there, with the internal-edge correction off and on.
#include "figures.h"

#include "13_worlds/scenes.h"
#include "13_worlds/world_manifold.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace figures {

using namespace stepwise;

namespace {

Point2 topDown(const Vec3& p) { return {static_cast<double>(p.x()), static_cast<double>(-p.z())}; }

/// A 6 x 4 patch of gently uneven ground, two triangles a tile.
Shape patch() {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> triangles;
    constexpr int kColumns = 6, kRows = 4;
    for (int row = 0; row <= kRows; ++row)
        for (int column = 0; column <= kColumns; ++column)
            vertices.emplace_back(Real(column), Real(0.1) * std::sin(Real(column + 2 * row)), Real(row));
    const auto at = [](int row, int column) { return row * (kColumns + 1) + column; };
    for (int row = 0; row < kRows; ++row)
        for (int column = 0; column < kColumns; ++column) {
            triangles.push_back({at(row, column), at(row + 1, column + 1), at(row, column + 1)});
            triangles.push_back({at(row, column), at(row + 1, column), at(row + 1, column + 1)});
        }
    return Shape::triangleMesh(std::move(vertices), std::move(triangles));
}

void boxOutline(Svg& svg, const Viewport& view, const Aabb& box, const std::string& style) {
    svg.polygon(view,
                {topDown(Vec3(box.min.x(), 0, box.min.z())), topDown(Vec3(box.max.x(), 0, box.min.z())),
                 topDown(Vec3(box.max.x(), 0, box.max.z())), topDown(Vec3(box.min.x(), 0, box.max.z()))},
                style);
}

}  // namespace

bool drawMeshTree(const std::string& path) {
    const Shape mesh = patch();
    const MeshTree tree = buildMeshTree(*mesh.mesh);
    Svg svg(680, 420);
    Viewport view{20, 40, 640, 360, {3, -2}, 95};
    // The query: a body's box, grown, and the triangles the tree hands back.
    Aabb body;
    body.min = Vec3(Real(2.3), -1, Real(1.2));
    body.max = Vec3(Real(3.4), 1, Real(2.1));
    std::vector<int> found;
    queryMeshTree(tree, *mesh.mesh, body, found);
    const auto& vertices = mesh.mesh->vertices;
    for (std::size_t t = 0; t < mesh.mesh->triangles.size(); ++t) {
        const auto& c = mesh.mesh->triangles[t];
        const bool hit = std::find(found.begin(), found.end(), static_cast<int>(t)) != found.end();
        svg.polygon(view, {topDown(vertices[static_cast<std::size_t>(c[0])]), topDown(vertices[static_cast<std::size_t>(c[1])]),
                           topDown(vertices[static_cast<std::size_t>(c[2])])},
                    std::string("stroke:#999;stroke-width:1;fill:") + (hit ? "#ffd27f" : "none"));
    }
    // The tree's boxes, level by level: each level's colour a step lighter.
    const char* colours[] = {"#1f3b73", "#2f6db5", "#4f9fd8", "#8cc7ea", "#bfe0f3", "#dff0fa"};
    std::vector<std::pair<int, int>> stack = {{0, 0}};
    while (!stack.empty()) {
        const auto [node, level] = stack.back();
        stack.pop_back();
        const MeshTreeNode& n = tree.nodes[static_cast<std::size_t>(node)];
        const double inset = 0.03 * level;  // nested boxes drawn a little inside their parent's
        Aabb box = n.box;
        box.min += Vec3(Real(inset), 0, Real(inset));
        box.max -= Vec3(Real(inset), 0, Real(inset));
        boxOutline(svg, view, box, std::string("fill:none;stroke-width:2;stroke:") + colours[std::min(level, 5)]);
        if (n.triangleCount == 0) {
            stack.push_back({node + 1, level + 1});
            stack.push_back({n.secondChild, level + 1});
        }
    }
    boxOutline(svg, view, body, "fill:none;stroke:#c0392b;stroke-width:3;stroke-dasharray:6,4");
    svg.textAt({20, 24}, "The tree over 48 triangles, seen from above: its boxes (dark: near the root), a body's box "
                         "(red, dashed) and the " + std::to_string(found.size()) + " triangles it finds (orange)");
    return svg.save(path);
}

bool drawSeamNormals(const std::string& path) {
    // Two floor tiles meeting at x = 1; a box tipped 20 degrees nose down has its lowest edge 2 mm
    // past the seam and 4 mm below the floor: it touches the right triangle's prism alone.
    const Shape floor = tiledFloor(2, 1);
    const Shape box = Shape::box(Vec3(Real(0.3), Real(0.3), Real(0.3)));
    Transform boxPose;
    boxPose.rotation = Quat(Eigen::AngleAxis<Real>(Real(-20) * kPi / 180, Vec3::UnitZ()));
    const Vec3 nose = boxPose.rotation * Vec3(Real(0.3), Real(-0.3), 0);  // the lowest edge, from the centre
    boxPose.position = Vec3(Real(1.002), Real(-0.004), Real(0.5)) - nose;
    Vec3 normals[2];
    for (int fixed = 0; fixed < 2; ++fixed) {
        WorldShapesCache cache;
        cache.internalEdgeFix = fixed == 1;
        Contact contact;
        worldManifold(cache, floor, Transform{}, box, boxPose, Real(0.02), nullptr, contact);
        normals[fixed] = contact.normal;
    }
    Svg svg(680, 360);
    Viewport view{20, 40, 640, 300, {Real(1.0), Real(0.0)}, 1400};
    const auto side = [](Real x, Real y) { return Point2{static_cast<double>(x), static_cast<double>(y)}; };
    // The two prisms, side on, reaching kPrismDepth below the floor (cut at the figure's edge).
    svg.polygon(view, {side(Real(0.75), 0), side(1, 0), side(1, Real(-0.1)), side(Real(0.75), Real(-0.1))},
                "fill:#e8e8e8;stroke:#777;stroke-width:2");
    svg.polygon(view, {side(1, 0), side(Real(1.25), 0), side(Real(1.25), Real(-0.1)), side(1, Real(-0.1))},
                "fill:#f3f3f3;stroke:#777;stroke-width:2");
    // The box's lower right part, as its turned outline.
    std::vector<Point2> outline;
    for (const Vec3& local : {Vec3(Real(0.05), Real(-0.3), 0), Vec3(Real(0.3), Real(-0.3), 0), Vec3(Real(0.3), Real(-0.2), 0),
                              Vec3(Real(0.05), Real(-0.2), 0)}) {
        const Vec3 at = boxPose.apply(local);
        outline.push_back(side(at.x(), at.y()));
    }
    svg.polygon(view, outline, "fill:#cfe3f7;stroke:#2f6db5;stroke-width:2");
    const Vec3 lowest = boxPose.position + nose;
    const Point2 corner = side(lowest.x(), lowest.y());
    const auto tip = [&](const Vec3& n) { return Point2{corner.x + 0.05 * n.x(), corner.y + 0.05 * n.y()}; };  // along the push on the box
    svg.arrow(view, corner, tip(normals[0]), "#c0392b", 3);
    svg.arrow(view, corner, tip(normals[1]), "#27ae60", 3);
    svg.text(view, side(Real(0.77), Real(-0.02)), "left triangle's prism");
    svg.text(view, side(Real(1.02), Real(-0.02)), "right triangle's prism");
    svg.textAt({20, 24}, "A box tipped 20 degrees, its edge 2 mm past the seam and 4 mm deep: the right prism's side "
                         "pushes it back (red) unless the seam is inactive (green)");
    return svg.save(path);
}

}  // namespace figures
