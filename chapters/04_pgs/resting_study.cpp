#include "04_pgs/resting_study.h"

#include "03_epa/narrowphase.h"
#include "04_pgs/scenes.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

double RestingRun::minDepth(int fromFrame) const { return *std::min_element(depth.begin() + fromFrame, depth.end()); }

double RestingRun::maxDepth(int fromFrame) const { return *std::max_element(depth.begin() + fromFrame, depth.end()); }

double RestingRun::drift(int fromFrame) const {
    const Vec3 offset = position.back() - position[fromFrame];
    return math::hypot(static_cast<double>(offset.x()), static_cast<double>(offset.z()));
}

RestingRun runRestingStudy(const RestingSetup& setup, int frames) {
    World world = emptyWorld("resting");
    world.settings.substeps = setup.substeps;
    addGroundPlane(world);
    int body = -1;   // the body whose overlap with `below` is recorded
    const int below = 0;
    const Real drop = setup.drop;
    const Vec3 start(0, Real(0.5) + drop, 0);
    if (setup.subject == RestingSubject::Ball) body = addBall(world, "ball", start, Real(0.5), 1, Material{});
    if (setup.subject == RestingSubject::Box)
        body = addCrate(world, "box", start, Vec3(Real(0.5), Real(0.5), Real(0.5)), 1, Material{});
    if (setup.subject == RestingSubject::Stack) {
        body = addBall(world, "light", Vec3(0, Real(0.4) + drop, 0), Real(0.4), 1, Material{});
        addBall(world, "heavy", Vec3(0, Real(1.2) + 2 * drop, 0), Real(0.4), 10, Material{});
    }
    Pipeline pipeline = makeChapter04Pipeline(world, setup.order);
    RestingRun run;
    const char* names[] = {"ball", "box, one point", "1 kg under 10 kg"};
    const bool split = setup.order == StepOrder::SplitIntegration;
    run.label = std::string(names[static_cast<int>(setup.subject)]) +
                (split ? (setup.subject == RestingSubject::Ball ? ", split" : "") : ", integrate first");
    for (int frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        const Body& lower = world.bodies[below];
        const Body& moving = world.bodies[body];
        const ContactQuery query = collideShapes(lower.shape, lower.transform, moving.shape, moving.transform);
        run.depth.push_back(query.intersect ? static_cast<double>(query.depth) : 0.0);
        const Vec3 up = moving.transform.rotate(Vec3::UnitY());
        run.tilt.push_back(math::acos(std::clamp(static_cast<double>(up.y()), -1.0, 1.0)));
        run.position.push_back(moving.transform.position);
    }
    return run;
}

}  // namespace stepwise
