// Exercise check for the primer's impulses (`ctest -L ch04-exercise`): rewrite applyRowImpulse in
// chapters/04_pgs/solver.cpp from the primer's two formulas, dv = P / m and
// dw = I^-1 (r x P), for the push of a contact row on each of its two bodies, and run this. A
// contact row between random bodies with random arms gets a random impulse; the velocities must
// change as the formulas say, momentum must be conserved, and a body that cannot move must not.
#include "04_pgs/solver.h"

#include "math/random.h"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace stepwise;

namespace {

Vec3 randomVector(Random& random, Real scale) {
    return Vec3(random.uniformReal(-scale, scale), random.uniformReal(-scale, scale), random.uniformReal(-scale, scale));
}

// A body with a random mass and a random symmetric positive definite inertia (A A^T + 0.1 I).
SolverBody randomBody(Random& random, bool movable, Mat3& inertia) {
    SolverBody body;
    body.linearVelocity = randomVector(random, 3);
    body.angularVelocity = randomVector(random, 3);
    body.center = randomVector(random, 2);
    inertia = Mat3::Identity();
    if (movable) {
        Mat3 a;
        for (int i = 0; i < 9; ++i) a.data()[i] = random.uniformReal(-1, 1);
        inertia = a * a.transpose() + Real(0.1) * Mat3::Identity();
        body.inverseMass = 1 / random.uniformReal(Real(0.2), 5);
        body.inverseInertia = inertia.inverse();
    }
    return body;
}

Real relativeError(const Vec3& got, const Vec3& expected) {
    return (got - expected).norm() / std::max(Real(1), expected.norm());
}

}  // namespace

TEST_CASE("exercise: an impulse at a point changes v by P / m and w by I^-1 (r x P)", "[ch04-exercise]") {
    Random random(4004);
    for (int trial = 0; trial < 2000; ++trial) {
        Mat3 inertiaA, inertiaB;
        const bool movableB = trial % 4 != 0;  // every fourth contact is with a static body
        std::vector<SolverBody> bodies = {randomBody(random, true, inertiaA), randomBody(random, movableB, inertiaB)};
        const std::vector<SolverBody> before = bodies;
        const Vec3 normal = randomVector(random, 1).normalized();
        const Vec3 point = randomVector(random, 2);
        const Vec3 armA = point - bodies[0].center, armB = point - bodies[1].center;
        ConstraintRow row;  // the contact row of chapter 4: J = (-n, -(rA x n), n, rB x n)
        row.bodyA = 0;
        row.bodyB = 1;
        row.linearA = -normal;
        row.angularA = -armA.cross(normal);
        row.linearB = normal;
        row.angularB = armB.cross(normal);
        const Real lambda = random.uniformReal(-2, 2);
        applyRowImpulse(row, lambda, bodies);

        // B is pushed by P = lambda n at the point, A by -P.
        const Vec3 impulse = lambda * normal;
        INFO("trial " << trial << ": impulse " << lambda << " N s along (" << normal.transpose() << ")");
        CHECK(relativeError(bodies[0].linearVelocity, before[0].linearVelocity - before[0].inverseMass * impulse) < 1e-4);
        CHECK(relativeError(bodies[0].angularVelocity,
                            before[0].angularVelocity + before[0].inverseInertia * armA.cross(-impulse)) < 1e-4);
        CHECK(relativeError(bodies[1].linearVelocity, before[1].linearVelocity + before[1].inverseMass * impulse) < 1e-4);
        CHECK(relativeError(bodies[1].angularVelocity,
                            before[1].angularVelocity + before[1].inverseInertia * armB.cross(impulse)) < 1e-4);
        if (movableB) {
            // Equal and opposite impulses: the total momentum does not change.
            const Vec3 momentum = bodies[0].linearVelocity / bodies[0].inverseMass + bodies[1].linearVelocity / bodies[1].inverseMass;
            const Vec3 momentumBefore =
                before[0].linearVelocity / before[0].inverseMass + before[1].linearVelocity / before[1].inverseMass;
            CHECK(relativeError(momentum, momentumBefore) < 1e-4);
            // And the angular momentum about the contact point neither (both impulses act there).
            const auto angularMomentum = [&](const std::vector<SolverBody>& state) {
                Vec3 total = Vec3::Zero();
                const Mat3* inertia[2] = {&inertiaA, &inertiaB};
                for (int k = 0; k < 2; ++k) {
                    const SolverBody& body = state[static_cast<std::size_t>(k)];
                    total += *inertia[k] * body.angularVelocity + (body.center - point).cross(body.linearVelocity / body.inverseMass);
                }
                return total;
            };
            CHECK(relativeError(angularMomentum(bodies), angularMomentum(before)) < 1e-3);
        } else {
            CHECK(bodies[1].linearVelocity == before[1].linearVelocity);
            CHECK(bodies[1].angularVelocity == before[1].angularVelocity);
        }
    }
}
