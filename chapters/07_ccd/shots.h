#pragma once
// The chapter's measured scene, one builder for the test, the bench and the demo: a small body
// shot at a static wall 5 cm thick, fast enough to cross it between two steps.

#include "math/random.h"
#include "world/world.h"

namespace stepwise {

constexpr Real kWallHalfThickness = Real(0.025);  // m: the wall is 5 cm thick, its faces at x = -/+ 2.5 cm

enum class ShotShape { Sphere, Box, Hull };
const char* toString(ShotShape shape);

/// One shot: what flies, how fast, and where along its path the first step starts.
struct Shot {
    ShotShape shape = ShotShape::Sphere;
    Real size = Real(0.03);                 // m: radius, half extent, or hull radius
    Real speed = 100;                       // m/s
    Vec3 direction = Vec3::UnitX();         // unit, towards +x (into the wall)
    Quat orientation = Quat::Identity();
    Vec3 spin = Vec3::Zero();               // rad/s
    Real stepsBeforeWall = 1;               // steps of travel from the body's front to the wall
};

/// A random shot: a sphere, box or hull of 1 to 5 cm, at `speed`, up to 30 degrees off the
/// wall's normal, turned and spinning at random, 0.3 to 1.7 steps from the wall.
Shot randomShot(Random& random, Real speed);

/// No gravity; a static wall 5 cm thick and 100 m square in the plane x = 0; the shot's body
/// (named "shot", index 1) in front of it. Settings::ccd as given.
World buildShot(const Shot& shot, CcdMode ccd);

/// Steps a shot needs to reach the wall and then some: the outcome is settled after it.
constexpr int kShotSteps = 3;

/// Whether the shot's body has crossed the wall: its centre past the wall's far face.
bool tunnelled(const World& world);

}  // namespace stepwise
