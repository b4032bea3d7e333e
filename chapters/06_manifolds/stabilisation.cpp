#include "06_manifolds/stabilisation.h"

#include "01_integrators/integrate.h"
#include "01_integrators/rotation.h"
#include "03_epa/chapter.h"
#include "06_manifolds/warm_start.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

// [ch06-make-softness]
// A spring of angular frequency omega and damping ratio zeta, stepped implicitly over h, asks a
// row for biasRate * error and scales its impulse (Catto, "Solver2D", 2024; Box2D v3 b2MakeSoft).
Softness makeSoftness(Real hertz, Real dampingRatio, Real h) {
    if (hertz <= 0) return Softness{};
    const Real omega = 2 * Real(kPi) * hertz;
    const Real a1 = 2 * dampingRatio + h * omega;
    const Real a2 = h * omega * a1;
    const Real a3 = 1 / (1 + a2);
    return Softness{omega / a1, a2 * a3, a3};
}
// [ch06-make-softness]

std::string stabilisedSolveStageName(Stabilisation stabilisation) {
    return stageName(stage_group::kSolve, toString(stabilisation));
}

bool isSubstepped(Stabilisation stabilisation) {
    return stabilisation == Stabilisation::Relax || stabilisation == Stabilisation::SoftStep;
}

// [ch06-manifold-pgs]
namespace {

// [first row, end row) of each contact: buildContactRows appends a contact's rows together.
std::vector<std::pair<int, int>> manifoldRanges(const ContactRows& contactRows) {
    std::vector<std::pair<int, int>> ranges;
    const std::vector<ContactRowRef>& points = contactRows.points;
    for (std::size_t first = 0; first < points.size();) {
        std::size_t end = first;
        while (end < points.size() && points[end].contactIndex == points[first].contactIndex) ++end;
        ranges.push_back({points[first].normalRow, points[end - 1].tangentRow[1] + 1});
        first = end;
    }
    return ranges;
}

// One Gauss-Seidel iteration over every manifold, each swept manifoldSweeps times.
void sweepManifolds(std::vector<ConstraintRow>& rows, const std::vector<std::pair<int, int>>& ranges,
                    const std::vector<Softness>& softness, std::vector<SolverBody>& bodies, int manifoldSweeps) {
    const Softness rigid;
    for (const auto& [begin, end] : ranges) {
        for (int sweep = 0; sweep < manifoldSweeps; ++sweep) {
            // A sweep that changes no impulse leaves the velocities as they were, so every later
            // sweep would repeat it: a speculative contact that stays apart costs one sweep, not eight.
            bool changed = false;
            for (int i = begin; i < end; ++i) {
                ConstraintRow& row = rows[static_cast<std::size_t>(i)];
                if (row.effectiveMass == 0) continue;
                Real lower = row.lower, upper = row.upper;
                if (row.boundRow >= 0) {
                    upper = row.boundScale * rows[static_cast<std::size_t>(row.boundRow)].impulse;
                    lower = -upper;
                }
                const Softness& soft = softness.empty() ? rigid : softness[static_cast<std::size_t>(i)];
                const Real velocityError = row.bias - rowVelocity(row, bodies);
                const Real previous = row.impulse;
                const Real increment = soft.massScale * row.effectiveMass * velocityError - soft.impulseScale * previous;
                row.impulse = std::clamp(previous + increment, lower, upper);
                if (row.impulse == previous) continue;
                changed = true;
                applyRowImpulse(row, row.impulse - previous, bodies);
            }
            if (!changed) break;
        }
    }
}

}  // namespace

void solveByManifold(ContactRows& contactRows, const std::vector<Softness>& softness, std::vector<SolverBody>& bodies,
                     int iterations, int manifoldSweeps) {
    const std::vector<std::pair<int, int>> ranges = manifoldRanges(contactRows);
    for (int iteration = 0; iteration < iterations; ++iteration)
        sweepManifolds(contactRows.rows, ranges, softness, bodies, manifoldSweeps);
}
// [ch06-manifold-pgs]

namespace {

const ContactPoint& pointOf(const World& world, const ContactRowRef& ref) {
    return world.contacts[static_cast<std::size_t>(ref.contactIndex)].points[ref.pointIndex];
}

// Soft step's rows: each normal row of a point deeper than the slop becomes a spring towards the
// slop, pushing out no faster than Settings::maxPushOutSpeed; the others stay rigid.
std::vector<Softness> softenContactRows(const World& world, ContactRows& contactRows,
                                        const std::vector<SolverBody>& bodies, Real dt) {
    std::vector<Softness> softness(contactRows.rows.size());
    const Real hertz = std::min(world.settings.contactHertz, Real(0.25) / dt);
    const Softness dynamicSoftness = makeSoftness(hertz, world.settings.contactDampingRatio, dt);
    const Softness staticSoftness = makeSoftness(2 * hertz, world.settings.contactDampingRatio, dt);
    for (const ContactRowRef& ref : contactRows.points) {
        const Real depth = pointOf(world, ref).depth;
        if (depth <= world.settings.slop) continue;
        ConstraintRow& row = contactRows.rows[static_cast<std::size_t>(ref.normalRow)];
        const bool againstStatic = bodies[row.bodyA].inverseMass == 0 || bodies[row.bodyB].inverseMass == 0;
        const Softness& soft = againstStatic ? staticSoftness : dynamicSoftness;
        softness[static_cast<std::size_t>(ref.normalRow)] = soft;
        row.bias = std::max(row.bias, std::min(soft.biasRate * (depth - world.settings.slop), world.settings.maxPushOutSpeed));
    }
    return softness;
}

// Relax's Baumgarte rows push a deep point out at feedback * depth / h: a body that arrives
// 7 cm deep (tunnelled) would be pushed at metres per second. The relax iteration takes the
// push-out speed out of the contact points' normal velocities, but with friction and offset
// points part of it stays behind as spin. Capped at soft step's (Box2D v3's) push-out speed, the
// energy it can leave is bounded. Restitution's target (the reversed approach speed) is kept.
void capPushOutSpeed(const World& world, ContactRows& contactRows, Real dt, Real feedback) {
    if (!(dt > 0)) return;
    for (const ContactRowRef& ref : contactRows.points) {
        const Real depth = pointOf(world, ref).depth;
        if (depth <= world.settings.slop) continue;
        ConstraintRow& row = contactRows.rows[static_cast<std::size_t>(ref.normalRow)];
        const Real pushOut = feedback * (depth - world.settings.slop) / dt;
        const Real most = world.settings.maxPushOutSpeed;
        if (row.bias > most && row.bias <= pushOut) row.bias = most;
    }
}

// Moves a body's centre of mass by `linear` dt and turns it by `angular` dt about it.
void nudgeBody(World& world, int bodyIndex, const Vec3& linear, const Vec3& angular, Real dt) {
    const Motion* motion = world.motionOf(bodyIndex);
    if (!motion) return;
    Transform& pose = world.bodies[static_cast<std::size_t>(bodyIndex)].transform;
    const Vec3 center = pose.apply(motion->localCenter) + linear * dt;
    pose.rotation = integrateRotation(pose.rotation, angular, dt);
    pose.position = center - pose.rotation * motion->localCenter;
}

}  // namespace

// [ch06-split-impulse]
Real splitImpulseCorrection(World& world, const ContactRows& contactRows, const std::vector<SolverBody>& bodies,
                            Real dt, int iterations) {
    if (!(dt > 0)) return 0;
    std::vector<SolverBody> pseudo = bodies;
    for (SolverBody& body : pseudo) body.linearVelocity = body.angularVelocity = Vec3::Zero();
    std::vector<ConstraintRow> pushRows;
    for (const ContactRowRef& ref : contactRows.points) {
        const Real excess = pointOf(world, ref).depth - world.settings.slop;
        if (excess <= 0) continue;
        ConstraintRow row = contactRows.rows[static_cast<std::size_t>(ref.normalRow)];
        row.bias = world.settings.baumgarte * excess / dt;
        row.impulse = 0;
        pushRows.push_back(row);
    }
    if (pushRows.empty()) return 0;
    solveGaussSeidel(pushRows, pseudo, iterations);
    Real fastest = 0;
    for (const Motion& motion : world.motions) {
        if (world.bodies[static_cast<std::size_t>(motion.bodyIndex)].type != BodyType::Dynamic) continue;
        const SolverBody& push = pseudo[static_cast<std::size_t>(motion.bodyIndex)];
        if (push.linearVelocity.isZero(0) && push.angularVelocity.isZero(0)) continue;
        fastest = std::max(fastest, push.linearVelocity.norm());
        nudgeBody(world, motion.bodyIndex, push.linearVelocity, push.angularVelocity, dt);
    }
    return fastest;
}
// [ch06-split-impulse]

// [ch06-solve]
namespace {

// Chapter 4's Jacobi when asked for (it knows no softness); Gauss-Seidel by manifold otherwise.
// A later chapter's constraints take their sweep first in every iteration: the contacts, which
// can only push, then see the bodies as the joints hold them.
void iterate(const World& world, ContactRows& contactRows, const std::vector<Softness>& softness,
             std::vector<SolverBody>& bodies, int iterations, ExtraConstraints* extra) {
    const bool jacobi = world.settings.solver == SolverKind::Jacobi;
    if (!extra) {
        if (jacobi)
            solveRows(contactRows.rows, bodies, SolverKind::Jacobi, iterations);
        else
            solveByManifold(contactRows, softness, bodies, iterations);
        return;
    }
    const std::vector<std::pair<int, int>> ranges = manifoldRanges(contactRows);
    for (int iteration = 0; iteration < iterations; ++iteration) {
        extra->iterate(bodies);
        if (jacobi)
            solveRows(contactRows.rows, bodies, SolverKind::Jacobi, 1);
        else
            sweepManifolds(contactRows.rows, ranges, softness, bodies, kManifoldSweeps);
    }
}

void recordResidual(World& world, const ContactRows& contactRows, const std::vector<SolverBody>& bodies) {
    const Residual residual = measureResidual(contactRows.rows, bodies);
    world.step.solver.residualRms = residual.rms;
    world.step.solver.residualMax = residual.max;
}

}  // namespace

SolverStats solveStabilised(World& world, Real dt, int iterations, ExtraConstraints* extra, Real frame,
                            ContactRows* rowBuffer) {
    const Settings& settings = world.settings;
    SolverStats stats;
    for (const Contact& contact : world.contacts) stats.contactPoints += contact.pointCount;
    std::vector<SolverBody> bodies = gatherSolverBodies(world);
    // Only Baumgarte and relax feed the penetration back through the velocity rows.
    const bool relax = settings.stabilisation == Stabilisation::Relax;
    const bool velocityBias = settings.stabilisation == Stabilisation::Baumgarte || relax;
    const Real feedback = relax ? relaxFeedback(settings, dt, frame) : settings.baumgarte;
    ContactRows ownRows;
    ContactRows& contactRows = rowBuffer ? *rowBuffer : ownRows;
    buildContactRows(world, bodies, dt, velocityBias ? feedback : Real(0), contactRows);
    if (relax) capPushOutSpeed(world, contactRows, dt, feedback);
    if (extra) extra->prepare(world, bodies, dt, /*positionFeedback=*/true);
    if (settings.warmStarting) {
        if (extra) extra->warmStart(bodies);
        warmStart(world, contactRows, bodies);
    }
    std::vector<Softness> softness;
    if (settings.stabilisation == Stabilisation::SoftStep) softness = softenContactRows(world, contactRows, bodies, dt);
    iterate(world, contactRows, softness, bodies, iterations, extra);
    if (settings.stabilisation == Stabilisation::SplitImpulse) splitImpulseCorrection(world, contactRows, bodies, dt, iterations);
    stats.rows = static_cast<int>(contactRows.rows.size());
    stats.invalidSkipped = contactRows.invalidSkipped;
    world.step.solver = stats;
    recordResidual(world, contactRows, bodies);
    scatterSolverBodies(world, bodies);
    storeContactImpulses(world, contactRows);
    if (extra) extra->store(world);
    return world.step.solver;
}
// [ch06-solve]

// [ch06-relax-feedback]
Real relaxFeedback(const Settings& settings, Real h, Real frame) {
    return frame > h ? settings.baumgarte * (h / frame) : settings.baumgarte;
}
// [ch06-relax-feedback]

// [ch06-relax]
void relaxContacts(World& world, Real dt, int iterations, ExtraConstraints* extra, ContactRows* rowBuffer) {
    followContactAnchors(world);  // the depths after the positions moved
    std::vector<SolverBody> bodies = gatherSolverBodies(world);
    ContactRows ownRows;
    ContactRows& contactRows = rowBuffer ? *rowBuffer : ownRows;
    buildContactRows(world, bodies, dt, 0, contactRows);
    // The biased solve's impulses are already in the velocities: they are where the accumulated
    // impulses start, not pushed again. They are loaded exactly as applied: clamped into the
    // cone they would be smaller than what the velocities hold (the rows clamp friction per
    // direction, a box around the cone), and the relax iteration would apply the difference twice.
    loadCarriedImpulses(world, contactRows, /*clampToCone=*/false);
    if (extra) extra->prepare(world, bodies, dt, /*positionFeedback=*/false);
    iterate(world, contactRows, {}, bodies, iterations, extra);
    recordResidual(world, contactRows, bodies);
    scatterSolverBodies(world, bodies);
    storeContactImpulses(world, contactRows);
    if (extra) extra->store(world);
}
// [ch06-relax]

// [ch06-substepped]
void substeppedSolve(World& world, Real dt, ExtraConstraints* extra) {
    const int substeps = std::max(1, world.settings.solverIterations);
    const Real h = dt / static_cast<Real>(substeps);
    // Nothing touches: chapter 4's split step, substep by substep, so that free bodies move
    // exactly as chapter 1 moves them at the substep. Every body moves in the same substeps
    // whether or not anything touches: a ball's flight must not depend on another body's contact
    // (a frame at a time, Euler's g h t / 2 took 7% off a dropped ball's bounce).
    if (world.contacts.empty() && !(extra && extra->active(world))) {
        for (int substep = 0; substep < substeps; ++substep) {
            applyForces(world);
            integrateVelocities(world, h);
            integratePositions(world, h);
        }
        world.step.velocitiesBeforeForces.clear();
        return;
    }
    ContactRows rows;  // one buffer for the frame's builds, two a substep
    for (int substep = 0; substep < substeps; ++substep) {
        // Restitution reverses the approach speed from before this substep's forces.
        world.step.velocitiesBeforeForces.resize(world.bodies.size());
        for (const Motion& motion : world.motions)
            world.step.velocitiesBeforeForces[static_cast<std::size_t>(motion.bodyIndex)] =
                BodyVelocity{motion.linearVelocity, motion.angularVelocity};
        applyForces(world);
        integrateVelocities(world, h);
        followContactAnchors(world);  // where the points are now (a no-op right after the search)
        solveStabilised(world, h, world.settings.solverIterations > 0 ? 1 : 0, extra, dt, &rows);
        integratePositions(world, h);
        relaxContacts(world, h, world.settings.solverIterations > 0 ? 1 : 0, extra, &rows);
    }
    world.step.velocitiesBeforeForces.clear();
}
// [ch06-substepped]

}  // namespace stepwise
