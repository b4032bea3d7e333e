// A block of single points (ManifoldBlock::singlePoint) takes chapter 4's row update, one row a
// lane (solveSinglePoint), where any other block takes the four rows as one block. For one point
// the block's answer is that row's, so the two kernels must agree on every single-point block a
// pile of balls makes: the same impulses and the same velocities, up to the block's
// regularisation (kNormalBlockRegularisation, 1e-3 of the effective mass, so of each sweep's change).
#include "04_pgs/scenes.h"
#include "11_wide_solve/block_solve.h"
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/solve_steps.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace stepwise;

namespace {

/// The largest difference between two velocity arrays, over every slot and component.
Real largestVelocityGap(const std::vector<SolverBodyState>& a, const std::vector<SolverBodyState>& b) {
    Real gap = 0;
    for (std::size_t slot = 0; slot < a.size(); ++slot)
        for (int k = 0; k < 3; ++k) {
            gap = std::max(gap, std::abs(a[slot].linearVelocity[k] - b[slot].linearVelocity[k]));
            gap = std::max(gap, std::abs(a[slot].angularVelocity[k] - b[slot].angularVelocity[k]));
        }
    return gap;
}

}  // namespace

TEST_CASE("a block of single points answers as the four-row block does", "[ch11][solve]") {
    World world = buildSpherePitScene();
    SkipWorkOptions skip;
    WideSolveOptions wide;
    wide.solverPath = SolverPath::Scalar;
    Pipeline pipeline = makeChapter11Pipeline(world, skip, wide);
    for (int frame = 0; frame < 90; ++frame) pipeline.step(world);  // the balls have landed

    // One more frame's solve on the scalar path, whose blocks hold one contact each.
    ContactSolverScratch scratch;
    solveFast(world, world.settings.dt, SolverPath::Scalar, scratch);
    const Real substeps = static_cast<Real>(std::max(1, world.step.iterationPlan.iterations));
    const ContactSolveParams params = solveParams(world.settings, world.settings.dt / substeps, world.settings.dt);
    int compared = 0, pushing = 0;
    for (const ManifoldBlock<1>& block : scratch.scalarBlocks) {
        if (!block.singlePoint || block.pointCount[0] != 1) continue;
        for (const bool useBias : {true, false}) {
            ManifoldBlock<1> byBlock = block, byRow = block;
            std::vector<SolverBodyState> blockStates = scratch.bodies.states, rowStates = scratch.bodies.states;
            solveBlock(byBlock, blockStates.data(), params, useBias);
            solveSinglePointBlock(byRow, rowStates.data(), params, useBias);
            const Real impulse = byBlock.point[0].normalImpulse[0];
            INFO("contact " << block.contactIndex[0] << (useBias ? ", biased" : ", relax") << ": block " << impulse
                            << " N s, row " << byRow.point[0].normalImpulse[0] << " N s");
            // The regularisation scales the sweep's change of impulse, not the impulse it adds to.
            const Real before = block.point[0].normalImpulse[0];
            const Real tolerance = Real(2e-3) * std::abs(impulse - before) + Real(1e-6) * std::abs(before) + Real(1e-9);
            CHECK(std::abs(byRow.point[0].normalImpulse[0] - impulse) <= tolerance);
            // The velocities differ by what the impulses differ by, and by the friction that the
            // normal impulse bounds: within a few thousandths of the change the block made.
            const Real change = largestVelocityGap(scratch.bodies.states, blockStates);
            CHECK(largestVelocityGap(blockStates, rowStates) <= Real(5e-3) * change + Real(1e-6));
            ++compared;
            pushing += impulse > 0 ? 1 : 0;
        }
    }
    // The pit's balls rest on the floor and on one another: blocks of one point, most pushing.
    CHECK(compared >= 40);
    CHECK(pushing >= compared / 2);
}
