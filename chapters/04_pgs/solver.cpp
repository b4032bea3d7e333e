#include "04_pgs/solver.h"

#include <algorithm>
#include <cmath>

namespace stepwise {

std::vector<SolverBody> gatherSolverBodies(const World& world) {
    std::vector<SolverBody> bodies(world.bodies.size());
    for (size_t i = 0; i < world.bodies.size(); ++i) {
        const int bodyIndex = static_cast<int>(i);
        SolverBody& solverBody = bodies[i];
        solverBody.center = worldCenterOfMass(world, bodyIndex);
        const Motion* motion = world.motionOf(bodyIndex);
        if (!motion) continue;  // static: no velocity, infinite mass
        solverBody.linearVelocity = motion->linearVelocity;
        solverBody.angularVelocity = motion->angularVelocity;
        if (world.bodies[i].type == BodyType::Dynamic) {
            solverBody.inverseMass = motion->inverseMass;
            solverBody.inverseInertia = worldInverseInertia(world.bodies[i], *motion);
        }
    }
    return bodies;
}

void scatterSolverBodies(World& world, const std::vector<SolverBody>& bodies) {
    for (Motion& motion : world.motions) {
        if (world.bodies[motion.bodyIndex].type != BodyType::Dynamic) continue;  // kinematic: keeps its velocity
        motion.linearVelocity = bodies[motion.bodyIndex].linearVelocity;
        motion.angularVelocity = bodies[motion.bodyIndex].angularVelocity;
    }
}

// [ch04-effective-mass]
// An impulse lambda along the row changes the bodies' velocities by dv = M^-1 J^T lambda, and
// so the row's own velocity by J M^-1 J^T lambda. The effective mass is the inverse of that
// scalar: the impulse that changes J v by exactly 1 m/s.
Real effectiveMass(const ConstraintRow& row, const std::vector<SolverBody>& bodies) {
    const SolverBody& a = bodies[row.bodyA];
    const SolverBody& b = bodies[row.bodyB];
    const Real inverseEffectiveMass = a.inverseMass * row.linearA.squaredNorm() +
                                      row.angularA.dot(a.inverseInertia * row.angularA) +
                                      b.inverseMass * row.linearB.squaredNorm() +
                                      row.angularB.dot(b.inverseInertia * row.angularB);
    return inverseEffectiveMass > 0 ? 1 / inverseEffectiveMass : 0;
}

void computeEffectiveMasses(std::vector<ConstraintRow>& rows, const std::vector<SolverBody>& bodies) {
    for (ConstraintRow& row : rows) row.effectiveMass = effectiveMass(row, bodies);
}
// [ch04-effective-mass]

Real rowVelocity(const ConstraintRow& row, const std::vector<SolverBody>& bodies) {
    const SolverBody& a = bodies[row.bodyA];
    const SolverBody& b = bodies[row.bodyB];
    return row.linearA.dot(a.linearVelocity) + row.angularA.dot(a.angularVelocity) +
           row.linearB.dot(b.linearVelocity) + row.angularB.dot(b.angularVelocity);
}

void applyRowImpulse(const ConstraintRow& row, Real impulse, std::vector<SolverBody>& bodies) {
    SolverBody& a = bodies[row.bodyA];
    SolverBody& b = bodies[row.bodyB];
    a.linearVelocity += a.inverseMass * impulse * row.linearA;
    a.angularVelocity += a.inverseInertia * (impulse * row.angularA);
    b.linearVelocity += b.inverseMass * impulse * row.linearB;
    b.angularVelocity += b.inverseInertia * (impulse * row.angularB);
}

void applyRowImpulses(const std::vector<ConstraintRow>& rows, std::vector<SolverBody>& bodies) {
    for (const ConstraintRow& row : rows)
        if (row.impulse != 0) applyRowImpulse(row, row.impulse, bodies);
}

static void rowBounds(const ConstraintRow& row, const std::vector<ConstraintRow>& rows, Real& lower, Real& upper) {
    if (row.boundRow < 0) {
        lower = row.lower;
        upper = row.upper;
        return;
    }
    upper = row.boundScale * rows[row.boundRow].impulse;
    lower = -upper;
}

// [ch04-pgs]
// One sweep solves each row exactly for the velocities it sees right now, then clamps. The clamp
// is on the accumulated impulse, not on the increment: an increment may be negative (a later
// sweep takes back some of what an earlier one pushed too hard), as long as the total stays a
// push (lambda >= 0) or inside the friction bounds. Clamping each increment instead would keep
// every overshoot forever (Catto, GDC 2006, "accumulated impulses").
void solveGaussSeidel(std::vector<ConstraintRow>& rows, std::vector<SolverBody>& bodies, int iterations) {
    for (int iteration = 0; iteration < iterations; ++iteration) {
        for (ConstraintRow& row : rows) {
            if (row.effectiveMass == 0) continue;
            Real lower, upper;
            rowBounds(row, rows, lower, upper);
            const Real velocityError = row.bias - rowVelocity(row, bodies);
            const Real previous = row.impulse;
            row.impulse = std::clamp(previous + row.effectiveMass * velocityError, lower, upper);
            applyRowImpulse(row, row.impulse - previous, bodies);
        }
    }
}
// [ch04-pgs]

// [ch04-jacobi]
// Jacobi computes every row's increment from the same velocities, so rows that share a body do
// not see each other within an iteration: k contacts under one body each push it by the full
// correction, k times too much, and the iteration overshoots (it can diverge). Each increment is
// therefore divided by the number of constraints on the busier of its two dynamic bodies, the
// averaging of "mass splitting" (Tonge, Benevolenski and Voroshilov, "Mass splitting for
// jitter-free parallel rigid body simulation", SIGGRAPH 2012). A constraint is a row with its own
// bounds; friction rows count with their normal row.
void solveJacobi(std::vector<ConstraintRow>& rows, std::vector<SolverBody>& bodies, int iterations) {
    std::vector<int> constraintsOnBody(bodies.size(), 0);
    for (const ConstraintRow& row : rows) {
        if (row.boundRow >= 0) continue;
        if (bodies[row.bodyA].inverseMass > 0) ++constraintsOnBody[row.bodyA];
        if (bodies[row.bodyB].inverseMass > 0) ++constraintsOnBody[row.bodyB];
    }
    std::vector<Real> relaxation(rows.size(), 1);
    for (size_t i = 0; i < rows.size(); ++i) {
        const int busiest = std::max({1, constraintsOnBody[rows[i].bodyA], constraintsOnBody[rows[i].bodyB]});
        relaxation[i] = Real(1) / static_cast<Real>(busiest);
    }

    std::vector<Real> nextImpulse(rows.size());
    for (int iteration = 0; iteration < iterations; ++iteration) {
        // Every row reads the same velocities and the same (previous) normal impulses.
        for (size_t i = 0; i < rows.size(); ++i) {
            const ConstraintRow& row = rows[i];
            nextImpulse[i] = row.impulse;
            if (row.effectiveMass == 0) continue;
            Real lower, upper;
            rowBounds(row, rows, lower, upper);
            const Real velocityError = row.bias - rowVelocity(row, bodies);
            nextImpulse[i] = std::clamp(row.impulse + relaxation[i] * row.effectiveMass * velocityError, lower, upper);
        }
        // Then all increments are applied at once.
        for (size_t i = 0; i < rows.size(); ++i) {
            const Real increment = nextImpulse[i] - rows[i].impulse;
            rows[i].impulse = nextImpulse[i];
            if (increment != 0) applyRowImpulse(rows[i], increment, bodies);
        }
    }
}
// [ch04-jacobi]

void solveRows(std::vector<ConstraintRow>& rows, std::vector<SolverBody>& bodies, SolverKind kind, int iterations) {
    if (kind == SolverKind::Jacobi)
        solveJacobi(rows, bodies, iterations);
    else
        solveGaussSeidel(rows, bodies, iterations);
}

Residual measureResidual(const std::vector<ConstraintRow>& rows, const std::vector<SolverBody>& bodies) {
    Residual residual;
    double sumSquares = 0;
    int counted = 0;
    for (const ConstraintRow& row : rows) {
        if (row.effectiveMass == 0) continue;
        Real lower, upper;
        rowBounds(row, rows, lower, upper);
        const Real velocityError = rowVelocity(row, bodies) - row.bias;
        const Real projected = std::clamp(row.impulse - row.effectiveMass * velocityError, lower, upper);
        const Real rowResidual = std::abs(row.impulse - projected) / row.effectiveMass;
        sumSquares += static_cast<double>(rowResidual) * rowResidual;
        residual.max = std::max(residual.max, rowResidual);
        ++counted;
    }
    residual.rms = counted ? static_cast<Real>(std::sqrt(sumSquares / counted)) : 0;
    return residual;
}

}  // namespace stepwise
