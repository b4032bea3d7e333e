#include "06_manifolds/stacking_study.h"

#include "03_epa/chapter.h"
#include "06_manifolds/chapter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace stepwise {

int contactsBeneath(const Body& body) {
    const Real bottom = body.transform.position.y() - body.shape.halfExtents.y();
    return static_cast<int>(std::lround(bottom)) + 1;
}

void applyStackingConfig(World& world, const StackingConfig& config) {
    if (config.iterations) world.settings.solverIterations = *config.iterations;
    if (config.substeps) world.settings.substeps = *config.substeps;
    if (config.warmStarting) world.settings.warmStarting = *config.warmStarting;
    if (config.stabilisation) world.settings.stabilisation = *config.stabilisation;
}

// [ch06-measure]
StackingMeasure measureStacking(World world, const StackingConfig& config, double seconds) {
    applyStackingConfig(world, config);
    Pipeline pipeline = makeChapter06Pipeline(world, config.manifold);
    const std::vector<Body> start = world.bodies;
    StackingMeasure measure;
    int top = -1;
    for (const Motion& motion : world.motions) {
        const int body = motion.bodyIndex;
        if (top < 0 || start[static_cast<std::size_t>(body)].transform.position.y() >
                           start[static_cast<std::size_t>(top)].transform.position.y())
            top = body;
    }
    if (top >= 0) measure.topHeightStart = static_cast<double>(start[static_cast<std::size_t>(top)].transform.position.y());
    const int frames = static_cast<int>(std::lround(seconds / static_cast<double>(world.settings.dt)));
    double totalMs = 0;
    for (int frame = 0; frame < frames; ++frame) {
        const auto begin = std::chrono::steady_clock::now();
        pipeline.step(world);
        totalMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - begin).count();
        if (world.time >= 1) measure.maxPenetration = std::max(measure.maxPenetration, static_cast<double>(measureDeepestPenetration(world)));
        for (const Motion& motion : world.motions) {
            const std::size_t body = static_cast<std::size_t>(motion.bodyIndex);
            const Vec3 moved = world.bodies[body].transform.position - start[body].transform.position;
            const double drift = math::hypot(static_cast<double>(moved.x()), static_cast<double>(moved.z()));
            const double sink = -static_cast<double>(moved.y());
            const int beneath = std::max(1, contactsBeneath(start[body]));
            const double slop = static_cast<double>(world.settings.slop);
            measure.maxDrift = std::max(measure.maxDrift, drift);
            measure.maxSink = std::max(measure.maxSink, sink);
            measure.maxSinkPerContact = std::max(measure.maxSinkPerContact, sink / beneath);
            measure.maxSinkExcess = std::max(measure.maxSinkExcess, sink - slop * beneath);
            if (drift > 0.5 || sink > 0.5) measure.stood = false;
        }
    }
    measure.stepMs = frames > 0 ? totalMs / frames : 0;
    if (top >= 0) measure.topHeightEnd = static_cast<double>(world.bodies[static_cast<std::size_t>(top)].transform.position.y());
    return measure;
}
// [ch06-measure]

}  // namespace stepwise
