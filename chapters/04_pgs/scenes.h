#pragma once
// Chapter 4's scenes, built in one place for the demo, the tests and the benches.

#include "world/world.h"

#include <vector>

namespace stepwise {

/// A static ground box whose top face is the plane y = 0.
int addGroundPlane(World& world, Real friction = Real(0.6), Real restitution = 0);

/// A dynamic sphere or box with the given mass (kg) and material.
int addBall(World& world, const std::string& name, const Vec3& position, Real radius, Real mass,
            const Material& material);
int addCrate(World& world, const std::string& name, const Vec3& position, const Vec3& halfExtents, Real mass,
             const Material& material, const Quat& rotation = Quat::Identity());

/// "pgs-drop": boxes and spheres dropped on the ground from a few metres, seeded orientations.
World buildDropScene();

/// "pgs-bounce": one ball per restitution (0.3, 0.6, 0.9, 1.0) dropped from `height` metres
/// (bottom of the ball above the ground), bodies named "ball-e<restitution>".
World buildBounceScene(Real height = 2);

/// "pgs-resting": a unit box resting on a face next to a ball and a 10 kg ball on a 1 kg ball,
/// all placed at the slop depth so they start at rest: one-point contacts make the box jitter.
World buildRestingScene();

/// "pgs-friction": two ramps of friction mu, 0.2 rad steeper and gentler than atan(mu), each
/// with a box on it, and a ball launched sliding without spin on flat ground; 8 substeps.
World buildFrictionScene(Real friction = Real(0.5));

/// A box resting on an inclined plane: a static ramp at `angle` radians about +Z with a unit
/// box on it (both with friction `friction`). Returns the box's body index through `box`.
World buildRampScene(Real angle, Real friction, int* box = nullptr);

/// "pgs-sphere-pit": `count` spheres dropped into a walled pit, a pile with many coupled contacts
/// (the solver bench's scene).
World buildSpherePitScene(int count = 40);

}  // namespace stepwise
