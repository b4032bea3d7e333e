// A block in which no lane holds an impulse and no lane asks for one is skipped (holdsNoImpulse,
// block_solve.h): its sweep would push every body by zero. The reference is the same block swept
// in full: a lane given restitution makes the kernel keep approach speeds for the restitution
// pass, which turns the skip off and changes no impulse and no velocity.
#include "04_pgs/scenes.h"
#include "10_skip_work/scenes.h"
#include "11_wide_solve/block_solve.h"
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/solve_steps.h"

#include <catch2/catch.hpp>

#include <limits>
#include <vector>

using namespace stepwise;

namespace {

/// Whether two velocity arrays are equal, component by component (-0 equals +0).
bool sameVelocities(const std::vector<SolverBodyState>& a, const std::vector<SolverBodyState>& b) {
    for (std::size_t slot = 0; slot < a.size(); ++slot)
        for (int k = 0; k < 3; ++k)
            if (a[slot].linearVelocity[k] != b[slot].linearVelocity[k] ||
                a[slot].angularVelocity[k] != b[slot].angularVelocity[k])
                return false;
    return true;
}

struct IdleCount {
    int idle = 0;  // sweeps of blocks that hold nothing and left every velocity as it was
    int held = 0;  // blocks that hold an impulse
};

/// Sweeps every block that holds no impulse, biased and relaxed, and checks that it gives what its
/// full sweep gives: the same velocities and the same impulses.
template <int N>
IdleCount compareWithFullSweeps(const std::vector<ManifoldBlock<N>>& blocks, const std::vector<SolverBodyState>& states,
                                const ContactSolveParams& params) {
    IdleCount count;
    for (const ManifoldBlock<N>& block : blocks) {
        if (!holdsNoImpulse(block)) {
            ++count.held;
            continue;
        }
        for (const bool useBias : {true, false}) {
            ManifoldBlock<N> swept = block;
            std::vector<SolverBodyState> sweptStates = states;
            solveAnyBlock(swept, sweptStates.data(), params, useBias);
            // The full sweep: a little restitution in the first lane turns the skip off.
            ManifoldBlock<N> full = block;
            full.restitution[0] = Real(0.01);
            std::vector<SolverBodyState> fullStates = states;
            solveAnyBlock(full, fullStates.data(), params, useBias);
            INFO("block of contact " << block.contactIndex[0] << (useBias ? ", biased" : ", relax"));
            CHECK(sameVelocities(sweptStates, fullStates));
            for (int lane = 0; lane < N; ++lane) {
                for (int k = 0; k < 4; ++k) CHECK(swept.point[k].normalImpulse[lane] == full.point[k].normalImpulse[lane]);
                CHECK(swept.tangentImpulse1[lane] == full.tangentImpulse1[lane]);
                CHECK(swept.tangentImpulse2[lane] == full.tangentImpulse2[lane]);
                CHECK(swept.twistImpulse[lane] == full.twistImpulse[lane]);
            }
            count.idle += sameVelocities(sweptStates, states) ? 1 : 0;
        }
    }
    return count;
}

/// One more frame's solve on `path`, its blocks left in `scratch`; the parameters of its substeps.
ContactSolveParams solveOneFrame(World& world, SolverPath path, ContactSolverScratch& scratch) {
    solveFast(world, world.settings.dt, path, scratch);
    const Real substeps = static_cast<Real>(std::max(1, world.step.iterationPlan.iterations));
    return solveParams(world.settings, world.settings.dt / substeps, world.settings.dt);
}

}  // namespace

TEST_CASE("a block that holds nothing answers as its full sweep does",
          "[ch11][solve]") {
    World world = buildPyramidRow(1, 20, kTouchingSpacing);
    world.settings.sleeping = false;  // settled rows would sleep, and a sleeping frame solves nothing
    Pipeline pipeline = makeChapter11Pipeline(world, SkipWorkOptions{}, WideSolveOptions{});
    for (int frame = 0; frame < 60; ++frame) pipeline.step(world);  // the rows have settled

    ContactSolverScratch scratch;
    const ContactSolveParams params = solveOneFrame(world, SolverPath::Wide, scratch);
    const IdleCount count = compareWithFullSweeps(scratch.wideBlocks, scratch.bodies.states, params);
    const int idle = count.idle, held = count.held;
    // Neighbours in a row touch and carry nothing: whole blocks of them have nothing to do, while
    // the blocks of the boxes that carry the rows above hold their load.
    CHECK(idle >= 4);
    CHECK(held >= 30);
}

TEST_CASE("holdsNoImpulse counts any impulse, and NaN, as held", "[ch11][solve]") {
    ManifoldBlock<kWideLanes> block;
    const auto clear = [&] {
        for (int lane = 0; lane < kWideLanes; ++lane) {
            for (ManifoldPointPack<kWideLanes>& point : block.point) point.normalImpulse[lane] = 0;
            block.tangentImpulse1[lane] = block.tangentImpulse2[lane] = block.twistImpulse[lane] = 0;
            block.rollingImpulse.x[lane] = block.rollingImpulse.y[lane] = block.rollingImpulse.z[lane] = 0;
        }
    };
    clear();
    CHECK(holdsNoImpulse(block));
    block.twistImpulse[kWideLanes - 1] = -Real(0);  // minus zero is zero
    CHECK(holdsNoImpulse(block));
    block.rollingImpulse.z[kWideLanes - 1] = Real(1e-30);
    CHECK_FALSE(holdsNoImpulse(block));
    clear();
    block.point[3].normalImpulse[2] = std::numeric_limits<Real>::quiet_NaN();
    CHECK_FALSE(holdsNoImpulse(block));
}

TEST_CASE("a block of single points that holds nothing answers as its full sweep does", "[ch11][solve]") {
    World world = buildSpherePitScene();
    world.settings.sleeping = false;
    WideSolveOptions wide;
    wide.solverPath = SolverPath::Scalar;
    Pipeline pipeline = makeChapter11Pipeline(world, SkipWorkOptions{}, wide);
    for (int frame = 0; frame < 90; ++frame) pipeline.step(world);  // the balls have landed

    ContactSolverScratch scratch;
    const ContactSolveParams params = solveOneFrame(world, SolverPath::Scalar, scratch);
    const IdleCount count = compareWithFullSweeps(scratch.scalarBlocks, scratch.bodies.states, params);
    // Balls resting on one another hold their loads; those only near one another hold nothing.
    CHECK(count.held >= 20);
    CHECK(count.idle >= 20);
}
