#include "09_debug/hit_tree.h"

#include <cmath>
#include <cstdio>

namespace stepwise {

int HitTree::pointCount() const {
    int count = 0;
    for (const HitPair& pair : pairs)
        for (const HitManifold& manifold : pair.manifolds) count += static_cast<int>(manifold.points.size());
    return count;
}

HitTree buildHitTree(const World& world) {
    HitTree tree;
    for (const Contact& contact : world.contacts) {
        if (contact.pointCount <= 0) continue;
        HitPair pair;
        pair.bodyA = contact.bodyA;
        pair.bodyB = contact.bodyB;
        pair.nameA = world.bodies[static_cast<std::size_t>(contact.bodyA)].name;
        pair.nameB = world.bodies[static_cast<std::size_t>(contact.bodyB)].name;
        HitManifold manifold;
        manifold.normal = contact.normal;
        for (int i = 0; i < contact.pointCount; ++i) {
            const ContactPoint& source = contact.points[i];
            HitPoint point;
            point.pointA = source.pointA;
            point.pointB = source.pointB;
            point.position = Real(0.5) * (source.pointA + source.pointB);
            point.depth = source.depth;
            point.normalImpulse = source.normalImpulse;
            point.tangentImpulse[0] = source.tangentImpulse[0];
            point.tangentImpulse[1] = source.tangentImpulse[1];
            point.featureId = source.featureId;
            point.persisted = source.persisted;
            manifold.points.push_back(point);
        }
        pair.manifolds.push_back(std::move(manifold));
        tree.pairs.push_back(std::move(pair));
    }
    return tree;
}

const HitPoint* selectedPoint(const HitTree& tree, const HitSelection& selection) {
    if (selection.pair < 0 || selection.pair >= static_cast<int>(tree.pairs.size())) return nullptr;
    const HitPair& pair = tree.pairs[static_cast<std::size_t>(selection.pair)];
    if (selection.manifold < 0 || selection.manifold >= static_cast<int>(pair.manifolds.size())) return nullptr;
    const HitManifold& manifold = pair.manifolds[static_cast<std::size_t>(selection.manifold)];
    if (selection.point < 0 || selection.point >= static_cast<int>(manifold.points.size())) return nullptr;
    return &manifold.points[static_cast<std::size_t>(selection.point)];
}

HitSelection pickHitPoint(const HitTree& tree, const Ray& ray, Real radius) {
    HitSelection best;
    Real bestAlong = kRealMax;
    const Vec3 direction = ray.direction.normalized();
    for (int p = 0; p < static_cast<int>(tree.pairs.size()); ++p) {
        const HitPair& pair = tree.pairs[static_cast<std::size_t>(p)];
        for (int m = 0; m < static_cast<int>(pair.manifolds.size()); ++m) {
            const HitManifold& manifold = pair.manifolds[static_cast<std::size_t>(m)];
            for (int i = 0; i < static_cast<int>(manifold.points.size()); ++i) {
                const Vec3 offset = manifold.points[static_cast<std::size_t>(i)].position - ray.origin;
                const Real along = offset.dot(direction);
                if (along < 0 || along > ray.maxDistance) continue;
                // Nearest to the eye among the points the ray passes close to: the one in front.
                if ((offset - along * direction).norm() <= radius && along < bestAlong) {
                    bestAlong = along;
                    best = HitSelection{p, m, i};
                }
            }
        }
    }
    return best;
}

HitSelection findPair(const HitTree& tree, int bodyA, int bodyB) {
    for (int p = 0; p < static_cast<int>(tree.pairs.size()); ++p) {
        const HitPair& pair = tree.pairs[static_cast<std::size_t>(p)];
        if ((pair.bodyA == bodyA && pair.bodyB == bodyB) || (pair.bodyA == bodyB && pair.bodyB == bodyA))
            return HitSelection{p, -1, -1};
    }
    return HitSelection{};
}

std::string describePair(const HitPair& pair) {
    int points = 0;
    for (const HitManifold& manifold : pair.manifolds) points += static_cast<int>(manifold.points.size());
    return pair.nameA + " / " + pair.nameB + " (" + std::to_string(points) + (points == 1 ? " point)" : " points)");
}

std::string describeManifold(const HitManifold& manifold) {
    char text[96];
    std::snprintf(text, sizeof text, "normal (%.3f, %.3f, %.3f)", double(manifold.normal.x()), double(manifold.normal.y()),
                  double(manifold.normal.z()));
    return text;
}

std::string describePoint(int index, const HitPoint& point) {
    char text[160];
    std::snprintf(text, sizeof text, "#%d %s %.2f mm, impulse %.3g N s, friction (%.3g, %.3g)%s", index,
                  point.depth >= 0 ? "depth" : "gap", std::abs(double(point.depth)) * 1000.0, double(point.normalImpulse),
                  double(point.tangentImpulse[0]), double(point.tangentImpulse[1]), point.persisted ? ", persisted" : "");
    return text;
}

}  // namespace stepwise
