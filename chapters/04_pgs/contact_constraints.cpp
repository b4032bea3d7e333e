#include "04_pgs/contact_constraints.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

Real combinedFriction(const Material& a, const Material& b) {
    return std::sqrt(std::max(Real(0), a.friction) * std::max(Real(0), b.friction));
}

Real combinedRestitution(const Material& a, const Material& b) {
    return std::max(a.restitution, b.restitution);
}

// [ch04-friction-directions]
void frictionDirections(const Vec3& normal, const Vec3& relativeVelocity, Vec3& tangent1, Vec3& tangent2) {
    // The sliding velocity in the contact's own basis, which depends on the normal alone.
    Vec3 basis1, basis2;
    tangentBasis(normal, basis1, basis2);
    const Real slide1 = basis1.dot(relativeVelocity), slide2 = basis2.dot(relativeVelocity);
    const Real slidingSpeed = std::sqrt(slide1 * slide1 + slide2 * slide2);
    // Below ~1e-5 m/s the direction is round-off: the basis itself will do.
    tangent1 = slidingSpeed > Real(1e-5) ? Vec3((slide1 * basis1 + slide2 * basis2) / slidingSpeed) : basis1;
    tangent2 = normal.cross(tangent1);
}
// [ch04-friction-directions]

static bool pointIsFinite(const Contact& contact, const ContactPoint& point) {
    return contact.normal.allFinite() && std::abs(contact.normal.norm() - 1) < Real(1e-3) &&
           point.pointA.allFinite() && point.pointB.allFinite() && std::isfinite(point.depth);
}

// [ch04-contact-row]
// A row along a unit direction at a contact point: J v = direction . (velocity of B's material
// point - velocity of A's material point), the relative velocity along the direction.
ConstraintRow pointVelocityRow(int bodyA, int bodyB, const Vec3& direction, const Vec3& armA, const Vec3& armB) {
    ConstraintRow row;
    row.bodyA = bodyA;
    row.bodyB = bodyB;
    row.linearA = -direction;
    row.angularA = -armA.cross(direction);
    row.linearB = direction;
    row.angularB = armB.cross(direction);
    return row;
}
// [ch04-contact-row]

// The relative velocity of the two material points at `at`.
static Vec3 relativeVelocityAt(const SolverBody& bodyA, const SolverBody& bodyB, const Vec3& at) {
    return bodyB.linearVelocity + bodyB.angularVelocity.cross(at - bodyB.center) - bodyA.linearVelocity -
           bodyA.angularVelocity.cross(at - bodyA.center);
}

/// The velocity of a body before this substep's forces, as a SolverBody (the approach speed).
static std::vector<SolverBody> approachBodiesOf(const World& world, const std::vector<SolverBody>& bodies) {
    const std::vector<BodyVelocity>& before = world.step.velocitiesBeforeForces;
    if (before.size() != bodies.size()) return {};
    std::vector<SolverBody> approach = bodies;
    for (size_t i = 0; i < approach.size(); ++i) {
        approach[i].linearVelocity = before[i].linear;
        approach[i].angularVelocity = before[i].angular;
    }
    return approach;
}

namespace {

// [ch04-closing]
/// How far a point's gap closes in a step of dt, at most: the row's speed (its arms reach the
/// middle of the gap) times dt, but no more than the bodies' own points can travel. The centres
/// move on straight lines; a point on an arm r turning at w sweeps a circle and comes at most
/// 2 |r| nearer anything, however fast it spins. Read off the row's speed alone, a body spun at
/// 458 rad/s "closed" a 37 cm gap in a frame and bounced off a floor it never reached (found by
/// fuzz_stepper).
Real closingInStep(const SolverBody& a, const SolverBody& b, const Vec3& normal, const Vec3& armA, const Vec3& armB,
                   const ContactPoint& point, Real dt) {
    const Real centres = -normal.dot(b.linearVelocity - a.linearVelocity) * dt;
    const Real turns = -normal.dot(b.angularVelocity.cross(armB) - a.angularVelocity.cross(armA)) * dt;
    const Real reach = std::min(a.angularVelocity.norm() * dt, Real(2)) * (point.pointA - a.center).norm() +
                       std::min(b.angularVelocity.norm() * dt, Real(2)) * (point.pointB - b.center).norm();
    return centres + std::clamp(turns, -reach, reach);
}
// [ch04-closing]

}  // namespace

ContactRows buildContactRows(const World& world, const std::vector<SolverBody>& bodies, Real dt) {
    return buildContactRows(world, bodies, dt, world.settings.baumgarte);
}

ContactRows buildContactRows(const World& world, const std::vector<SolverBody>& bodies, Real dt, Real baumgarte) {
    ContactRows result;
    buildContactRows(world, bodies, dt, baumgarte, result);
    return result;
}

void buildContactRows(const World& world, const std::vector<SolverBody>& bodies, Real dt, Real baumgarte,
                      ContactRows& result) {
    const std::vector<SolverBody> approachVelocities = approachBodiesOf(world, bodies);
    const std::vector<SolverBody>* approachBodies = approachVelocities.empty() ? nullptr : &approachVelocities;
    const Settings& settings = world.settings;
    const Real inverseDt = dt > 0 ? 1 / dt : 0;
    result.rows.clear();  // the buffers are kept: a solve that builds its rows every substep reuses them
    result.points.clear();
    result.invalidSkipped = 0;
    for (size_t contactIndex = 0; contactIndex < world.contacts.size(); ++contactIndex) {
        const Contact& contact = world.contacts[contactIndex];
        const int bodyCount = static_cast<int>(bodies.size());
        if (contact.bodyA < 0 || contact.bodyA >= bodyCount || contact.bodyB < 0 || contact.bodyB >= bodyCount ||
            contact.bodyA == contact.bodyB || contact.pointCount < 0 || contact.pointCount > 4) {
            result.invalidSkipped += std::clamp(contact.pointCount, 1, 4);
            continue;
        }
        const SolverBody& bodyA = bodies[contact.bodyA];
        const SolverBody& bodyB = bodies[contact.bodyB];
        if (bodyA.inverseMass == 0 && bodyB.inverseMass == 0) continue;  // nothing here can move
        const Material& materialA = world.bodies[contact.bodyA].material;
        const Material& materialB = world.bodies[contact.bodyB].material;
        const Real friction = combinedFriction(materialA, materialB);
        const Real restitution = combinedRestitution(materialA, materialB);

        for (int pointIndex = 0; pointIndex < contact.pointCount; ++pointIndex) {
            const ContactPoint& point = contact.points[pointIndex];
            if (!pointIsFinite(contact, point)) {
                ++result.invalidSkipped;
                continue;
            }
            const Vec3& normal = contact.normal;
            // The impulse acts halfway between the two deepest points, on both bodies.
            const Vec3 at = Real(0.5) * (point.pointA + point.pointB);
            const Vec3 armA = at - bodyA.center;
            const Vec3 armB = at - bodyB.center;
            const Vec3 relativeVelocity = relativeVelocityAt(bodyA, bodyB, at);
            const Real normalVelocity = normal.dot(relativeVelocity);
            const Real approachVelocity =
                approachBodies ? normal.dot(relativeVelocityAt((*approachBodies)[contact.bodyA],
                                                               (*approachBodies)[contact.bodyB], at))
                               : normalVelocity;

            // [ch04-normal-target]
            // Baumgarte: ask for a separating speed that removes the fraction beta of the
            // penetration beyond the slop in this step. A point still apart (depth < 0, if the
            // narrowphase reports one) may approach by the gap and no faster.
            Real target = 0;
            if (point.depth > settings.slop)
                target = baumgarte * inverseDt * (point.depth - settings.slop);
            else if (point.depth < 0)
                target = point.depth * inverseDt;
            // Restitution reverses the approach speed from before this step's forces (Box2D's
            // "relax" velocity), and only above the threshold, so resting bodies do not bounce on
            // gravity's own speed. The larger of the two targets wins: adding them would bounce a
            // deep contact higher than the restitution law allows. A point still apart (a
            // speculative point, found early for the substeps) bounces only in the substep whose
            // motion would close its gap; before that it merely keeps the bodies from closing more.
            // Without restitution the gap closes in full: a target of zero would stop a ball
            // dropping at 6.5 m/s a centimetre above the ground, to fall the rest a frame later.
            const bool closesThisStep = point.depth + closingInStep(bodyA, bodyB, normal, armA, armB, point, dt) >= 0;
            if (closesThisStep && restitution > 0 && approachVelocity < -settings.restitutionThreshold)
                target = std::max(target, -restitution * approachVelocity);
            // [ch04-normal-target]

            ContactRowRef ref;
            ref.contactIndex = static_cast<int>(contactIndex);
            ref.pointIndex = pointIndex;
            frictionDirections(normal, relativeVelocity, ref.tangent[0], ref.tangent[1]);

            // The normal row first, then the friction rows bounded by it, so friction already has
            // this sweep's normal impulse to work with, even in the first sweep.
            ConstraintRow normalRow = pointVelocityRow(contact.bodyA, contact.bodyB, normal, armA, armB);
            normalRow.bias = target;
            normalRow.lower = 0;
            normalRow.upper = kRealMax;
            ref.normalRow = static_cast<int>(result.rows.size());
            result.rows.push_back(normalRow);
            for (int k = 0; k < 2; ++k) {
                ConstraintRow row = pointVelocityRow(contact.bodyA, contact.bodyB, ref.tangent[k], armA, armB);
                row.boundRow = ref.normalRow;
                row.boundScale = friction;
                ref.tangentRow[k] = static_cast<int>(result.rows.size());
                result.rows.push_back(row);
            }
            result.points.push_back(ref);
        }
    }
    computeEffectiveMasses(result.rows, bodies);
}

// [ch04-store-impulses]
void storeContactImpulses(World& world, const ContactRows& contactRows) {
    // Points without rows (separating, invalid) carried no impulse.
    for (Contact& contact : world.contacts) {
        contact.pointCount = std::clamp(contact.pointCount, 0, 4);  // a malformed count cannot index past points[3]
        for (int i = 0; i < contact.pointCount; ++i) {
            ContactPoint& point = contact.points[i];
            point.normalImpulse = point.normalMass = 0;
            point.tangentImpulse[0] = point.tangentImpulse[1] = 0;
        }
    }
    for (const ContactRowRef& ref : contactRows.points) {
        ContactPoint& point = world.contacts[ref.contactIndex].points[ref.pointIndex];
        const ConstraintRow& normalRow = contactRows.rows[ref.normalRow];
        point.normalImpulse = normalRow.impulse;
        point.normalMass = normalRow.effectiveMass;
        // The rows ran along this step's friction directions; the cache keeps the friction
        // impulse in tangentBasis(normal), which the next step can read whatever it slides along.
        const Vec3 friction = contactRows.rows[ref.tangentRow[0]].impulse * ref.tangent[0] +
                              contactRows.rows[ref.tangentRow[1]].impulse * ref.tangent[1];
        Vec3 basis1, basis2;
        tangentBasis(world.contacts[ref.contactIndex].normal, basis1, basis2);
        point.tangentImpulse[0] = friction.dot(basis1);
        point.tangentImpulse[1] = friction.dot(basis2);
    }
}
// [ch04-store-impulses]

// [ch04-drop-weak]
// Keep a point only if its impulse changed the approach speed by at least kDropVelocityChange.
// The normal row clamps at zero, so these are also the points whose bodies separate on their own
// (J v >= target without any push): what is left is the set of contacts that actually held
// something. The rule runs after the frame's last solve on purpose: a point that separates when
// the solve starts can be pushed shut by its neighbours within the same solve (a heavy ball on
// a light one), so it keeps its row until the solves are over.
int dropUnloadedContactPoints(World& world) {
    int removed = 0;
    size_t kept = 0;
    for (Contact contact : world.contacts) {
        int keptPoints = 0;
        for (int i = 0; i < std::clamp(contact.pointCount, 0, 4); ++i) {
            const ContactPoint& point = contact.points[i];
            const bool carried = point.normalMass > 0 && point.normalImpulse >= kDropVelocityChange * point.normalMass;
            if (carried)
                contact.points[keptPoints++] = point;
            else
                ++removed;
        }
        contact.pointCount = keptPoints;
        if (keptPoints > 0) world.contacts[kept++] = contact;
    }
    world.contacts.resize(kept);
    return removed;
}
// [ch04-drop-weak]

SolverStats solveContacts(World& world, Real dt) {
    SolverStats stats;
    for (const Contact& contact : world.contacts) stats.contactPoints += contact.pointCount;
    std::vector<SolverBody> bodies = gatherSolverBodies(world);
    ContactRows contactRows = buildContactRows(world, bodies, dt);
    solveRows(contactRows.rows, bodies, world.settings.solver, std::max(0, world.settings.solverIterations));
    stats.rows = static_cast<int>(contactRows.rows.size());
    stats.invalidSkipped = contactRows.invalidSkipped;
    const Residual residual = measureResidual(contactRows.rows, bodies);
    stats.residualRms = residual.rms;
    stats.residualMax = residual.max;
    scatterSolverBodies(world, bodies);
    storeContactImpulses(world, contactRows);
    world.step.solver = stats;
    return stats;
}

}  // namespace stepwise
