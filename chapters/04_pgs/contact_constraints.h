#pragma once
// Contacts become constraint rows: for each contact point one normal row (push only) and two
// friction rows (bounded by mu times the normal impulse), then the solved impulses go back into
// World::contacts, where the demo draws them and chapter 6 will find them next frame.

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
    Vec3 tangent[2] = {Vec3::Zero(), Vec3::Zero()};
};

struct ContactRows {
    std::vector<ConstraintRow> rows;
    std::vector<ContactRowRef> points;
    int invalidSkipped = 0;     // contact points with non-finite data (a defined result, not a crash)
};

/// A contact point whose normal impulse changed the bodies' approach speed by less than this
/// (impulse / effective mass) carried nothing, its bodies separate on their own, and it is
/// removed from World::contacts after the solve.
constexpr Real kDropVelocityChange = Real(1e-4);  // m/s

/// Friction and restitution of a pair, per the scene contract: sqrt(f_a f_b) and max(r_a, r_b).
Real combinedFriction(const Material& a, const Material& b);
Real combinedRestitution(const Material& a, const Material& b);

/// The friction directions of a contact: the first along the sliding velocity when the bodies
/// slide (so the friction pyramid's edge lines up with the motion and bounds it by exactly
/// mu lambda), else any direction perpendicular to the normal.
void frictionDirections(const Vec3& normal, const Vec3& relativeVelocity, Vec3& tangent1, Vec3& tangent2);

/// Builds the rows of every contact point in World::contacts for a step of dt, with effective
/// masses filled in, against velocities as `bodies` holds them (after gravity, before the solve).
/// `approachBodies`, when given, holds the velocities from before this step's forces: the
/// approach speed that restitution reverses is taken from them, as Box2D does (its contact
/// "relax" velocity is measured before the velocity integration). Without them the approach
/// speed includes this step's gravity, and a ball with e = 1 gains about v dt of height per
/// bounce (tests/ch04/bounce_test.cpp).
ContactRows buildContactRows(const World& world, const std::vector<SolverBody>& bodies, Real dt,
                             const std::vector<SolverBody>* approachBodies = nullptr);

/// Copies the solved impulses into World::contacts (normalImpulse; tangentImpulse in the fixed
/// basis u1 = anyPerpendicular(normal), u2 = normal x u1, so the numbers do not depend on the
/// sliding direction this step happened to use), then removes the points that carried less than
/// kDropVelocityChange and the contacts left without points. Returns how many points it removed.
int storeContactImpulses(World& world, const ContactRows& contactRows);

/// What one call of solveContacts did, for tests, benches and the demo panel.
struct SolveStats {
    int contactPoints = 0;      // in World::contacts before the solve
    int rows = 0;
    int pointsRemoved = 0;      // taken out of World::contacts after the solve (no rows, or an
                                // impulse below kDropVelocityChange times the effective mass)
    Residual residual;          // after the last iteration, m/s
};

/// The chapter's stage: gather velocities, build rows, iterate (Settings::solver,
/// Settings::solverIterations), write velocities and impulses back. `approachBodies` as for
/// buildContactRows (ignored unless it has one entry per body).
SolveStats solveContacts(World& world, Real dt, const std::vector<SolverBody>* approachBodies = nullptr);

}  // namespace stepwise
