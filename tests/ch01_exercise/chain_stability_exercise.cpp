// Exercise check for chapter 1 (`ctest -L ch01-exercise`), the derive exercise: at which spring
// stiffness does each chain of `integrators-side-by-side` blow up? The page's answer: a chain of
// two equal masses m on two equal springs k, hung from an anchor, has the stiffness matrix
// k [[2, -1], [-1, 1]] along its length; its eigenvalues are k (3 -+ sqrt 5) / 2, so the fast
// mode has w^2 = phi^2 k / m with phi = (1 + sqrt 5) / 2, and a method that is stable while
// h w < c blows up from
//     k* = m (c / (h phi))^2,      c = 2 (semi-implicit Euler, Verlet), 2 sqrt 2 (RK4).
// This test finds k* on the scene's chains by bisection and compares it with the formula.
// Another answer fails it: one mass on one spring (phi = 1) puts k* 2.6 times too high.
#include "01_integrators/integrate.h"
#include "01_integrators/scenes.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace stepwise;

namespace {

// The derivation above, for the scene's masses and step.
double predictedBlowUp(IntegratorKind method, double h, double mass) {
    const double phi = (1 + std::sqrt(5.0)) / 2;
    const double limit = method == IntegratorKind::Rk4 ? 2 * std::sqrt(2.0) : 2;   // h w at the edge
    return mass * std::pow(limit / (h * phi), 2);
}

// The chains of the scene: each anchor with the two bodies hanging from it.
struct Chain {
    Vec3 anchor;
    int upper = -1, lower = -1;
};

std::vector<Chain> chainsOf(const World& world) {
    std::vector<Chain> chains;
    for (const Spring& top : world.springs) {
        if (top.bodyB >= 0) continue;   // the top spring hangs from a point of the world
        Chain chain{top.anchorB, top.bodyA, -1};
        for (const Spring& link : world.springs)
            if (link.bodyB == chain.upper) chain.lower = link.bodyA;
        chains.push_back(chain);
    }
    return chains;
}

// The scene as the demo starts it (`straight` false), or with every chain hung straight down,
// 20 cm and 40 cm below its rest pose: then each chain moves along one vertical line and its
// springs act exactly as the linear chain of the derivation.
World chainScene(bool straight) {
    World world = buildIntegratorsSideBySide();
    if (!straight) return world;
    for (const Chain& chain : chainsOf(world)) {
        world.bodies[chain.upper].transform.position = chain.anchor - Vec3(0, Real(1.2), 0);
        world.bodies[chain.lower].transform.position = chain.anchor - Vec3(0, Real(2.4), 0);
    }
    return world;
}

// Runs the scene for `seconds` at stiffness k and says whether `method`'s chain blew up: a body
// left the ball of twice the chain's length (4 m) around its anchor, or stopped being a number.
// A bounded swing stays well inside. A mode past its limit grows by a factor every step and
// leaves within a few dozen; once far out, the springs' rest length makes the motion wild but
// no longer linear, so the energy alone is a poor witness.
bool blowsUp(IntegratorKind method, double stiffness, double seconds, bool straight) {
    World world = chainScene(straight);
    for (Spring& spring : world.springs) spring.stiffness = Real(stiffness);
    const std::vector<Chain> chains = chainsOf(world);
    const int frames = static_cast<int>(seconds / double(world.settings.dt));
    for (int frame = 0; frame < frames; ++frame) {
        integrate(world, world.settings.dt);
        for (const Chain& chain : chains) {
            if (integratorOf(world, *world.motionOf(chain.upper)) != method) continue;
            for (int body : {chain.upper, chain.lower}) {
                const Vec3 offset = world.bodies[body].transform.position - chain.anchor;
                if (!offset.allFinite() || offset.norm() > 4) return true;
            }
        }
    }
    return false;
}

// The smallest stiffness (to 0.5%) at which the chain blows up within `seconds`.
double measuredBlowUp(IntegratorKind method, double seconds, bool straight) {
    double stable = 1000, unstable = 40000;
    REQUIRE(!blowsUp(method, stable, seconds, straight));
    REQUIRE(blowsUp(method, unstable, seconds, straight));
    while (unstable - stable > 0.005 * stable) {
        const double middle = 0.5 * (stable + unstable);
        (blowsUp(method, middle, seconds, straight) ? unstable : stable) = middle;
    }
    return unstable;
}

const IntegratorKind kMethods[3] = {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet, IntegratorKind::Rk4};

}  // namespace

TEST_CASE("exercise: a straight chain blows up where h w = 2 (2 sqrt 2 for RK4) for its fast mode", "[ch01-exercise]") {
    const World scene = buildIntegratorsSideBySide();
    const double h = double(scene.settings.dt);
    const double mass = double(scene.motions[0].mass);   // every body of the scene weighs the same
    for (IntegratorKind method : kMethods) {
        const double predicted = predictedBlowUp(method, h, mass);
        const double measured = measuredBlowUp(method, 10, true);
        WARN(toString(method) << ", straight chain: blows up from k = " << measured << " N/m; the formula says "
                              << predicted << " N/m");
        CHECK(measured == Approx(predicted).epsilon(0.01));
    }
}

TEST_CASE("exercise: the swinging chains of the demo blow up near the same stiffness", "[ch01-exercise]") {
    // Swinging in 3D, a chain is bent most of the time, and a bent chain's fast mode is slower
    // (w^2 falls towards 2 k / m with the springs at right angles); the stretch of the swing
    // also shakes the springs. So the demo's slider finds the edge near the formula, not on it.
    const World scene = buildIntegratorsSideBySide();
    const double h = double(scene.settings.dt);
    const double mass = double(scene.motions[0].mass);
    for (IntegratorKind method : kMethods) {
        const double predicted = predictedBlowUp(method, h, mass);
        const double measured = measuredBlowUp(method, 10, false);
        WARN(toString(method) << ", swinging chain: blows up from k = " << measured << " N/m within 10 s; the formula says "
                              << predicted << " N/m");
        CHECK(measured == Approx(predicted).epsilon(0.2));
    }
}
