#pragma once
// Contacts become constraint rows: for each contact point one normal row (push only) and two
// friction rows (bounded by mu times the normal impulse), then the solved impulses are stored in
// World::contacts, the contact cache, where the demo draws them and chapter 6 will
// start the next step from them. What the cache keeps is decided apart, after the frame's solves.

#include "04_pgs/constraint_row.h"
#include "04_pgs/solver.h"
#include "world/world.h"

#include <vector>

namespace stepwise {

/// Where one contact point's rows are, and the friction directions they use.
struct ContactRowRef {
    int contactIndex = -1;      // into World::contacts
    int pointIndex = 0;         // into Contact::points
    int normalRow = -1;         // into ContactRows::rows
    int tangentRow[2] = {-1, -1};
    Vec3 tangent[2] = {Vec3::Zero(), Vec3::Zero()};  // frictionDirections()
};

struct ContactRows {
    std::vector<ConstraintRow> rows;
    std::vector<ContactRowRef> points;
    int invalidSkipped = 0;     // contact points with non-finite data (a defined result, not a crash)
};

/// A contact point whose normal impulse changed the bodies' approach speed by less than this
/// (impulse / effective mass) carried nothing, its bodies separate on their own, and the cache
/// upkeep at the end of the frame removes it from World::contacts.
constexpr Real kDropVelocityChange = Real(1e-4);  // m/s

/// The row of two material points' relative velocity along a unit direction: J v =
/// direction . (velocity of B's point - velocity of A's point), the points at arms armA and armB
/// from the centres of mass. A contact's normal and friction rows are such rows; so are many of
/// chapter 8's joint rows.
ConstraintRow pointVelocityRow(int bodyA, int bodyB, const Vec3& direction, const Vec3& armA, const Vec3& armB);

/// Friction and restitution of a pair, per the scene contract: sqrt(f_a f_b) and max(r_a, r_b).
Real combinedFriction(const Material& a, const Material& b);
Real combinedRestitution(const Material& a, const Material& b);

/// The friction directions of a contact: the first along the sliding velocity when the bodies
/// slide (so the friction pyramid's edge lines up with the motion and bounds it by exactly
/// mu lambda), else the first axis of tangentBasis(normal). The sliding direction is taken in
/// that basis, so the directions depend on the normal and the sliding velocity alone.
void frictionDirections(const Vec3& normal, const Vec3& relativeVelocity, Vec3& tangent1, Vec3& tangent2);

/// Builds the rows of every contact point in World::contacts for a step of dt, with effective
/// masses filled in, against velocities as `bodies` holds them (after gravity, before the solve).
/// World::step.velocitiesBeforeForces, when it holds one entry per body, gives the approach
/// speed that restitution reverses, as Box2D does (its contact "relax" velocity is measured
/// before the velocity integration). Without it the approach speed includes this step's
/// gravity, and a ball with e = 1 gains about v dt of height per bounce (tests/ch04/bounce_test.cpp).
ContactRows buildContactRows(const World& world, const std::vector<SolverBody>& bodies, Real dt);
/// The same with the fraction of penetration fed back per step given rather than read from
/// Settings::baumgarte: chapter 6's split impulses and soft step build their velocity rows with
/// 0 here and correct positions their own way.
ContactRows buildContactRows(const World& world, const std::vector<SolverBody>& bodies, Real dt, Real baumgarte);
/// The same into `rows`, whose buffers it keeps: a solve that builds its rows every substep
/// (chapter 6's) would otherwise allocate and free them twice a substep, and the allocator hands
/// large freed blocks back to the system, to be faulted in again page by page.
void buildContactRows(const World& world, const std::vector<SolverBody>& bodies, Real dt, Real baumgarte,
                      ContactRows& rows);

/// Copies the solved impulses into World::contacts: normalImpulse, tangentImpulse (in
/// tangentBasis(normal)) and the normal row's effective mass. Points without rows get zeros. It
/// only stores; what the cache keeps is dropUnloadedContactPoints' decision.
void storeContactImpulses(World& world, const ContactRows& contactRows);

/// The cache upkeep after the frame's last solve: removes the points whose normal impulse
/// changed their bodies' approach speed by less than kDropVelocityChange (no row, or
/// impulse < kDropVelocityChange * normalMass), and the contacts left without points. Returns
/// how many points it removed.
int dropUnloadedContactPoints(World& world);

/// The chapter's solve: gather velocities, build rows, iterate (Settings::solver,
/// Settings::solverIterations), write velocities and impulses back. Records what it did in
/// World::step.solver and returns it.
SolverStats solveContacts(World& world, Real dt);

}  // namespace stepwise
