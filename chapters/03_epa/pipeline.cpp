// The narrowphase stage of chapter 3 and the penetration probe of run reports.
#include "03_epa/chapter.h"

#include "02_gjk/chapter.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace stepwise {

namespace {

bool canCollide(const Body& a, const Body& b) {
    // Two static bodies never need a contact: nothing could respond to it (as in chapter 2).
    return a.type != BodyType::Static || b.type != BodyType::Static;
}

std::vector<Aabb> bodyBounds(const World& world) {
    std::vector<Aabb> bounds(world.bodies.size());
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        bounds[i] = computeAabb(world.bodies[i].shape, world.bodies[i].transform);
    }
    return bounds;
}

}  // namespace

// [ch03-stage]
int findContacts(World& world, const CollideOptions& options) {
    world.pairs.clear();
    world.contacts.clear();
    CollideOptions stageOptions = options;
    stageOptions.separationDistance = false;  // the solver has no use for the distance of a miss
    const std::vector<Aabb> bounds = bodyBounds(world);
    int queries = 0;
    const int bodyCount = static_cast<int>(world.bodies.size());
    for (int i = 0; i < bodyCount; ++i) {
        for (int j = i + 1; j < bodyCount; ++j) {
            const Body& bodyA = world.bodies[i];
            const Body& bodyB = world.bodies[j];
            // Boxes that do not overlap rule the pair out for the price of six comparisons;
            // chapter 5 replaces this loop over all pairs with a broadphase.
            if (!canCollide(bodyA, bodyB) || !bounds[i].overlaps(bounds[j])) continue;
            ++queries;
            const ContactQuery query =
                collideShapes(bodyA.shape, bodyA.transform, bodyB.shape, bodyB.transform, stageOptions);
            if (!query.intersect) continue;
            world.pairs.push_back(BodyPair{i, j});
            Contact contact;
            contact.bodyA = i;
            contact.bodyB = j;
            contact.normal = query.normal;
            contact.points[0].pointA = query.pointA;
            contact.points[0].pointB = query.pointB;
            contact.points[0].depth = query.depth;
            contact.pointCount = 1;
            world.contacts.push_back(contact);
        }
    }
    return queries;
}

Pipeline makeChapter03Pipeline(const World& world) {
    Pipeline pipeline = makeChapter02Pipeline(world);
    Stage stage;
    // Plan from the scene: the name says which routines this world will use.
    stage.name = allPairsClosedForm(world) ? "narrowphase:closed_form" : "narrowphase:gjk_epa";
    stage.run = [](World& stepWorld, Real) { findContacts(stepWorld); };
    if (Stage* previous = pipeline.find("narrowphase")) {
        *previous = std::move(stage);
    } else {
        pipeline.add(std::move(stage));
    }
    return pipeline;
}
// [ch03-stage]

bool allPairsClosedForm(const World& world) {
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        for (std::size_t j = i + 1; j < world.bodies.size(); ++j) {
            const Body& a = world.bodies[i];
            const Body& b = world.bodies[j];
            if (canCollide(a, b) && !hasClosedForm(a.shape.type, b.shape.type)) return false;
        }
    }
    return true;
}

Real measureDeepestPenetration(const World& world) {
    // Sweep along x: sorted by the boxes' lower x, a body only needs testing against the bodies
    // that start before it ends, so a run report does not pay for all n^2 pairs every frame.
    const std::vector<Aabb> bounds = bodyBounds(world);
    std::vector<int> order(world.bodies.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return bounds[a].min.x() < bounds[b].min.x(); });
    CollideOptions options;
    options.separationDistance = false;
    Real deepest = 0;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const int i = order[k];
        for (std::size_t m = k + 1; m < order.size() && bounds[order[m]].min.x() <= bounds[i].max.x(); ++m) {
            const int j = order[m];
            const Body& a = world.bodies[std::min(i, j)];
            const Body& b = world.bodies[std::max(i, j)];
            if (!canCollide(a, b) || !bounds[i].overlaps(bounds[j])) continue;
            const ContactQuery query = collideShapes(a.shape, a.transform, b.shape, b.transform, options);
            if (query.intersect) deepest = std::max(deepest, query.depth);
        }
    }
    return deepest;
}

}  // namespace stepwise
