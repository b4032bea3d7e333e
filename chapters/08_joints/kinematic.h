#pragma once
// Kinematic bodies: moved by the program, not by forces. The solver gives them zero inverse mass
// but keeps their velocity (chapter 4's SolverBody), so they push dynamic bodies and are never
// pushed; friction carries a box on a moving platform because the contact rows see the platform's
// velocity. What a kinematic body needs is a velocity that takes it exactly where the program
// wants it at the end of the step (Jolt's MoveKinematic does the same).

#include "world/world.h"

namespace stepwise {

/// Sets a kinematic body's velocities so that one step of dt lands its origin on `target`
/// (position and orientation). Does nothing to static or dynamic bodies.
void moveKinematic(World& world, int bodyIndex, const Transform& target, Real dt);

/// Where a path puts its body at time t: center + amplitude sin(2 pi t / period + phase).
Vec3 pathPosition(const KinematicPath& path, double time);

/// The stage's work: every World::kinematicPaths body gets the velocity that lands it on its path
/// at the end of this (sub)step (linear motion only; a path keeps the body's angular velocity).
void driveKinematicPaths(World& world, Real dt);

}  // namespace stepwise
