#pragma once
// How the contact solve removes penetration without adding energy. Chapter 4 asks the velocity
// rows for a separating speed proportional to the penetration (Baumgarte), and that speed stays
// in the bodies after the overlap is gone: a stack pushed apart keeps moving apart, then falls
// back, and jitters. The remedies compared here (Settings::stabilisation):
//
// - baumgarte: chapter 4's bias, now warm started.
// - relax: the same biased solve, then, after the positions have moved, a second solve of the
//   same rows without the bias ("relax"), which takes the push-out speed back out of the
//   velocities (Catto, "Solver2D", 2024).
// - split_impulse: the velocity rows get no bias; the correction is solved apart, on
//   pseudo-velocities that move the positions once and are thrown away (Erleben's thesis,
//   "Stable, Robust, and Versatile Multibody Dynamics Animation", 2004; Bullet's split impulse).
// - soft_step: Box2D v3's soft step: soft contact rows (a spring-damper of 30 Hz, damping ratio
//   10, capped push-out speed), then the relax pass (Catto, "Solver2D", 2024; Box2D v3 and
//   Box3D's contact_solver.c).

#include "04_pgs/contact_constraints.h"
#include "world/world.h"

#include <string>
#include <vector>

namespace stepwise {

// [ch06-softness]
/// A soft constraint in Box2D v3's form: solving a row with it gives the impulse of a
/// spring-damper integrated implicitly over the substep, instead of the rigid answer.
///   increment = massScale * m (target - J v) - impulseScale * accumulated,  target = biasRate * error
/// The rigid row is biasRate 0 (no position feedback), massScale 1, impulseScale 0.
struct Softness {
    Real biasRate = 0;      // 1/s: the fraction of the position error asked for per second
    Real massScale = 1;
    Real impulseScale = 0;
};

/// Box2D v3's b2MakeSoft: stiffness by frequency (Hz) and damping ratio, for a step of h.
Softness makeSoftness(Real hertz, Real dampingRatio, Real h);

/// Box2D v3's defaults: contact frequency (capped at a quarter of the substep rate), damping ratio, and the
/// largest speed the soft contacts push out at. Contacts with a static body are twice as stiff.
constexpr Real kContactHertz = 30;
constexpr Real kContactDampingRatio = 10;
constexpr Real kMaxPushOutSpeed = 3;  // m/s
// [ch06-softness]

/// The solve stage's name, "solve:<stabilisation>".
std::string stabilisedSolveStageName(Stabilisation stabilisation);

/// Whether the stabilisation runs a relax pass after the positions moved.
bool hasRelaxPass(Stabilisation stabilisation);

/// Projected Gauss-Seidel with a Softness per row (rigid rows behave exactly as in chapter 4).
void solveSoftGaussSeidel(std::vector<ConstraintRow>& rows, const std::vector<Softness>& softness,
                          std::vector<SolverBody>& bodies, int iterations);

/// Split impulses: the position error beyond the slop, solved as a separate push on
/// pseudo-velocities (normal rows only, starting from rest), moves the bodies once. Nothing
/// of it reaches the real velocities. Returns the largest pseudo-speed applied, m/s.
Real splitImpulseCorrection(World& world, const ContactRows& contactRows, const std::vector<SolverBody>& bodies,
                            Real dt, int iterations);

/// The solve stage of chapter 6: rows from World::contacts, the warm start (Settings::warmStarting),
/// the iterations with the bias Settings::stabilisation asks for, split impulses' position
/// correction, velocities and impulses written back. Records World::step.solver.
SolverStats solveStabilised(World& world, Real dt);

/// The relax pass (relax and soft_step): after the positions moved, the same rows with no
/// position bias, starting from the impulses the biased solve accumulated (already in the
/// velocities), remove the push-out speed. Restitution and speculative gaps stay in the target.
void relaxContacts(World& world, Real dt);

}  // namespace stepwise
