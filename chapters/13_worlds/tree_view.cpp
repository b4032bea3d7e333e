#include "13_worlds/tree_view.h"

#include <algorithm>

namespace stepwise {

namespace {

void collectLevel(const MeshTree& tree, int node, int depth, int level, std::vector<Aabb>& boxes) {
    const MeshTreeNode& at = tree.nodes[node];
    const bool leaf = at.secondChild < 0;
    if (depth == level || leaf) {  // never deeper: the walk stops at the level
        boxes.push_back(at.box);
        return;
    }
    collectLevel(tree, node + 1, depth + 1, level, boxes);
    collectLevel(tree, at.secondChild, depth + 1, level, boxes);
}

/// Twelve lines, not DebugDraw::box: lines keep their world ends in a recording, so the demo's
/// screenshot test can look for them where they are drawn.
void drawBoxEdges(DebugDraw& draw, const Transform& pose, const Aabb& box, Color color) {
    const auto corner = [&](int bits) {
        return pose.apply(Vec3((bits & 1) ? box.max.x() : box.min.x(), (bits & 2) ? box.max.y() : box.min.y(),
                               (bits & 4) ? box.max.z() : box.min.z()));
    };
    for (int bits = 0; bits < 8; ++bits)
        for (int axis = 1; axis < 8; axis <<= 1)
            if (!(bits & axis)) draw.line(corner(bits), corner(bits | axis), color);
}

Color levelColor(int level) {
    const float t = std::min(1.0f, static_cast<float>(level) / 12.0f);
    return Color{0.55f + 0.45f * t, 0.1f + 0.8f * t, 0.1f, 1.0f};
}

}  // namespace

std::vector<Aabb> meshTreeLevelBoxes(const MeshTree& tree, int level) {
    std::vector<Aabb> boxes;
    if (!tree.nodes.empty() && level >= 0) collectLevel(tree, 0, 0, level, boxes);
    return boxes;
}

void drawMeshTreeLevel(DebugDraw& draw, const World& world, int level, WorldShapesCache& cache) {
    const Color color = levelColor(level);
    for (const Body& body : world.bodies) {
        if (body.shape.type != ShapeType::Mesh || !body.shape.mesh) continue;
        const MeshTree& tree = cache.entry(body.shape.mesh).tree;
        for (const Aabb& box : meshTreeLevelBoxes(tree, level)) drawBoxEdges(draw, body.transform, box, color);
    }
}

}  // namespace stepwise
