#include "08_joints/scenes.h"

#include "08_joints/builders.h"
#include "app/registry.h"
#include "math/random.h"

namespace stepwise {

void addGround(World& world) {
    BodyDef ground;
    ground.name = "ground";
    ground.type = BodyType::Static;
    ground.shape = Shape::box(Vec3(20, Real(0.5), 20));
    ground.transform.position = Vec3(0, Real(-0.5), 0);
    addBody(world, ground);
}

World buildRagdollPile(int ragdolls, unsigned seed) {
    World world;
    world.name = "joints-ragdoll-pile";
    addGround(world);
    Random random(seed);
    for (int i = 0; i < ragdolls; ++i) {
        RagdollSpec spec;
        spec.prefix = "ragdoll" + std::to_string(i);
        spec.pelvis = Vec3(random.uniformReal(Real(-0.3), Real(0.3)), Real(1.2) + Real(1.0) * Real(i), random.uniformReal(Real(-0.3), Real(0.3)));
        // Lying down, turned about the vertical at random: limbs cross the ones below.
        spec.orientation = Quat(Eigen::AngleAxis<Real>(random.uniformReal(0, 2 * kPi), Vec3::UnitY())) *
                           Quat(Eigen::AngleAxis<Real>(kPi / 2, Vec3::UnitX()));
        addRagdoll(world, spec);
    }
    return world;
}

void addChapter08Scenes(Registry& registry) {
    const char* const category = "Joints";
    registry.addScene({"joints-ragdoll-pile", 8, category, "ten ragdolls fall in a heap and come to rest, joints holding",
                       [] { return buildRagdollPile(); }, {}});
}

}  // namespace stepwise
