// Exercise check for chapter 4 (`ctest -L ch04-exercise`): rewrite computeEffectiveMasses in
// chapters/04_pgs/solver.cpp from the page's formula 1 / (J M^-1 J^T), and run this. A single
// row with no bounds must be solved exactly by one Gauss-Seidel iteration: after it, J v equals
// the row's target, whatever the masses, inertias and arms. A wrong effective mass overshoots
// or undershoots, and the message says by how much.
#include "04_pgs/solver.h"

#include <catch2/catch.hpp>

#include <random>

using namespace stepwise;

namespace {

Vec3 randomVector(std::mt19937& random, double scale) {
    std::uniform_real_distribution<double> component(-scale, scale);
    return Vec3(Real(component(random)), Real(component(random)), Real(component(random)));
}

SolverBody randomBody(std::mt19937& random, bool movable) {
    std::uniform_real_distribution<double> positive(0.2, 5);
    SolverBody body;
    body.linearVelocity = randomVector(random, 3);
    body.angularVelocity = randomVector(random, 3);
    body.center = randomVector(random, 2);
    if (movable) {
        body.inverseMass = Real(positive(random));
        // A symmetric positive definite inverse inertia: A A^T plus a little of the identity.
        Mat3 a;
        for (int i = 0; i < 9; ++i) a.data()[i] = Real(positive(random) - 2.5);
        body.inverseInertia = a * a.transpose() + Real(0.1) * Mat3::Identity();
    }
    return body;
}

}  // namespace

TEST_CASE("exercise: one Gauss-Seidel iteration solves a single row exactly", "[ch04-exercise]") {
    std::mt19937 random(2024);
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<SolverBody> bodies = {randomBody(random, true), randomBody(random, trial % 4 != 0)};
        const Vec3 normal = randomVector(random, 1).normalized();
        const Vec3 point = randomVector(random, 2);
        const Vec3 armA = point - bodies[0].center;
        const Vec3 armB = point - bodies[1].center;
        ConstraintRow row;
        row.bodyA = 0;
        row.bodyB = 1;
        row.linearA = -normal;
        row.angularA = -armA.cross(normal);
        row.linearB = normal;
        row.angularB = armB.cross(normal);
        row.bias = Real(0.5);
        std::vector<ConstraintRow> rows = {row};
        computeEffectiveMasses(rows, bodies);
        solveGaussSeidel(rows, bodies, 1);
        const Real after = rowVelocity(rows[0], bodies);
        INFO("trial " << trial << ": J v after one iteration is " << after << ", the target is 0.5 (effective mass "
                      << rows[0].effectiveMass << " kg)");
        REQUIRE(std::abs(after - Real(0.5)) < 1e-3);
    }
}

TEST_CASE("exercise: a row between two immovable bodies gets zero effective mass", "[ch04-exercise]") {
    std::mt19937 random(5);
    std::vector<SolverBody> bodies = {randomBody(random, false), randomBody(random, false)};
    ConstraintRow row;
    row.bodyA = 0;
    row.bodyB = 1;
    row.linearA = Vec3(0, -1, 0);
    row.linearB = Vec3(0, 1, 0);
    std::vector<ConstraintRow> rows = {row};
    computeEffectiveMasses(rows, bodies);
    INFO("your effective mass: " << rows[0].effectiveMass << " (it must be 0, not infinite or NaN)");
    REQUIRE(rows[0].effectiveMass == 0);
}
