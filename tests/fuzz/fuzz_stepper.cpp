// Fuzz target: the whole step (the latest chapter's pipeline) on small random scenes: a ground (a
// box, a bumpy triangle mesh or a height field with holes) and 1 to 6 bodies of every shape kind
// (compounds and cylinders too), random sizes, speeds, spins, materials and settings,
// joints of every type between them. 100 frames must run without a crash or a hang (libFuzzer's
// -timeout). With the settings whose stability the engine claims (semi-implicit Euler, the
// gyroscopic term implicit or off) every body must stay finite, and when nothing drives the
// scene (no kinematic body) its energy must stay bounded: contacts may remove energy, and may
// add only a little (position correction pushing an overlap apart).
//
// The other settings are conditionally stable by design (chapter 1): the explicit gyroscopic
// term gains energy every step, and RK4 and Verlet treat the term explicitly inside their
// stages, so a needle-thin body spun fast about its long axis by a contact diverges within a
// few frames. Those runs must still not crash or hang; a diverged one simply ends (the runner
// reports it as unstable, exit code 3).
#include "fuzz_input.h"
#include "random_shapes.h"

#include "app/registry.h"
#include "world/scene.h"
#include "world/scene_limits.h"
#include "world/world.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

using namespace stepwise;
using namespace stepwise::fuzz;

namespace {

constexpr const char* kTarget = "fuzz_stepper";

Settings randomSettings(FuzzInput& input) {
    Settings settings;
    settings.substeps = input.integer(1, 4);
    settings.solverIterations = input.integer(1, 20);
    settings.baumgarte = Real(input.uniform(0, 0.5));
    settings.warmStarting = input.flag();
    settings.integrator = IntegratorKind(input.integer(0, 2));
    settings.gyroscopic = GyroscopicMode(input.integer(0, 2));
    settings.solver = SolverKind(input.integer(0, 1));
    return settings;
}

/// Room to spare for what the contacts may add: 5% of the potential energy the bodies could
/// release falling their own size, plus 2% of the starting energy.
double energyAllowance(const World& world, double startEnergy) {
    double scale = 0;
    for (const Motion& motion : world.motions) {
        const Body& body = world.bodies[std::size_t(motion.bodyIndex)];
        scale += double(motion.mass) * double(world.settings.gravity.norm()) * double(boundingRadius(body.shape));
    }
    return 0.05 * scale + 0.02 * std::abs(startEnergy) + 1e-6;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    FuzzInput input(data, size);
    World world;
    world.name = "fuzz";
    world.settings = randomSettings(input);

    // The bodies start above the ground's highest point, so none starts inside it.
    Real groundTop = 0;
    if (const std::optional<Shape> ground = randomGround(input)) {
        BodyDef def;
        def.name = "ground";
        def.type = BodyType::Static;
        def.shape = *ground;
        def.transform.position = Vec3(-15, 0, -20);
        groundTop = computeAabb(def.shape, def.transform).max.y();
        addBody(world, def);
    } else {
        addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(50, Real(0.5), 50));
    }

    const int count = input.integer(1, 6);
    bool driven = false;
    double x = -10;
    for (int i = 0; i < count; ++i) {
        const double bodySize = input.logUniform(0.05, 2);
        const std::optional<Shape> shape = randomBodyShape(input, bodySize);
        if (!shape) continue;
        BodyDef def;
        def.name = "body" + std::to_string(i);
        def.type = input.integer(0, 7) == 0 ? BodyType::Kinematic : BodyType::Dynamic;
        driven |= def.type == BodyType::Kinematic;
        def.shape = *shape;
        const Real radius = boundingRadius(def.shape);
        // Side by side without overlap at the start, from resting on the ground to 3 m above it.
        x += double(radius) + 0.05;
        const Real height = Real(input.uniform(0, 3));
        const Real depth = Real(input.uniform(-1, 1));
        def.transform.position = Vec3(Real(x), groundTop + radius + height, depth);
        x += double(radius) + 0.05;
        def.transform.rotation = randomRotation(input);
        def.linearVelocity = input.vector(-10, 10).cast<Real>();
        def.angularVelocity = input.vector(-10, 10).cast<Real>();
        def.density = Real(input.logUniform(10, 10000));
        // The scene format refuses masses below kMinMass (scene_limits.h); the engine's claims are
        // for what it accepts. Lighter bodies are an open case: a 0.08 mg capsule, 1.4 mm long,
        // against a hull went non-finite in its first frame (docs/reliability.md).
        if (computeMassProperties(def.shape, def.density).mass < kMinMass) continue;
        def.material.friction = Real(input.uniform(0, 1.2));
        def.material.restitution = Real(input.uniform(0, 1));
        def.bullet = input.flag();
        try {
            addBody(world, def);
        } catch (const std::invalid_argument&) {
            continue;  // a hull too thin to have a mass: rejected, correctly
        }
    }
    if (world.bodies.size() < 2) return 0;
    // Joints between random pairs (solved from chapter 8; ignored with a warning before), each
    // satisfied where the bodies start: the anchors at one world point near A (a distance joint's
    // two points apart, its length theirs), the rest orientation the one they have. A joint that
    // starts violated pulls its bodies together, which may rightly lift one and add energy.
    const int jointCount = input.integer(0, 3);
    for (int j = 0; j < jointCount; ++j) {
        JointDesc joint;
        joint.type = static_cast<JointType>(input.integer(0, 5));  // every JointType
        joint.bodyA = input.integer(0, int(world.bodies.size()) - 1);
        joint.bodyB = input.integer(0, int(world.bodies.size()) - 1);
        if (joint.bodyA == joint.bodyB) continue;
        const Transform& poseA = world.bodies[std::size_t(joint.bodyA)].transform;
        const Transform& poseB = world.bodies[std::size_t(joint.bodyB)].transform;
        // Anchors near their bodies: a 4 mm box on a 0.8 m lever, or a capsule jointed 90 m from
        // its centre, is the open case of docs/reliability.md (tests/fuzz/open/stepper/), as
        // needles are the narrowphase's. A joint's one point lies between the two bodies, weighted
        // towards the smaller; a pair too far apart for it to be near both gets no such joint.
        const Real radiusA = boundingRadius(world.bodies[std::size_t(joint.bodyA)].shape);
        const Real radiusB = boundingRadius(world.bodies[std::size_t(joint.bodyB)].shape);
        const auto nearBody = [](const Vec3& point, const Transform& pose, Real radius) {
            return (point - pose.position).norm() <= 4 * radius + Real(0.1);
        };
        Vec3 pointA, pointB;
        if (joint.type == JointType::Distance) {
            pointA = poseA.apply(2 * radiusA * input.vector(-1, 1).cast<Real>());
            pointB = poseB.apply(2 * radiusB * input.vector(-1, 1).cast<Real>());
        } else {
            const Real towardB = radiusA / (radiusA + radiusB);
            pointA = poseA.position + towardB * (poseB.position - poseA.position) +
                     std::min(radiusA, radiusB) * input.vector(-1, 1).cast<Real>();
            pointB = pointA;
        }
        if (!nearBody(pointA, poseA, radiusA) || !nearBody(pointB, poseB, radiusB)) continue;
        joint.localAnchorA = poseA.applyInverse(pointA);
        joint.localAnchorB = poseB.applyInverse(pointB);
        joint.length = (pointB - pointA).norm();
        joint.referenceRotation = poseA.rotation.conjugate() * poseB.rotation;
        joint.axis = randomRotation(input) * Vec3::UnitY();
        joint.coneAngle = Real(input.uniform(0, 3));
        world.joints.push_back(joint);
    }

    // The scene's own count or "auto" (the planner's, from 10): both are what users write. Drawn
    // after every older draw, so that the inputs kept before it existed still build their scenes.
    if (input.flag()) world.settings.planIterations = false;
    else world.settings.solverIterations = Settings{}.solverIterations;
    // Then the rest of the settings a scene may choose, each draw after the last (a byte past an
    // input's end reads as 0: the default of each).
    world.settings.stabilisation = Stabilisation(input.integer(0, 3) ^ 1);  // 0: Relax, the default
    world.settings.ccd = CcdMode(input.integer(0, 2));
    world.settings.manifoldContacts = !input.flag();
    world.settings.sleeping = !input.flag();

    // STEPWISE_FUZZ_SCENE=1 prints the scene (as a scene file) before stepping it: a failing input
    // becomes a file `stepwise run` can replay and a test can load.
    if (std::getenv("STEPWISE_FUZZ_SCENE")) std::fprintf(stderr, "%s\n", saveSceneToString(world).c_str());
    Pipeline pipeline = chapterRegistry().makePipeline(world);
    const double startEnergy = computeEnergy(world).total();
    const bool claimsStability = world.settings.integrator == IntegratorKind::SemiImplicitEuler &&
                                 world.settings.gyroscopic != GyroscopicMode::Explicit;
    for (int frame = 0; frame < 100; ++frame) {
        pipeline.step(world);
        for (const Motion& motion : world.motions) {
            const Body& body = world.bodies[std::size_t(motion.bodyIndex)];
            const bool finite = body.transform.position.allFinite() && body.transform.rotation.coeffs().allFinite() &&
                                motion.linearVelocity.allFinite() && motion.angularVelocity.allFinite();
            if (!finite && !claimsStability) return 0;
            STEPWISE_FUZZ_CHECK(kTarget, finite, frame, motion.bodyIndex);
        }
    }
    // The energy bound is part of the same claim: the explicit gyroscopic term gains energy by
    // design (a spinning capsule on a distance joint: 1,346 J to 2,572 J in 100 frames, and to
    // 463 J with the implicit term; found by the CI smoke).
    if (driven || !claimsStability) return 0;
    const double endEnergy = computeEnergy(world).total();
    const double allowance = energyAllowance(world, startEnergy);
    STEPWISE_FUZZ_CHECK(kTarget, endEnergy <= startEnergy + allowance, endEnergy - startEnergy, allowance);
    return 0;
}
