#include "07_ccd/scenes.h"

#include "07_ccd/gun_view.h"
#include "07_ccd/shots.h"
#include "app/registry.h"

#include <cmath>
#include <tuple>

namespace stepwise {

namespace {

constexpr Real kTargetZ[2] = {Real(-2), Real(2)};  // the wall's and the stack's z
constexpr Real kTargetX = 0;

/// A world of the chapter's scenes: its name, its CCD setting, and gravity or none.
World ccdWorld(const char* name, CcdMode ccd, bool gravity) {
    World world = emptyWorld(name, gravity ? Settings{}.gravity : Vec3::Zero());
    world.settings.ccd = ccd;
    return world;
}

/// A dynamic body flying at `velocity` from `position`.
BodyDef flyingBody(const char* name, const Shape& shape, const Vec3& position, const Vec3& velocity) {
    BodyDef body;
    body.name = name;
    body.shape = shape;
    body.transform.position = position;
    body.linearVelocity = velocity;
    return body;
}

}  // namespace

int fireBullet(World& world, int target, Real height, Real speed) {
    BodyDef bullet;
    bullet.name = "bullet" + std::to_string(world.bodies.size());
    bullet.shape = Shape::sphere(Real(0.03));
    bullet.density = 7800;  // steel
    bullet.bullet = true;
    const Vec3 muzzle(kGunX, Real(1.2), 0);
    const Vec3 aim(kTargetX, height, kTargetZ[target & 1]);
    // A ballistic arc that reaches the aim point: the horizontal speed is `speed`, the vertical
    // one makes up for the fall of g t^2 / 2 over the flight time t.
    const Vec3 across = Vec3(aim.x() - muzzle.x(), 0, aim.z() - muzzle.z());
    const Real flight = across.norm() / speed;
    const Real g = -world.settings.gravity.y();
    bullet.transform.position = muzzle;
    bullet.linearVelocity = across.normalized() * speed + Vec3::UnitY() * ((aim.y() - muzzle.y()) / flight + g * flight / 2);
    return addBody(world, bullet);
}

World buildGunRange(Real speed, CcdMode ccd) {
    World world = ccdWorld("ccd-gun", ccd, true);
    addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(30, Real(0.5), 10));
    addStaticBox(world, "wall", Vec3(kTargetX, Real(1.5), kTargetZ[0]), Vec3(kWallHalfThickness, Real(1.5), Real(1.5)));
    for (int level = 0; level < 5; ++level) {
        BodyDef box;
        box.name = "stack" + std::to_string(level);
        box.shape = Shape::box(Vec3::Constant(Real(0.2)));
        box.transform.position = Vec3(kTargetX + Real(0.3), Real(0.2) + Real(0.4) * Real(level), kTargetZ[1]);
        addBody(world, box);
    }
    // The volley: six bullets leave the muzzle together, three for each target, at three heights.
    for (int k = 0; k < 6; ++k) fireBullet(world, k % 2, Real(0.4) + Real(0.5) * Real(k / 2), speed);
    return world;
}

World buildSpinningRod(CcdMode ccd) {
    World world = ccdWorld("ccd-spinning-rod", ccd, false);
    addStaticBox(world, "wall", Vec3::Zero(), Vec3(kWallHalfThickness, 3, 3));
    BodyDef rod = flyingBody("rod", Shape::box(Vec3(Real(0.01), Real(0.5), Real(0.01))), Vec3(-2, 0, 0), Vec3(50, 0, 0));
    rod.angularVelocity = Vec3(0, 0, 100);  // about z: the rod's ends sweep through the x-y plane
    addBody(world, rod);
    return world;
}

World buildHeadOnBullets() {
    World world = ccdWorld("ccd-head-on", CcdMode::Auto, false);
    // 10 g from the left, 30 g from the right, 12.6 m apart: they meet in the second step.
    for (const auto& [name, side, mass] : {std::tuple{"left", Real(-1), Real(0.01)}, std::tuple{"right", Real(1), Real(0.03)}}) {
        BodyDef bullet = flyingBody(name, Shape::sphere(Real(0.01)), Vec3(side * Real(6.3), 0, 0), Vec3(-side * 300, 0, 0));
        bullet.mass = mass;
        bullet.bullet = true;
        addBody(world, bullet);
    }
    return world;
}

void addChapter07Scenes(Registry& registry) {
    const char* const category = "Continuous collision";
    registry.addScene({"ccd-gun", 7, category, prose(R"(
        bullets stop at a 5 cm wall and knock the stack; untick CCD and they fly through)"),
        [] { return buildGunRange(); }, viewOfType<GunView>()});
    registry.addScene({"ccd-spinning-rod", 7, category, prose(R"(
        a rod spinning at 100 rad/s and flying at 50 m/s stops at the wall)"),
        [] { return buildSpinningRod(); }, viewOfType<GunView>()});
    registry.addScene({"ccd-head-on", 7, category, prose(R"(
        two bullets at 300 m/s meet and bounce apart, momentum kept)"),
        [] { return buildHeadOnBullets(); }, viewOfType<GunView>()});
}

}  // namespace stepwise
