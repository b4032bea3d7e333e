// The wide solve's kernels are chapter 1's steps and chapter 6's friction, lanes at a time: the
// position step eight at a time and the gyroscopic step sixteen at a time are chapter 1's, and the
// manifold's friction at its centre holds a box on a gentle ramp, lets it slide on a steep one and
// stops a spinning box by its twist.
#include "01_integrators/rotation.h"
#include "04_pgs/scenes.h"
#include "11_wide_solve/chapter.h"
#include "11_wide_solve/contact_kernels.h"
#include "11_wide_solve/solve_steps.h"
#include "11_wide_solve/wide_solver.h"
#include "math/random.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace stepwise;

namespace {

Pipeline fastPipeline(const World& world) {
    SkipWorkOptions options;
    options.sleeping = false;
    return makeChapter11Pipeline(world, options, WideSolveOptions{});
}

}  // namespace
TEST_CASE("the position step eight at a time is chapter 1's rotation step", "[ch11][solve]") {
    Random random(7);
    std::vector<SolverBodyState> states(1 + 19);  // slot 0 and 19 bodies: two packs and a remainder
    std::vector<Quat> expected(states.size());
    for (std::size_t slot = 1; slot < states.size(); ++slot) {
        SolverBodyState& state = states[slot];
        const Quat start = random.rotation();
        for (int k = 0; k < 3; ++k) {
            state.linearVelocity[k] = random.uniformReal(-3, 3);
            state.angularVelocity[k] = random.uniformReal(-20, 20);
        }
        state.deltaRotation[0] = start.x();
        state.deltaRotation[1] = start.y();
        state.deltaRotation[2] = start.z();
        state.deltaRotation[3] = start.w();
        if (slot == 3) state.angularVelocity[0] = 10000;
        const Vec3 angular(state.angularVelocity[0], state.angularVelocity[1], state.angularVelocity[2]);
        expected[slot] = turnRotation(start, angular, Real(1.0 / 600));
    }
    // The wide file's own loop (packs of kWideLanes, then one at a time): the wide kernels are
    // instantiated only there, built for AVX2 or AVX-512; one instantiated here too, built for
    // SSE2, would be a second definition of the same template with another calling convention. One
    // body in the first pack spins too fast for the series (10,000 rad/s: 8.3 rad a step): it takes
    // chapter 1's step, and the other lanes of its pack the series.
    const int count = static_cast<int>(states.size());
    integratePositionsWide(states.data(), count, Real(1.0 / 600), Real(1), /*firstDynamic=*/count);  // none held
    for (std::size_t slot = 1; slot < states.size(); ++slot) {
        const SolverBodyState& state = states[slot];
        const Quat turned(state.deltaRotation[3], state.deltaRotation[0], state.deltaRotation[1], state.deltaRotation[2]);
        CHECK(std::abs(std::abs(turned.coeffs().dot(expected[slot].coeffs())) - 1) < 1e-6);
        CHECK(std::abs(turned.norm() - 1) < 1e-6);
        CHECK(state.deltaPosition[0] == Approx(state.linearVelocity[0] / 600).margin(1e-7));
    }
    CHECK(states[0].deltaRotation[3] == 1);  // slot 0 is never moved
}

TEST_CASE("the position step holds a dynamic body's spin as holdSpin does, bit for bit", "[ch11][solve]") {
    // Slots 1-3 kinematic, the rest dynamic; some spin faster than the most a substep allows.
    Random random(5);
    SolverBodies held;
    held.states.resize(1 + 21);
    held.firstDynamic = 4;
    const Real most = 30;
    int fast = 0;
    for (std::size_t slot = 1; slot < held.states.size(); ++slot) {
        SolverBodyState& state = held.states[slot];
        const Real speed = slot % 3 == 0 ? Real(80) : Real(10);
        for (int k = 0; k < 3; ++k) state.angularVelocity[k] = speed * random.uniformReal(-1, 1);
        state.deltaRotation[3] = 1;
        fast += slot >= 4 && std::sqrt(state.angularVelocity[0] * state.angularVelocity[0] +
                                       state.angularVelocity[1] * state.angularVelocity[1] +
                                       state.angularVelocity[2] * state.angularVelocity[2]) > most;
    }
    REQUIRE(fast >= 3);
    SolverBodies reference = held;
    const Real h = Real(1.0 / 600);
    const int count = static_cast<int>(held.states.size());
    holdSpin(reference, most);  // the scalar rule, then the step holding nothing
    integratePositionsWide(reference.states.data(), count, h, most, /*firstDynamic=*/count);
    integratePositionsWide(held.states.data(), count, h, most, held.firstDynamic);
    for (std::size_t slot = 1; slot < held.states.size(); ++slot) {
        const SolverBodyState& a = held.states[slot];
        const SolverBodyState& b = reference.states[slot];
        for (int k = 0; k < 3; ++k) CHECK(a.angularVelocity[k] == b.angularVelocity[k]);
        for (int k = 0; k < 4; ++k) CHECK(a.deltaRotation[k] == b.deltaRotation[k]);
    }
    // A kinematic body keeps its spin whatever it is.
    CHECK(held.states[3].angularVelocity[0] == reference.states[3].angularVelocity[0]);
    const Real* kinematic = held.states[3].angularVelocity;
    CHECK(kinematic[0] * kinematic[0] + kinematic[1] * kinematic[1] + kinematic[2] * kinematic[2] > most * most);
}

TEST_CASE("the gyroscopic step sixteen bodies at a time is chapter 1's", "[ch11][solve]") {
    Random random(11);
    // Two packs and a remainder; full symmetric inertias (a hull's), a body at rest, one spinning
    // fast enough that the Newton step matters, and one without inertia (chapter 1 keeps its velocity).
    SolverBodies bodies;
    bodies.states.resize(1 + 37);
    std::vector<Vec3> expected(bodies.states.size(), Vec3::Zero());
    const Real h = Real(1.0 / 120);
    for (std::size_t slot = 1; slot < bodies.states.size(); ++slot) {
        SolverBodyState& state = bodies.states[slot];
        const Real speed = slot == 5 ? Real(0) : slot == 9 ? Real(300) : Real(8);
        for (int k = 0; k < 3; ++k) state.angularVelocity[k] = speed * random.uniformReal(-1, 1);
        const Quat delta = random.rotation(), start = random.rotation(), axes = random.rotation();
        state.deltaRotation[0] = delta.x(), state.deltaRotation[1] = delta.y();
        state.deltaRotation[2] = delta.z(), state.deltaRotation[3] = delta.w();
        const Vec3 principal(random.uniformReal(1, 3), random.uniformReal(1, 3), random.uniformReal(1, 3));
        const Mat3 inertia = slot == 13 ? Mat3::Zero() : Mat3(axes * principal.asDiagonal() * axes.conjugate());
        GyroscopicBody body;
        body.slot = static_cast<int>(slot);
        body.startRotation[0] = start.x(), body.startRotation[1] = start.y();
        body.startRotation[2] = start.z(), body.startRotation[3] = start.w();
        body.inertia[0] = inertia(0, 0), body.inertia[1] = inertia(1, 1), body.inertia[2] = inertia(2, 2);
        body.inertia[3] = inertia(0, 1), body.inertia[4] = inertia(0, 2), body.inertia[5] = inertia(1, 2);
        bodies.gyroscopic.push_back(body);
        const Vec3 angular(state.angularVelocity[0], state.angularVelocity[1], state.angularVelocity[2]);
        expected[slot] = gyroscopicStepImplicit(angular, (delta * start).normalized(), inertia, h);
    }
    const Vec3 fastBefore(bodies.states[9].angularVelocity[0], bodies.states[9].angularVelocity[1],
                          bodies.states[9].angularVelocity[2]);
    gyroscopicStepWide(bodies.states.data(), bodies.gyroscopic, h);
    for (std::size_t slot = 1; slot < bodies.states.size(); ++slot) {
        const SolverBodyState& state = bodies.states[slot];
        const Vec3 turned(state.angularVelocity[0], state.angularVelocity[1], state.angularVelocity[2]);
        INFO("slot " << slot);
        CHECK((turned - expected[slot]).norm() <= 1e-5 * std::max(Real(1), expected[slot].norm()));
    }
    CHECK(bodies.states[5].angularVelocity[0] == 0);  // at rest stays at rest, exactly
    // The fast spin's step turned it by far more than the tolerance: the comparison is not of two no-ops.
    const SolverBodyState& fast = bodies.states[9];
    CHECK((Vec3(fast.angularVelocity[0], fast.angularVelocity[1], fast.angularVelocity[2]) - fastBefore).norm() > 1);
}

TEST_CASE("friction at the manifold's centre: a box sticks below atan(mu), slides above, and a spin stops by its twist",
          "[ch11][friction]") {
    const Real mu = Real(0.5);
    for (const Real tilt : {std::atan(mu) - Real(0.1), std::atan(mu) + Real(0.1)}) {
        World world;
        world.settings.sleeping = false;
        const Quat slope(Eigen::AngleAxis<Real>(tilt, Vec3::UnitZ()));
        Material ramp;
        ramp.friction = mu;
        addStaticBox(world, "ramp", Vec3::Zero(), Vec3(10, Real(0.5), 10), slope, ramp);
        Material crate;
        crate.friction = mu;
        const int box = addCrate(world, "box", slope * Vec3(0, 1, 0), Vec3::Constant(Real(0.5)), 1, crate, slope);
        Pipeline pipeline = fastPipeline(world);
        for (int frame = 0; frame < 120; ++frame) pipeline.step(world);
        const Real moved = (world.bodies[static_cast<std::size_t>(box)].transform.position - slope * Vec3(0, 1, 0)).norm();
        INFO("tilt " << tilt << " rad, moved " << moved << " m in 2 s");
        if (tilt < std::atan(mu))
            CHECK(moved < Real(0.01));
        else  // slides from rest: g (sin - mu cos) t^2 / 2 in 2 s
            CHECK(moved == Approx(Real(9.81) * (std::sin(tilt) - mu * std::cos(tilt)) * 2).epsilon(0.05));
    }

    // A unit box spinning on its face: four corners 0.71 m out, mu m g each quarter: the twist
    // decelerates it at mu m g 0.71 / I = 20.8 rad/s^2 (I = m / 6), so 5 rad/s stops in 0.24 s.
    World world;
    world.settings.sleeping = false;
    addGroundPlane(world, mu);
    Material crate;
    crate.friction = mu;
    const int box = addCrate(world, "spinner", Vec3(0, Real(0.5), 0), Vec3::Constant(Real(0.5)), 1, crate);
    Pipeline pipeline = fastPipeline(world);
    for (int frame = 0; frame < 10; ++frame) pipeline.step(world);
    world.motionOf(box)->angularVelocity = Vec3(0, 5, 0);
    int framesToStop = 0;
    while (world.motionOf(box)->angularVelocity.norm() > Real(0.05) && framesToStop < 120) {
        pipeline.step(world);
        ++framesToStop;
    }
    INFO("stopped after " << framesToStop << " frames");
    CHECK(framesToStop >= 11);  // 0.18 s
    CHECK(framesToStop <= 18);  // 0.30 s
    CHECK(world.bodies[static_cast<std::size_t>(box)].transform.position.head<2>().norm() < Real(0.52));
}
