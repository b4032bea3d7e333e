#include "04_pgs/scenes.h"

#include "math/random.h"

#include <cmath>
#include <string>

namespace stepwise {

int addGroundPlane(World& world, Real friction, Real restitution) {
    return addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20), Quat::Identity(),
                        Material{friction, restitution});
}

int addBall(World& world, const std::string& name, const Vec3& position, Real radius, Real mass,
            const Material& material) {
    BodyDef def;
    def.name = name;
    def.shape = Shape::sphere(radius);
    def.transform.position = position;
    def.mass = mass;
    def.material = material;
    return addBody(world, def);
}

int addCrate(World& world, const std::string& name, const Vec3& position, const Vec3& halfExtents, Real mass,
             const Material& material, const Quat& rotation) {
    BodyDef def;
    def.name = name;
    def.shape = Shape::box(halfExtents);
    def.transform.position = position;
    def.transform.rotation = rotation;
    def.mass = mass;
    def.material = material;
    return addBody(world, def);
}

World buildDropScene() {
    World world = emptyWorld("pgs-drop");
    addGroundPlane(world);
    Random random(4);
    for (int i = 0; i < 8; ++i) {
        const Vec3 position(Real(-2.1) + Real(1.4) * static_cast<Real>(i % 4), Real(1.5) + Real(1.2) * static_cast<Real>(i / 4),
                            random.uniformReal(Real(-0.4), Real(0.4)));
        const Material material{Real(0.6), i % 4 == 3 ? Real(0.5) : Real(0)};
        if (i % 2 == 0) {
            // One draw per statement: the order of a call's arguments is unspecified in C++ (GCC and Clang
            // differ), so draws inside one expression would give each compiler a different scene. z, y, x
            // is the order GCC evaluated them in, so the scenes are the ones GCC always built.
            const Real axisZ = random.uniformReal(-1, 1);
            const Real axisY = random.uniformReal(-1, 1);
            const Real axisX = random.uniformReal(-1, 1);
            const Vec3 axis = Vec3(axisX, axisY, axisZ).normalized();
            const Quat rotation(angleAxis(random.uniformReal(0, kPi), axis));
            addCrate(world, "box" + std::to_string(i), position, Vec3(Real(0.4), Real(0.3), Real(0.35)), 2, material,
                     rotation);
        } else {
            addBall(world, "ball" + std::to_string(i), position, random.uniformReal(Real(0.25), Real(0.45)), 2, material);
        }
    }
    return world;
}

World buildBounceScene(Real height) {
    World world = emptyWorld("pgs-bounce");
    addGroundPlane(world);
    const Real restitutions[] = {Real(0.3), Real(0.6), Real(0.9), Real(1.0)};
    const Real radius = Real(0.25);
    for (int i = 0; i < 4; ++i) {
        std::string name = "ball-e" + std::to_string(restitutions[i]).substr(0, 3);
        addBall(world, name, Vec3(Real(-1.5) + static_cast<Real>(i), height + radius, 0), radius, 1,
                Material{Real(0.6), restitutions[i]});
    }
    return world;
}

World buildRestingScene() {
    World world = emptyWorld("pgs-resting");
    addGroundPlane(world);
    const Real slop = world.settings.slop;
    addCrate(world, "box", Vec3(-1, Real(0.5) - slop, 0), Vec3(Real(0.5), Real(0.5), Real(0.5)), 1, Material{});
    addBall(world, "ball", Vec3(Real(0.5), Real(0.5) - slop, 0), Real(0.5), 1, Material{});
    // 10 kg on 1 kg: both radius 0.4, stacked exactly on the vertical.
    const Real radius = Real(0.4);
    addBall(world, "light", Vec3(2, radius - slop, 0), radius, 1, Material{});
    addBall(world, "heavy", Vec3(2, 3 * radius - 2 * slop, 0), radius, 10, Material{});
    return world;
}

World buildRampScene(Real angle, Real friction, int* box) {
    World world = emptyWorld("pgs-ramp");
    const Quat tilt(angleAxis(angle, Vec3::UnitZ()));
    const Vec3 rampHalf(4, Real(0.25), 2);
    const Vec3 rampCenter(0, 0, 0);
    const Vec3 rampNormal = tilt * Vec3::UnitY();
    addStaticBox(world, "ramp", rampCenter, rampHalf, tilt, Material{friction, 0});
    const Real half = Real(0.5);
    const Vec3 boxCenter = rampCenter + rampNormal * (rampHalf.y() + half - world.settings.slop);
    const int boxIndex = addCrate(world, "box", boxCenter, Vec3(half, half, half), 1, Material{friction, 0}, tilt);
    if (box) *box = boxIndex;
    return world;
}

World buildFrictionScene(Real friction) {
    World world = emptyWorld("pgs-friction");
    // One contact point per box rocks it from corner to corner; at 60 Hz that rocking walks a box
    // down even a gentle ramp. 8 substeps make it small enough to show Coulomb's law.
    world.settings.substeps = 8;
    addGroundPlane(world, friction);
    const Real critical = math::atan(friction);
    const Real offsets[] = {Real(0.2), Real(-0.2)};  // rad: steeper, gentler than atan(mu)
    for (int i = 0; i < 2; ++i) {
        const Real angle = critical + offsets[i];
        const Quat tilt(angleAxis(angle, Vec3::UnitZ()));
        const Vec3 rampCenter(2, 3, Real(-2) + Real(2.5) * static_cast<Real>(i));
        const Vec3 rampNormal = tilt * Vec3::UnitY();
        addStaticBox(world, i == 0 ? "ramp-steep" : "ramp-gentle", rampCenter, Vec3(3, Real(0.2), 1), tilt,
                     Material{friction, 0});
        addCrate(world, i == 0 ? "box-slides" : "box-stays",
                 rampCenter + rampNormal * (Real(0.2) + Real(0.4) - world.settings.slop),
                 Vec3(Real(0.4), Real(0.4), Real(0.4)), 1, Material{friction, 0}, tilt);
    }
    const int ball = addBall(world, "ball-rolls", Vec3(-6, Real(0.3) - world.settings.slop, 3), Real(0.3), 1,
                             Material{friction, 0});
    world.motionOf(ball)->linearVelocity = Vec3(4, 0, 0);
    return world;
}

World buildSpherePitScene(int count) {
    World world = emptyWorld("pgs-sphere-pit");
    addGroundPlane(world);
    const Real inner = Real(1.0);       // half width of the pit, m
    const Real wall = Real(0.2);        // half thickness
    const Real height = Real(1.5);      // half height
    for (int side = 0; side < 4; ++side) {
        const bool alongX = side < 2;
        const Real sign = side % 2 == 0 ? Real(1) : Real(-1);
        const Vec3 center = alongX ? Vec3(sign * (inner + wall), height, 0) : Vec3(0, height, sign * (inner + wall));
        const Vec3 half = alongX ? Vec3(wall, height, inner + 2 * wall) : Vec3(inner + 2 * wall, height, wall);
        addStaticBox(world, "wall" + std::to_string(side), center, half, Quat::Identity(), Material{});
    }
    Random random(7);
    for (int i = 0; i < count; ++i) {
        const int layer = i / 9;
        const int cell = i % 9;
        // One draw per statement: the order of a call's arguments is unspecified in C++ (GCC and Clang
        // differ), so draws inside one expression would give each compiler a different scene. z, then x
        // is the order GCC evaluated them in, so the scenes are the ones GCC always built.
        const Real jitterZ = random.uniformReal(Real(-0.03), Real(0.03));
        const Real jitterX = random.uniformReal(Real(-0.03), Real(0.03));
        const Vec3 position(Real(-0.6) + Real(0.6) * static_cast<Real>(cell % 3) + jitterX,
                            Real(0.4) + Real(0.6) * static_cast<Real>(layer),
                            Real(-0.6) + Real(0.6) * static_cast<Real>(cell / 3) + jitterZ);
        addBall(world, "ball" + std::to_string(i), position, random.uniformReal(Real(0.2), Real(0.28)), 1, Material{});
    }
    return world;
}

}  // namespace stepwise
