#pragma once
// How the contact solve removes penetration without adding energy, and how it spends its
// iterations. Chapter 4 asks the velocity rows for a separating speed proportional to the
// penetration (Baumgarte), and that speed stays in the bodies after the overlap is gone: a
// stack pushed apart keeps moving apart, falls back, and rocks. The remedies compared here
// (Settings::stabilisation):
//
// - baumgarte: chapter 4's bias, now warm started: Settings::solverIterations iterations.
// - split_impulse: the velocity rows get no bias; the correction is solved apart, on
//   pseudo-velocities that move the positions once and are thrown away (Erleben's thesis,
//   "Stable, Robust, and Versatile Multibody Dynamics Animation", 2004; Bullet's split impulse).
// - relax: the iterations become substeps (Catto, "Solver2D", 2024: many substeps of one
//   iteration beat many iterations): each substep integrates the velocities, warm starts, runs
//   one biased iteration, moves the positions, then one "relax" iteration without the bias,
//   which takes the push-out speed back out of the velocities. The push-out is capped at
//   Settings::maxPushOutSpeed, as soft step's: relax gives the contact points' normal speed back, but
//   with friction and offset points part of a large push stays behind as spin.
// - soft_step: the same with Box2D v3's soft contacts (a spring-damper of 30 Hz, damping ratio
//   10, push-out capped at 3 m/s) in the biased iteration (Catto, "Solver2D", 2024; Box2D v3).
//
// Every Gauss-Seidel sweep here visits the contacts one manifold at a time and sweeps a
// manifold's rows kManifoldSweeps times before moving on: the four points of a face contact
// share one load, and letting them agree before the next contact is what keeps a tall stack
// from tilting (tests/ch06/stacking_test.cpp and the page measure it).

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

// The contact frequency (capped at a quarter of the substep rate), damping ratio and the largest
// speed soft contacts push out at are settings (Settings::contactHertz, contactDampingRatio,
// maxPushOutSpeed; Box2D v3's defaults). Contacts with a static body are twice as stiff.
// [ch06-softness]

/// Sweeps over one manifold's rows before the solver moves to the next contact.
constexpr int kManifoldSweeps = 8;

// [ch06-extra-constraints]
/// Constraints a later chapter solves together with the contacts (chapter 8's joints), in the same
/// passes and against the same bodies: built from the poses at the start of each solve, warm
/// started, swept once before the contacts in every iteration (with their position feedback in
/// the biased solve, without it in the relax pass) and their impulses stored at the end. A
/// fresh object per solve: whatever must outlive it goes into the World in store().
class ExtraConstraints {
public:
    virtual ~ExtraConstraints() = default;
    /// Whether there is anything to solve: without contacts or extras, the substepped solve
    /// integrates the free bodies exactly as chapter 1 does.
    virtual bool active(const World& world) const = 0;
    /// Builds the rows for a (sub)step of h. `positionFeedback` false: the relax pass, whose
    /// rows start from the impulses already applied (no warm start follows).
    virtual void prepare(const World& world, const std::vector<SolverBody>& bodies, Real h, bool positionFeedback) = 0;
    virtual void warmStart(std::vector<SolverBody>& bodies) = 0;
    virtual void iterate(std::vector<SolverBody>& bodies) = 0;
    virtual void store(World& world) const = 0;
};
// [ch06-extra-constraints]

/// The solve stage's name, "solve:<stabilisation>".
std::string stabilisedSolveStageName(Stabilisation stabilisation);

/// True for relax and soft_step, which spend the iterations as substeps of one biased and one
/// relax iteration each; their solve stage integrates the bodies itself.
bool isSubstepped(Stabilisation stabilisation);

/// Projected Gauss-Seidel by manifold: the rows of ContactRows (grouped by contact, as
/// buildContactRows makes them), each contact's rows swept `manifoldSweeps` times per
/// iteration, with a Softness per row (empty: all rigid).
void solveByManifold(ContactRows& contactRows, const std::vector<Softness>& softness, std::vector<SolverBody>& bodies,
                     int iterations, int manifoldSweeps = kManifoldSweeps);

/// Split impulses: the position error beyond the slop, solved as a separate push on
/// pseudo-velocities (normal rows only, starting from rest), moves the bodies once. Nothing of
/// it reaches the real velocities. Returns the largest pseudo-speed applied, m/s.
Real splitImpulseCorrection(World& world, const ContactRows& contactRows, const std::vector<SolverBody>& bodies,
                            Real dt, int iterations);

/// The fraction of a penetration (beyond the slop) relax's biased sweep feeds back in a substep of
/// h of a frame of `frame` seconds: Settings::baumgarte per frame, spread over its substeps
/// (baumgarte * h / frame; baumgarte itself when the step is the frame). Fed back per substep, the
/// push-out speed would grow with the substep count (baumgarte / h: 120 per second at ten
/// substeps, ten times chapter 4's 12 at 60 Hz), and where the relax sweep cannot take it back
/// in one sweep (a light body between heavy ones) that speed stays: a column of balls with an
/// 11 kg ball between 116 and 181 kg ones bounced for ever on it.
Real relaxFeedback(const Settings& settings, Real h, Real frame);

/// One solve over World::contacts for a step of dt: rows, the warm start
/// (Settings::warmStarting), `iterations` iterations with the bias the stabilisation asks for
/// (Baumgarte for baumgarte and relax, none for split impulses, soft springs for soft_step), split impulses'
/// position correction, velocities and impulses written back. Records World::step.solver.
/// `frame`: the frame a relax substep belongs to (relaxFeedback); 0 when dt is the frame.
/// `rowBuffer`: where the rows are built, its buffers kept from call to call (none: a fresh one).
SolverStats solveStabilised(World& world, Real dt, int iterations, ExtraConstraints* extra = nullptr, Real frame = 0,
                            ContactRows* rowBuffer = nullptr);

/// The relax iteration(s): the same rows with no position bias, starting from the impulses the
/// biased solve accumulated (already in the velocities), take the push-out speed back out.
/// Restitution and speculative gaps stay in the target.
void relaxContacts(World& world, Real dt, int iterations, ExtraConstraints* extra = nullptr,
                   ContactRows* rowBuffer = nullptr);

/// The substepped solve of relax and soft_step, for one (pipeline) step of dt: solverIterations
/// substeps, each: forces and velocities, contact points moved with their bodies, warm start and one
/// biased iteration, positions, one relax iteration.
void substeppedSolve(World& world, Real dt, ExtraConstraints* extra = nullptr);

}  // namespace stepwise
