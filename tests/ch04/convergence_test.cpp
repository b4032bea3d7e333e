// Gauss-Seidel against Jacobi on one frozen set of rows: the same rows, the same start, only the
// method differs.
#include "04_pgs/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "04_pgs/frozen_rows.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

Real residualAfter(const FrozenRows& frozen, SolverKind kind, int iterations) {
    std::vector<ConstraintRow> rows = frozen.rows;
    std::vector<SolverBody> bodies = frozen.bodies;
    solveRows(rows, bodies, kind, iterations);
    return measureResidual(rows, bodies).rms;
}

}  // namespace

TEST_CASE("on a fixed contact set Gauss-Seidel leaves a lower residual than Jacobi for the same iterations",
          "[ch04][convergence]") {
    const FrozenRows frozen = freezeSpherePitRows(40, 20);
    REQUIRE(frozen.rows.size() > 60);  // a real pile: many coupled rows
    Real previous = kRealMax;
    for (int iterations : {1, 2, 4, 8, 16, 32}) {
        const Real gaussSeidel = residualAfter(frozen, SolverKind::GaussSeidel, iterations);
        const Real jacobi = residualAfter(frozen, SolverKind::Jacobi, iterations);
        INFO(iterations << " iterations: Gauss-Seidel " << gaussSeidel << " m/s, Jacobi " << jacobi << " m/s");
        CHECK(gaussSeidel < jacobi);
        CHECK(gaussSeidel < previous);  // and more iterations help
        previous = gaussSeidel;
    }
}
