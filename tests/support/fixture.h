#pragma once
// A small test context in the spirit of Jolt's PhysicsTestContext: make a world, drop in a
// ground, boxes and spheres, and simulate for some seconds through any chapter's pipeline.
// Header-only and chapter-agnostic, so every suite can use it.
//
//   World world = test::makeWorld();
//   test::addGround(world);
//   const int box = test::addBox(world, Vec3(0, 2, 0), Vec3(0.5, 0.5, 0.5));
//   Pipeline pipeline = makeChapter01Pipeline(world);
//   test::simulate(world, pipeline, 1.0);

#include "world/pipeline.h"
#include "world/world.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace stepwise::test {

/// A world with the given settings (the scene-format defaults when none are given).
inline World makeWorld(const Settings& settings = Settings{}, const std::string& name = "test") {
    World world;
    world.name = name;
    world.settings = settings;
    return world;
}

/// Settings with gravity switched off, for tests about springs or free rotation.
inline Settings zeroGravitySettings() {
    Settings settings;
    settings.gravity = Vec3::Zero();
    return settings;
}

/// A static box whose top face is the plane y = topY. Returns the body index.
inline int addGround(World& world, Real topY = 0, Real halfSize = 50, Real halfThickness = Real(0.5)) {
    return addStaticBox(world, "ground", Vec3(0, topY - halfThickness, 0), Vec3(halfSize, halfThickness, halfSize));
}

/// A box; dynamic bodies get their mass from `density` (kg/m^3) unless `mass` (kg) is > 0.
inline int addBox(World& world, const Vec3& position, const Vec3& halfExtents, BodyType type = BodyType::Dynamic,
                  const Quat& rotation = Quat::Identity(), Real mass = 0, Real density = 1000) {
    BodyDef def;
    def.name = "box" + std::to_string(world.bodies.size());
    def.type = type;
    def.shape = Shape::box(halfExtents);
    def.transform.position = position;
    def.transform.rotation = rotation;
    if (mass > 0) def.mass = mass;
    def.density = density;
    return addBody(world, def);
}

/// A sphere; mass as for addBox.
inline int addSphere(World& world, const Vec3& position, Real radius, BodyType type = BodyType::Dynamic,
                     Real mass = 0, Real density = 1000) {
    BodyDef def;
    def.name = "sphere" + std::to_string(world.bodies.size());
    def.type = type;
    def.shape = Shape::sphere(radius);
    def.transform.position = position;
    if (mass > 0) def.mass = mass;
    def.density = density;
    return addBody(world, def);
}

/// Sets a moving body's velocities (world frame). Does nothing for static bodies.
inline void setVelocity(World& world, int bodyIndex, const Vec3& linear, const Vec3& angular = Vec3::Zero()) {
    if (Motion* motion = world.motionOf(bodyIndex)) {
        motion->linearVelocity = linear;
        motion->angularVelocity = angular;
    }
}

/// Number of frames of settings.dt that make up `seconds` (rounded to the nearest frame).
inline long framesFor(const World& world, double seconds) {
    return std::lround(seconds / static_cast<double>(world.settings.dt));
}

/// Steps the pipeline for `seconds` of simulated time; calls `afterFrame` (when given) after
/// every frame. Returns the number of frames stepped.
inline long simulate(World& world, Pipeline& pipeline, double seconds,
                     const std::function<void(const World&)>& afterFrame = {}) {
    const long frames = framesFor(world, seconds);
    for (long frame = 0; frame < frames; ++frame) {
        pipeline.step(world);
        if (afterFrame) afterFrame(world);
    }
    return frames;
}

/// Chapter 4's head-on collision: a 1 kg ball at 3 m/s meets a 3 kg ball at -0.5 m/s along x, no
/// gravity. Small steps (16 substeps): the overlap at first detection (relative speed times dt)
/// stays below the slop, so Baumgarte adds nothing and the outcome is the restitution law alone.
struct HeadOn {
    World world;
    int light = -1;
    int heavy = -1;
};

inline HeadOn headOnCollision(double restitution) {
    HeadOn headOn{makeWorld(zeroGravitySettings())};
    headOn.world.settings.substeps = 16;
    headOn.light = addSphere(headOn.world, Vec3(-1, 0, 0), Real(0.5), BodyType::Dynamic, 1);
    headOn.heavy = addSphere(headOn.world, Vec3(1, 0, 0), Real(0.5), BodyType::Dynamic, 3);
    for (int body : {headOn.light, headOn.heavy}) headOn.world.bodies[body].material.restitution = static_cast<Real>(restitution);
    setVelocity(headOn.world, headOn.light, Vec3(3, 0, 0));
    setVelocity(headOn.world, headOn.heavy, Vec3(Real(-0.5), 0, 0));
    return headOn;
}

/// A ball's first apex after it bounces: the highest its bottom gets between the first frame it
/// moves up and the first frame it moves down again. Feed it every frame (simulate's afterFrame).
struct FirstApex {
    int body = -1;
    double apex = 0;       // m, height of the body's lowest point (a sphere's bottom)
    bool bounced = false;  // it has moved up
    bool falling = false;  // it has come down again: apex is final

    void record(const World& world) {
        const double bottom = static_cast<double>(world.bodies[body].transform.position.y() - world.bodies[body].shape.radius);
        const double upward = static_cast<double>(world.motionOf(body)->linearVelocity.y());
        if (!bounced && upward > 0) bounced = true;
        if (bounced && !falling) {
            apex = std::max(apex, bottom);
            if (upward < 0) falling = true;
        }
    }
};

}  // namespace stepwise::test
