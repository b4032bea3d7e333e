#include "07_ccd/toi_loop.h"

#include "03_epa/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "04_pgs/solver.h"
#include "07_ccd/closed_form_toi.h"
#include "07_ccd/fast_bodies.h"

#include <algorithm>

namespace stepwise {

bool mayHit(const World& world, int mover, int other) {
    if (mover == other) return false;
    const Body& a = world.bodies[std::size_t(mover)];
    const Body& b = world.bodies[std::size_t(other)];
    if (a.type != BodyType::Dynamic || !canCollide(a, b)) return false;
    if (b.type == BodyType::Static) return true;
    return b.type == BodyType::Dynamic && (a.bullet || b.bullet);
}

static bool isSphere(const Shape& shape) { return shape.type == ShapeType::Sphere; }

static ToiResult sweptQuery(const Shape& a, const Sweep& sweepA, const Shape& b, const Sweep& sweepB, const ToiOptions& options) {
    if (isSphere(a) && isSphere(b)) return sphereSweepsTimeOfImpact(a.radius, sweepA, b.radius, sweepB, options);
    return timeOfImpact(a, sweepA, b, sweepB, options);
}

/// The mover's centre of mass alone (a ball of the target's radius) against the other shape:
/// a body that begins the step overlapping something must at least not carry its centre through
/// it (Box2D v3 keeps the centroid on the near side the same way). Touching again when the centre
/// is already at or inside the surface: then it is the solver's.
static ToiResult centreTimeOfImpact(const Shape& shapeB, const Sweep& a, const Sweep& b, const ToiOptions& options) {
    const Shape core = Shape::sphere(std::max(options.target, kEpsilon));
    Sweep centre = a;
    centre.localCenter = Vec3::Zero();  // poses of the centre of mass itself
    return timeOfImpact(core, centre, shapeB, b, options);
}

// [ch07-find-impact]
bool findImpact(const World& world, int mover, int other, const std::vector<Sweep>& sweeps, const ToiOptions& options,
                ToiEvent& event) {
    const Shape& shapeA = world.bodies[std::size_t(mover)].shape;
    const Shape& shapeB = world.bodies[std::size_t(other)].shape;
    const Sweep& a = sweeps[std::size_t(mover)];
    const Sweep& b = sweeps[std::size_t(other)];
    if (!sweptBounds(a, shapeA).overlaps(sweptBounds(b, shapeB))) return false;
    ToiResult toi = sweptQuery(shapeA, a, shapeB, b, options);
    // Touching where the sweeps start, but apart: the contact the step began with may hold one
    // point while the body turns another into the wall. Advance to half the gap, so that a
    // spinning rod stops before its far end crosses. An overlap (distance 0) is the solver's,
    // but the centre may not cross the other body on the way.
    if (toi.state == ToiState::Touching && toi.distance > options.target / 8) {
        ToiOptions closer = options;
        closer.target = toi.distance / 2;
        closer.tolerance = toi.distance / 8;
        toi = timeOfImpact(shapeA, a, shapeB, b, closer);
    } else if (toi.state == ToiState::Touching) {
        toi = centreTimeOfImpact(shapeB, a, b, options);
    }
    if (toi.state != ToiState::Hit && toi.state != ToiState::Stalled) return false;
    event = ToiEvent{mover, other, toi};
    return true;
}
// [ch07-find-impact]

namespace {

/// A body's solver view at its pose at time t: velocities from its Motion, inertia in the
/// rotated axes. Static bodies (no Motion) have none.
SolverBody solverBodyAt(const World& world, int body, const Transform& pose) {
    SolverBody solverBody;
    const Motion* motion = world.motionOf(body);
    solverBody.center = pose.apply(motion ? motion->localCenter : Vec3::Zero());
    if (!motion || world.bodies[std::size_t(body)].type != BodyType::Dynamic) return solverBody;
    solverBody.linearVelocity = motion->linearVelocity;
    solverBody.angularVelocity = motion->angularVelocity;
    solverBody.inverseMass = motion->inverseMass;
    const Mat3 rotation = pose.rotation.toRotationMatrix();
    solverBody.inverseInertia = rotation * motion->inverseInertiaLocal * rotation.transpose();
    return solverBody;
}

}  // namespace

// [ch07-resolve-impact]
Real resolveImpact(World& world, const ToiEvent& event, const std::vector<Sweep>& sweeps) {
    const Real t = event.toi.time;
    std::vector<SolverBody> pair = {solverBodyAt(world, event.mover, poseAt(sweeps[std::size_t(event.mover)], t)),
                                    solverBodyAt(world, event.other, poseAt(sweeps[std::size_t(event.other)], t))};
    // One contact row (chapter 4's), J v = the speed at which B leaves A along the normal.
    const Vec3 point = Real(0.5) * (event.toi.pointA + event.toi.pointB);
    const Vec3& normal = event.toi.normal;
    std::vector<ConstraintRow> rows(1);
    ConstraintRow& row = rows[0];
    row.bodyA = 0;
    row.bodyB = 1;
    row.linearA = -normal;
    row.angularA = -(point - pair[0].center).cross(normal);
    row.linearB = normal;
    row.angularB = (point - pair[1].center).cross(normal);
    computeEffectiveMasses(rows, pair);
    const Real separating = rowVelocity(row, pair);
    if (separating >= 0) return 0;
    const Body& a = world.bodies[std::size_t(event.mover)];
    const Body& b = world.bodies[std::size_t(event.other)];
    const Real restitution =
        -separating > world.settings.restitutionThreshold ? combinedRestitution(a.material, b.material) : Real(0);
    const Real impulse = -(Real(1) + restitution) * separating * row.effectiveMass;
    applyRowImpulse(row, impulse, pair);
    for (int side = 0; side < 2; ++side) {
        Motion* motion = world.motionOf(side == 0 ? event.mover : event.other);
        if (!motion || pair[std::size_t(side)].inverseMass == 0) continue;
        motion->linearVelocity = pair[std::size_t(side)].linearVelocity;
        motion->angularVelocity = pair[std::size_t(side)].angularVelocity;
    }
    return impulse;
}
// [ch07-resolve-impact]

namespace {

bool involves(const ToiEvent& event, int body) { return event.mover == body || event.other == body; }

bool isStill(const World& world, const ToiLoopScratch& loop, int body) {
    return loop.stopped[std::size_t(body)] || world.bodies[std::size_t(body)].type != BodyType::Dynamic;
}

/// Impacts of `body` with everything it can hit or be hit by, except `skip`; each pair once.
void collectImpacts(const World& world, ToiLoopScratch& loop, int body, int skip, const ToiOptions& options) {
    for (int other = 0; other < int(world.bodies.size()); ++other) {
        if (other == skip || other == body) continue;
        int mover = body, target = other;
        if (!loop.checked[std::size_t(body)] || !mayHit(world, body, other)) std::swap(mover, target);
        if (!loop.checked[std::size_t(mover)] || !mayHit(world, mover, target)) continue;
        if (isStill(world, loop, mover) && isStill(world, loop, target)) continue;
        const bool known = std::any_of(loop.pending.begin(), loop.pending.end(),
                                       [&](const ToiEvent& e) { return involves(e, mover) && involves(e, target); });
        if (known) continue;
        ToiEvent event;
        const bool hit = findImpact(world, mover, target, loop.sweeps, options, event);
        if (!hit) continue;
        loop.queries += event.toi.iterations;
        loop.pending.push_back(event);
    }
}

/// Leaves the body at its pose at time t for the rest of the step. Its spin turns back with it:
/// the angular velocity is the one the sweep's end pose had, and kept in world axes on a pose
/// turned back it would spin the body about other axes of its own, with another energy (a rod
/// spinning off its axis at 108 rad/s gained 290 J in one stop). Kept in the body's axes, the
/// spin's energy and the size of its angular momentum are the end pose's.
void stopAt(World& world, ToiLoopScratch& loop, int body, Real t) {
    if (world.bodies[std::size_t(body)].type != BodyType::Dynamic) return;
    Sweep& sweep = loop.sweeps[std::size_t(body)];
    const Transform pose = poseAt(sweep, t);
    Motion* motion = world.motionOf(body);
    if (motion && !loop.stopped[std::size_t(body)]) {  // a body stopped before waits already: its spin is turned
        const Quat turnedBack = pose.rotation * poseAt(sweep, 1).rotation.conjugate();
        motion->angularVelocity = turnedBack * motion->angularVelocity;
    }
    sweep = stillSweep(pose, sweep.localCenter);
    sweep.alpha0 = t;
    loop.stopped[std::size_t(body)] = 1;
    loop.checked[std::size_t(body)] = 1;  // a body that was hit may now hit others
}

bool earlier(const ToiEvent& a, const ToiEvent& b) {
    if (a.toi.time != b.toi.time) return a.toi.time < b.toi.time;
    return a.mover != b.mover ? a.mover < b.mover : a.other < b.other;  // a total order: deterministic
}

}  // namespace

// [ch07-toi-loop]
void resolveTimesOfImpact(World& world, Real dt) {
    ToiLoopScratch loop;
    resolveTimesOfImpact(world, dt, loop);
}

void resolveTimesOfImpact(World& world, Real /*dt*/, ToiLoopScratch& loop) {
    CcdState& state = world.step.ccd;
    state.fastBodies = state.toiEvents = state.rootIterations = 0;
    state.boundHit = false;
    state.timeLost = 0;
    state.ghostBodies.clear();
    state.ghostPoses.clear();
    state.sweptBounds.clear();
    const std::size_t count = world.bodies.size();
    if (state.sweepStart.size() != count) return;  // no sweep start recorded for these bodies
    if (count < 2) return;                           // a body alone has nothing to hit

    // Every body's sweep from where the step began to where the step left it.
    loop.sweeps.clear();
    loop.pending.clear();
    loop.resolved = loop.queries = 0;
    loop.checked.assign(count, 0);
    loop.stopped.assign(count, 0);
    loop.eventsOf.assign(count, 0);
    for (std::size_t i = 0; i < count; ++i) {
        const Motion* motion = world.motionOf(int(i));
        const Vec3 localCenter = motion ? motion->localCenter : Vec3::Zero();
        loop.sweeps.push_back(sweepBetween(state.sweepStart[i], world.bodies[i].transform, localCenter));
        loop.checked[i] = needsContinuousCollision(world.bodies[i], loop.sweeps.back()) ? 1 : 0;
        if (loop.checked[i]) state.sweptBounds.push_back(sweptBounds(loop.sweeps.back(), world.bodies[i].shape));
    }
    state.fastBodies = int(state.sweptBounds.size());
    if (state.fastBodies == 0) return;  // nothing fast: the step is chapter 6's, untouched
    ++state.stepsRun;

    // The impacts of the fast bodies in the step, earliest first.
    const ToiOptions options = toiOptionsFor(world.settings);
    for (std::size_t i = 0; i < count; ++i)
        if (loop.checked[i]) collectImpacts(world, loop, int(i), -1, options);

    while (!loop.pending.empty()) {
        const auto first = std::min_element(loop.pending.begin(), loop.pending.end(), earlier);
        const ToiEvent event = *first;
        const Real t = event.toi.time;
        // Past a bound the bodies wait at the impact unresolved: no tunnel, but no bounce either.
        const bool withinBounds = loop.resolved < kMaxToiEventsPerStep &&
                                  loop.eventsOf[std::size_t(event.mover)] < kMaxToiEventsPerBody &&
                                  loop.eventsOf[std::size_t(event.other)] < kMaxToiEventsPerBody;
        state.timeLost += Real(1) - t;
        state.ghostBodies.push_back(event.mover);
        state.ghostPoses.push_back(poseAt(loop.sweeps[std::size_t(event.mover)], t));
        // Both bodies wait at their impact poses, their spins turned back with them, and the
        // impact is resolved there; whatever involved them is looked at again.
        stopAt(world, loop, event.mover, t);
        stopAt(world, loop, event.other, t);
        if (withinBounds) {
            resolveImpact(world, event, loop.sweeps);
            ++loop.resolved;
            ++loop.eventsOf[std::size_t(event.mover)];
            ++loop.eventsOf[std::size_t(event.other)];
        } else {
            state.boundHit = true;
        }
        // Only the bodies that moved differ now: a static body's other impacts still stand.
        const bool otherMoves = world.bodies[std::size_t(event.other)].type == BodyType::Dynamic;
        loop.pending.erase(std::remove_if(loop.pending.begin(), loop.pending.end(),
                                          [&](const ToiEvent& e) {
                                              return involves(e, event.mover) || (otherMoves && involves(e, event.other));
                                          }),
                           loop.pending.end());
        if (withinBounds) {
            collectImpacts(world, loop, event.mover, event.other, options);
            if (otherMoves) collectImpacts(world, loop, event.other, -1, options);
        }
    }

    // The bodies the loop stopped end the step where they wait.
    for (std::size_t i = 0; i < count; ++i)
        if (loop.stopped[i]) world.bodies[i].transform = poseAt(loop.sweeps[i], 1);
    state.toiEvents = loop.resolved;
    state.rootIterations = loop.queries;
    state.totalToiEvents += loop.resolved;
    if (state.boundHit) ++state.stepsBoundHit;
}
// [ch07-toi-loop]

}  // namespace stepwise
