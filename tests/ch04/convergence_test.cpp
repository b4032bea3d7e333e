// Gauss-Seidel against Jacobi on one frozen set of rows: the same rows, the same start, only the
// method differs.
#include "04_pgs/chapter.h"
#include "04_pgs/contact_constraints.h"
#include "04_pgs/scenes.h"

#include <catch2/catch.hpp>

using namespace stepwise;

namespace {

struct Frozen {
    std::vector<ConstraintRow> rows;
    std::vector<SolverBody> bodies;
};

// The sphere pit after 20 frames, while the balls land on each other, frozen at the next
// frame's solve. (In the settled pile the residual left is mostly the pile's slow chains, and
// the first one or two sweeps of either method leave about the same; bench `solver` shows both.)
Frozen freezePit() {
    World world = buildSpherePitScene(40);
    Pipeline pipeline = makeChapter04Pipeline(world);
    for (int frame = 0; frame < 20; ++frame) pipeline.step(world);
    for (Stage& stage : pipeline.stages()) {
        if (stageGroup(stage.name) == "solve") break;
        stage.run(world, world.settings.dt);
    }
    Frozen frozen;
    frozen.bodies = gatherSolverBodies(world);
    frozen.rows = buildContactRows(world, frozen.bodies, world.settings.dt).rows;
    return frozen;
}

Real residualAfter(const Frozen& frozen, SolverKind kind, int iterations) {
    std::vector<ConstraintRow> rows = frozen.rows;
    std::vector<SolverBody> bodies = frozen.bodies;
    solveRows(rows, bodies, kind, iterations);
    return measureResidual(rows, bodies).rms;
}

}  // namespace

TEST_CASE("on a fixed contact set Gauss-Seidel leaves a lower residual than Jacobi for the same iterations",
          "[ch04][convergence]") {
    const Frozen frozen = freezePit();
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
