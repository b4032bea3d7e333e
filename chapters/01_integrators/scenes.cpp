#include "01_integrators/scenes.h"

#include "01_integrators/forces.h"
#include "01_integrators/integrate.h"
#include "app/panel.h"
#include "app/registry.h"
#include "world/debug_draw.h"

#include <cstdio>
#include <string>

namespace stepwise {

namespace {

constexpr IntegratorKind kMethods[3] = {IntegratorKind::SemiImplicitEuler, IntegratorKind::Verlet,
                                        IntegratorKind::Rk4};
constexpr Color kMethodColors[3] = {colors::kOrange, colors::kCyan, colors::kMagenta};

int methodSlot(IntegratorKind kind) {
    for (int slot = 0; slot < 3; ++slot)
        if (kMethods[slot] == kind) return slot;
    return 0;
}

std::string formatValue(const char* label, double value, const char* unit) {
    char text[96];
    std::snprintf(text, sizeof text, "%s %.5g %s", label, value, unit);
    return text;
}

int addBall(World& world, const std::string& name, const Vec3& position, Real radius, IntegratorKind method) {
    BodyDef def;
    def.name = name;
    def.shape = Shape::sphere(radius);
    def.transform.position = position;
    def.mass = Real(1);
    def.integrator = method;
    return addBody(world, def);
}

// Labels every moving body with the integrator it uses, just above it.
void labelBodies(const World& world, DebugDraw& draw) {
    for (const Motion& motion : world.motions) {
        const Body& body = world.bodies[motion.bodyIndex];
        const Vec3 above = body.transform.position + Vec3(0, boundingRadius(body.shape) + Real(0.15), 0);
        if (body.type == BodyType::Kinematic) {
            draw.text(above, "kinematic", colors::kBlue);
            continue;
        }
        const IntegratorKind method = integratorOf(world, motion);
        draw.text(above, toString(method), kMethodColors[methodSlot(method)]);
    }
}

void drawSprings(const World& world, DebugDraw& draw) {
    for (const Spring& spring : world.springs) {
        const Vec3 endA = world.bodies[spring.bodyA].transform.apply(spring.localAnchorA);
        const Vec3 endB =
            spring.bodyB < 0 ? spring.anchorB : world.bodies[spring.bodyB].transform.apply(spring.anchorB);
        draw.line(endA, endB, colors::kYellow);
        if (spring.bodyB < 0) draw.point(endB, 8, colors::kWhite);
    }
}

// Kinetic, gravitational and spring energy of the bodies on one method (springs count for the
// body at their A end), so the panel can show each chain's energy drift.
double methodEnergy(const World& world, IntegratorKind method) {
    return computeEnergy(world, [&](int bodyIndex) {
        const Motion* motion = world.motionOf(bodyIndex);
        return motion && integratorOf(world, *motion) == method;
    }).total();
}

// Side by side: the chain geometry, shared by the builder and nothing else.
// N/m. A chain of two 1 kg bodies has its fast mode at w = 1.618 sqrt(k/m), 46 rad/s here:
// h w = 0.76 at 60 Hz, inside every method's limit (h w = 2 at k = 5,500 N/m for Euler and
// Verlet, 2 sqrt 2 at 11,000 N/m for RK4; tests/ch01_exercise/chain_stability_exercise.cpp).
constexpr Real kChainStiffness = 800;
constexpr Real kChainSpacing = 3;       // m between the chains
constexpr Real kAnchorHeight = 5;       // m

// Projectile: the launch, shared by the builder and the draw hook's exact parabola.
const Vec3 kLaunchPoint(-6, 1, 0);
const Vec3 kLaunchVelocity(5, 9, 0);
constexpr Real kProjectileDt = Real(1.0 / 30.0);   // a coarse step makes Euler's lag visible

// T-handle: half extents give inertia ratios 0.1825 : 0.025 : 0.1625 (times 4m/3), so body z
// is the intermediate axis.
const Vec3 kHandleHalfExtents(Real(0.05), Real(0.4), Real(0.15));

}  // namespace

World buildIntegratorsSideBySide() {
    World world = emptyWorld("integrators-side-by-side");
    for (int slot = 0; slot < 3; ++slot) {
        const IntegratorKind method = kMethods[slot];
        const Real x = (slot - 1) * kChainSpacing;
        const std::string prefix = toString(method);
        // Released from a bent, stretched pose so the chains swing and bounce in 3D.
        const int upper = addBall(world, prefix + "-upper", Vec3(x + Real(0.6), kAnchorHeight - Real(0.9), Real(0.3)),
                                  Real(0.15), method);
        const int lower = addBall(world, prefix + "-lower", Vec3(x + Real(1.2), kAnchorHeight - Real(1.6), 0),
                                  Real(0.15), method);
        Spring top;
        top.bodyA = upper;
        top.anchorB = Vec3(x, kAnchorHeight, 0);
        top.restLength = 1;
        top.stiffness = kChainStiffness;
        world.springs.push_back(top);
        Spring link;
        link.bodyA = lower;
        link.bodyB = upper;
        link.restLength = 1;
        link.stiffness = kChainStiffness;
        world.springs.push_back(link);
    }
    return world;
}

World buildTHandle(GyroscopicMode gyroscopic) {
    World world = emptyWorld("t-handle", Vec3::Zero());
    world.settings.gyroscopic = gyroscopic;
    BodyDef def;
    def.name = "handle";
    def.shape = Shape::box(kHandleHalfExtents);
    def.transform.position = Vec3(0, 2, 0);
    def.mass = Real(1);
    // 6 rad/s about the intermediate axis plus a 0.3% nudge about the major axis: the nudge
    // grows exponentially until the handle flips.
    def.angularVelocity = Vec3(Real(0.02), 0, 6);
    addBody(world, def);
    return world;
}

World buildProjectile() {
    World world = emptyWorld("projectile");
    world.settings.dt = kProjectileDt;
    for (int slot = 0; slot < 3; ++slot) {
        const Vec3 lane(0, 0, (slot - 1) * Real(0.6));
        const int ball = addBall(world, std::string(toString(kMethods[slot])), kLaunchPoint + lane, Real(0.1),
                                 kMethods[slot]);
        world.motionOf(ball)->linearVelocity = kLaunchVelocity;
    }
    return world;
}

namespace {

// The demo views: chapter 1 scenes remember nothing, so plain functions serve.
void drawChains(const World& world, DebugDraw& draw) {
    drawSprings(world, draw);
    labelBodies(world, draw);
}

void chainPanel(World& world, Panel& panel) {
    for (IntegratorKind method : kMethods)
        panel.text(formatValue((std::string(toString(method)) + " energy").c_str(), methodEnergy(world, method), "J"));
    float stiffness = world.springs.empty() ? 0.0f : static_cast<float>(world.springs[0].stiffness);
    if (panel.sliderFloat("spring stiffness (N/m)", stiffness, 10.0f, 20000.0f))
        for (Spring& spring : world.springs) spring.stiffness = static_cast<Real>(stiffness);
    panel.text("Stable while h*w < 2 (Euler, Verlet) or < 2.83 (RK4); the chain's fastest mode has w = 1.6 sqrt(k/m).");
}

void drawHandle(const World& world, DebugDraw& draw) {
    labelBodies(world, draw);
    const Body& body = world.bodies[0];
    const Vec3 center = worldCenterOfMass(world, 0);
    draw.arrow(center, center + Real(0.3) * angularMomentum(world, 0), colors::kYellow);
    draw.arrow(center, center + body.transform.rotate(Vec3(0, 0, Real(0.6))), colors::kGreen);
    draw.text(center + Real(0.3) * angularMomentum(world, 0), "L", colors::kYellow);
    draw.text(center + body.transform.rotate(Vec3(0, 0, Real(0.6))), "intermediate axis", colors::kGreen);
}

void handlePanel(World& world, Panel& panel) {
    static const char* const modes[] = {"off", "explicit", "implicit"};
    int mode = static_cast<int>(world.settings.gyroscopic);
    if (panel.combo("gyroscopic term", mode, modes, 3)) world.settings.gyroscopic = static_cast<GyroscopicMode>(mode);
    panel.text(formatValue("|L|", angularMomentum(world, 0).norm(), "kg m^2/s"));
    panel.text(formatValue("energy", 0.5 * world.motions[0].angularVelocity.dot(angularMomentum(world, 0)), "J"));
    panel.text("Off: no flip. Explicit: energy grows. Implicit: flips, energy kept.");
}

void drawProjectile(const World& world, DebugDraw& draw) {
    labelBodies(world, draw);
    const Vec3 gravity = world.settings.gravity;
    auto exact = [&](double t, const Vec3& lane) {
        return Vec3(kLaunchPoint + lane + kLaunchVelocity * Real(t) + Real(0.5 * t * t) * gravity);
    };
    for (int slot = 0; slot < 3; ++slot) {
        const Vec3 lane(0, 0, (slot - 1) * Real(0.6));
        const double duration = world.time + 0.5;
        const int segments = 60;
        for (int i = 0; i < segments; ++i)
            draw.line(exact(duration * i / segments, lane), exact(duration * (i + 1) / segments, lane),
                      colors::kWhite);
        draw.point(exact(world.time, lane), 6, colors::kWhite);
    }
}

}  // namespace

void addChapter01Scenes(Registry& registry) {
    const char* const category = "Integrators";
    registry.addScene({"integrators-side-by-side", 1, category, prose(R"(
        Three identical spring chains: RK4's swing slowly dies down, Verlet and semi-implicit Euler keep
        their energy within a band.)"),
        buildIntegratorsSideBySide, statelessView(drawChains, chainPanel)});
    registry.addScene({"t-handle", 1, category, prose(R"(
        Spun about its intermediate axis, the handle flips over every few seconds while its angular momentum
        (arrow) stays put.)"),
        [] { return buildTHandle(); }, statelessView(drawHandle, handlePanel)});
    registry.addScene({"projectile", 1, category, prose(R"(
        Verlet and RK4 stay on the exact parabola (white); semi-implicit Euler runs below it by |g| h t / 2.)"),
        buildProjectile, statelessView(drawProjectile)});
}

}  // namespace stepwise
