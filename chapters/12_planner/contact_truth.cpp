// The reported contact depths against the shapes' true overlap (contact_truth.h).
#include "12_planner/contact_truth.h"

#include "03_epa/narrowphase.h"

#include <algorithm>

namespace stepwise {

ContactDepthErrors contactDepthErrors(const World& world) {
    ContactDepthErrors errors;
    for (const Contact& contact : world.contacts) {
        if (contact.pointCount == 0) continue;
        const Body& a = world.bodies[static_cast<std::size_t>(contact.bodyA)];
        const Body& b = world.bodies[static_cast<std::size_t>(contact.bodyB)];
        if (!isValidShape(a.shape) || !isValidShape(b.shape)) continue;  // not one convex set
        Real reported = -kRealMax;
        for (int i = 0; i < contact.pointCount; ++i) reported = std::max(reported, contact.points[i].depth);
        const ContactQuery truth = collideShapes(a.shape, a.transform, b.shape, b.transform);
        const Real overlap = std::max(Real(0), truth.depth);
        if (reported > 0) errors.deeper = std::max(errors.deeper, reported - overlap);
        if (overlap > 0) errors.shallower = std::max(errors.shallower, overlap - reported);
    }
    return errors;
}

ContactDepthErrors depthAgainstTrue(const World& start, const SpeedOptions& options, long frames) {
    World world = start;
    Pipeline pipeline = makeChapter12Pipeline(world, options);
    ContactDepthErrors worst;
    Stage check;
    check.name = "check:contact_depths";
    check.frequency = StageFrequency::FrameStart;
    check.run = [&worst](World& checked, Real) {
        const ContactDepthErrors errors = contactDepthErrors(checked);
        worst.deeper = std::max(worst.deeper, errors.deeper);
        worst.shallower = std::max(worst.shallower, errors.shallower);
    };
    pipeline.insertBefore(pipeline.find(stage_group::kPlan) ? stage_group::kPlan : stage_group::kSolve, check);
    for (long frame = 0; frame < frames; ++frame) pipeline.step(world);
    return worst;
}

}  // namespace stepwise
