#include "09_debug/scenes.h"

#include "04_pgs/scenes.h"
#include "app/registry.h"

#include <cmath>

namespace stepwise {

World buildDebugDrop() {
    World world = emptyWorld("debug-drop");
    addGroundPlane(world);
    const Quat tilt(angleAxis(Real(0.5), Vec3(1, 0, 1).normalized()));
    addCrate(world, "box", Vec3(0, Real(1.2), 0), Vec3(Real(0.3), Real(0.2), Real(0.25)), 2, Material{}, tilt);
    // Higher up and beside it, so its first contact comes on a later frame than the box's.
    addBall(world, "ball", Vec3(Real(1.0), Real(2.5), Real(0.2)), Real(0.25), 1, Material{});
    return world;
}

std::vector<Vec3> gemPoints() {
    std::vector<Vec3> points{Vec3(0, Real(0.35), 0), Vec3(0, Real(-0.25), 0)};
    for (int i = 0; i < 8; ++i) {
        const Real angle = Real(2) * kPi * Real(i) / 8;
        points.push_back(Vec3(Real(0.3) * math::cos(angle), Real(0.05), Real(0.3) * math::sin(angle)));
    }
    return points;
}

World buildDebugHullOnBox() {
    World world = emptyWorld("debug-hull-on-box");
    addGroundPlane(world);
    addCrate(world, "crate", Vec3(0, Real(0.3), 0), Vec3(Real(0.6), Real(0.3), Real(0.6)), 20, Material{});
    // The gem tilted so it lands on an edge and rolls onto a face.
    BodyDef gem;
    gem.name = "gem";
    gem.shape = Shape::convex(gemPoints());
    gem.transform = Transform{Vec3(Real(0.1), Real(1.4), 0), Quat(angleAxis(Real(0.6), Vec3::UnitZ()))};
    gem.mass = 1;
    addBody(world, gem);
    return world;
}

World buildDebugTunnel() {
    World world = emptyWorld("debug-tunnel", Vec3::Zero());
    world.settings.ccd = CcdMode::Off;   // the bug to find; `ccd: on` is the fix the page shows
    // Chapter 4's solve: chapter 6's relax and soft step search contacts a whole frame ahead (a
    // speculative margin of v dt), which alone would catch this bullet; Baumgarte looks no further
    // than the bodies touch, as a first engine does.
    world.settings.stabilisation = Stabilisation::Baumgarte;
    addStaticBox(world, "wall", Vec3(0, 1, 0), Vec3(Real(0.05), 1, 1));
    BodyDef bullet;
    bullet.name = "bullet";
    bullet.shape = Shape::sphere(Real(0.03));
    bullet.density = 7800;   // steel, as chapter 7's gun
    bullet.transform.position = Vec3(-4, 1, 0);
    // 150 m/s: 2.5 m a frame at 60 Hz, far more than the wall and the bullet are thick together (16 cm).
    bullet.linearVelocity = Vec3(150, 0, 0);
    addBody(world, bullet);
    return world;
}

World buildDebugJitter() {
    World world = emptyWorld("debug-jitter");
    world.settings.warmStarting = false;   // what makes it jitter; the page turns it back on
    addGroundPlane(world);
    for (int level = 0; level < 5; ++level)
        addCrate(world, "box" + std::to_string(level), Vec3(0, Real(0.25) + Real(0.5) * Real(level), 0),
                 Vec3::Constant(Real(0.25)), 1, Material{});
    return world;
}

void addChapter09Scenes(Registry& registry) {
    const char* const category = "debugging";
    registry.addScene({"debug-drop", 9, category, prose(R"(
        Hold Space: the run stops on the frame the box first touches the ground (Left Alt goes on); then
        drag the timeline back and step the impact again)"),
        buildDebugDrop, {}});
    registry.addScene({"debug-hull-on-box", 9, category, prose(R"(
        Turn on the EPA face and A - B views: the blue face is the one whose normal became the contact
        normal)"),
        buildDebugHullOnBox, {}});
    registry.addScene({"debug-tunnel", 9, category, prose(R"(
        The bullet passes the wall between two frames: rewind one frame at a time to see it never
        touched; set ccd on)"),
        buildDebugTunnel, {}});
    registry.addScene({"debug-jitter", 9, category, prose(R"(
        Warm starting is off: select a contact in the hit tree and watch its impulse jump every frame;
        turn it on)"),
        buildDebugJitter, {}});
}

}  // namespace stepwise
