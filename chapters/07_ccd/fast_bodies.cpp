#include "07_ccd/fast_bodies.h"

#include <algorithm>
#include <cstdio>

namespace stepwise {

Real smallestExtent(const Shape& shape) {
    switch (shape.type) {
        case ShapeType::Box: return Real(2) * shape.halfExtents.minCoeff();
        case ShapeType::Sphere:
        case ShapeType::Capsule: return Real(2) * shape.radius;
        case ShapeType::Convex: {
            Real thinnest = kRealMax;
            for (const HullFace& face : shape.hull->faces) {
                Real deepest = 0;
                for (const Vec3& vertex : shape.hull->vertices) deepest = std::max(deepest, face.offset - face.normal.dot(vertex));
                thinnest = std::min(thinnest, deepest);
            }
            return thinnest == kRealMax ? Real(0) : thinnest;
        }
        case ShapeType::Cylinder: return Real(2) * std::min(shape.radius, shape.halfHeight);
        case ShapeType::Compound: {  // a thin child can tunnel on its own
            Real thinnest = kRealMax;
            for (const CompoundChild& child : shape.compound->children)
                thinnest = std::min(thinnest, smallestExtent(child.shape));
            return thinnest == kRealMax ? Real(0) : thinnest;
        }
        case ShapeType::Mesh:
        case ShapeType::HeightField: return 0;  // static: never fast
    }
    return 0;
}

Real travelPerExtent(const World& world, int body, Real dt) {
    const Motion* motion = world.motionOf(body);
    const Body& shaped = world.bodies[std::size_t(body)];
    if (!motion || shaped.type != BodyType::Dynamic) return 0;
    const Real travel = (motion->linearVelocity.norm() +
                         motion->angularVelocity.norm() * maxLeverArm(shaped.shape, motion->localCenter)) * dt;
    const Real extent = smallestExtent(shaped.shape);
    return extent > 0 ? travel / extent : kRealMax;
}

// [ch07-needs-ccd]
bool needsContinuousCollision(const Body& body, const Sweep& sweep) {
    if (body.type != BodyType::Dynamic) return false;
    return body.bullet || sweepTravel(sweep, body.shape) > kFastTravelFraction * smallestExtent(body.shape);
}
// [ch07-needs-ccd]

static std::string fixed2(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
}

// [ch07-plan]
CcdPlan planContinuousCollision(const World& world) {
    const std::string setting = std::string("settings.ccd is \"") + toString(world.settings.ccd) + "\"";
    if (world.settings.ccd == CcdMode::Off) return {false, "off: " + setting};
    if (world.settings.ccd == CcdMode::On) return {true, "on: " + setting};
    // A body alone hits nothing, however fast (a projectile in the air): the sweeps would only cost.
    if (world.bodies.size() < 2) return {false, "off: auto, one body: nothing to collide with"};
    int bullets = 0;
    int fastest = -1;
    Real fastestTravel = 0;
    const Real dt = world.settings.dt / static_cast<Real>(std::max(1, world.settings.substeps));
    for (std::size_t i = 0; i < world.bodies.size(); ++i) {
        if (world.bodies[i].type != BodyType::Dynamic) continue;
        if (world.bodies[i].bullet) ++bullets;
        const Real travel = travelPerExtent(world, int(i), dt);
        if (fastest < 0 || travel > fastestTravel) fastest = int(i), fastestTravel = travel;
    }
    const std::string line = fixed2(double(kFastTravelFraction)) + " of its smallest extent per step";
    if (bullets > 0) return {true, "auto: " + std::to_string(bullets) + " bullet bod" + (bullets == 1 ? "y" : "ies")};
    if (fastest >= 0 && fastestTravel > kFastTravelFraction)
        return {true, "auto: \"" + world.bodies[std::size_t(fastest)].name + "\" travels " + fixed2(double(fastestTravel)) +
                          " of its smallest extent per step, more than " + fixed2(double(kFastTravelFraction))};
    return {false, "off: auto, no bullet and no body faster than " + line +
                       (fastest >= 0 ? " (fastest: \"" + world.bodies[std::size_t(fastest)].name + "\", " +
                                           fixed2(double(fastestTravel)) + ")"
                                     : " (no dynamic body)")};
}
// [ch07-plan]

}  // namespace stepwise
