#include "13_worlds/chapter.h"

#include <memory>
#include <string>

namespace stepwise {

std::string worldShapesNote(const World& world) {
    int counts[4] = {0, 0, 0, 0};  // meshes, height fields, compounds, cylinders
    long triangles = 0;
    for (const Body& body : world.bodies) {
        switch (body.shape.type) {
            case ShapeType::Mesh:
                ++counts[0];
                triangles += static_cast<long>(body.shape.mesh->triangles.size());
                break;
            case ShapeType::HeightField: ++counts[1]; break;
            case ShapeType::Compound: ++counts[2]; break;
            case ShapeType::Cylinder: ++counts[3]; break;
            default: break;
        }
    }
    if (counts[0] + counts[1] + counts[2] + counts[3] == 0) return "";
    return std::to_string(counts[0]) + " mesh(es) of " + std::to_string(triangles) + " triangles, " +
           std::to_string(counts[1]) + " height field(s), " + std::to_string(counts[2]) + " compound(s), " +
           std::to_string(counts[3]) + " cylinder(s): collided part by part";
}

Pipeline makeChapter13Pipeline(const World& world) { return makeChapter13Pipeline(world, WorldOptions{}); }

// [ch13-pipeline]
Pipeline makeChapter13Pipeline(const World& world, const WorldOptions& options) {
    const std::string note = worldShapesNote(world);
    if (note.empty()) {  // nothing of this chapter's: chapter 12's step, bit for bit
        Pipeline pipeline = makeChapter12Pipeline(world, options.speed);
        pipeline.setPlanNote(stage_group::kWorldShapes, "left out: no mesh, height field, compound or cylinder");
        return pipeline;
    }
    auto cache = std::make_shared<WorldShapesCache>();
    cache->internalEdgeFix = options.internalEdgeFix && world.settings.activeEdges;
    SpeedOptions speed = options.speed;
    speed.pairManifold = worldManifoldFunction(cache);
    Pipeline pipeline = makeChapter12Pipeline(world, speed);
    // The meshes' trees, built before the first narrowphase needs them (once: a mesh never changes).
    Stage trees;
    trees.name = stageName(stage_group::kWorldShapes, "parts");
    // Settings::activeEdges is read every step, so the demo's checkbox takes effect at once.
    const bool edgeFix = options.internalEdgeFix;
    trees.run = [cache, edgeFix](World& stepWorld, Real) {
        cache->internalEdgeFix = edgeFix && stepWorld.settings.activeEdges;
        for (const Body& body : stepWorld.bodies)
            if (body.shape.type == ShapeType::Mesh) cache->entry(body.shape.mesh);
    };
    pipeline.insertBefore(stage_group::kNarrowphase, std::move(trees));
    pipeline.setPlanNote(stage_group::kWorldShapes,
                         note + (cache->internalEdgeFix ? "; internal edges corrected" : "; internal edges not corrected"));
    return pipeline;
}
// [ch13-pipeline]

}  // namespace stepwise
