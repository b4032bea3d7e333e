#pragma once
// Chapter 7's scenes: bullets at a thin wall and at a stack, a spinning rod, two bullets head on.
// One builder each, shared by the demo, the tests and the bench.

#include "world/world.h"

namespace stepwise {

class Registry;

/// Where the gun stands and how fast its bullets fly by default.
constexpr Real kGunX = -12;
constexpr Real kDefaultBulletSpeed = 150;  // m/s

/// Ground, a static wall 5 cm thick (z < 0) and a stack of five 40 cm boxes (z > 0), and a volley
/// of six 3 cm steel bullets (flagged `bullet`) just fired from the gun at `speed`, three at
/// each target: "ccd-gun".
World buildGunRange(Real speed = kDefaultBulletSpeed, CcdMode ccd = CcdMode::Auto);

/// Fires one bullet from the gun's muzzle at the wall (target 0) or the stack (target 1) with
/// the given speed, aimed so that gravity brings it to `height` at the target. Returns its index.
int fireBullet(World& world, int target, Real height, Real speed);

/// No gravity; a static wall 5 cm thick at x = 0, and a rod 1 m long and 2 cm thick spinning at
/// 100 rad/s about its middle while flying at 50 m/s towards it: "ccd-spinning-rod".
World buildSpinningRod(CcdMode ccd = CcdMode::Auto);

/// No gravity; two 2 cm bullets of 10 g and 30 g flying at each other at 300 m/s each:
/// "ccd-head-on".
World buildHeadOnBullets();

/// Registers the scenes above under "Continuous collision".
void addChapter07Scenes(Registry& registry);

}  // namespace stepwise
