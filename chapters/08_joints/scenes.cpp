#include "08_joints/scenes.h"

#include "08_joints/builders.h"
#include "08_joints/joint_view.h"
#include "app/registry.h"
#include "math/random.h"

namespace stepwise {

namespace {


Quat turn(Real degrees, const Vec3& axis) { return Quat(angleAxis(degrees * kDegree, axis)); }

int addDynamic(World& world, const std::string& name, const Shape& shape, const Vec3& position,
               const Quat& rotation = Quat::Identity()) {
    BodyDef def;
    def.name = name;
    def.shape = shape;
    def.transform = Transform{position, rotation};
    return addBody(world, def);
}

/// Joins `b` to `a` at the world point `at`: the anchors are `at` in each body's frame, so the
/// joint starts exactly satisfied, and B's pose now is the joint's rest pose.
JointDesc& join(World& world, JointType type, int a, int b, const Vec3& at, const Vec3& axis = Vec3::UnitY()) {
    JointDesc joint;
    joint.type = type;
    joint.bodyA = a;
    joint.bodyB = b;
    const Transform& poseA = world.bodies[std::size_t(a)].transform;
    const Transform& poseB = world.bodies[std::size_t(b)].transform;
    joint.localAnchorA = poseA.rotation.conjugate() * (at - poseA.position);
    joint.localAnchorB = poseB.rotation.conjugate() * (at - poseB.position);
    joint.axis = poseA.rotation.conjugate() * axis.normalized();
    joint.referenceRotation = (poseA.rotation.conjugate() * poseB.rotation).normalized();
    world.joints.push_back(joint);
    return world.joints.back();
}

void addStack(World& world, const Vec3& base, int boxes) {
    const Real half = Real(0.25);
    for (int level = 0; level < boxes; ++level)
        addDynamic(world, "stack" + std::to_string(level), Shape::box(Vec3::Constant(half)),
                   base + Vec3(0, half + 2 * half * Real(level), 0));
}

// The demo's default camera looks from yaw 0.6 rad about +y (renderer_dx12/camera.h). The sandbox
// and the gallery are laid out in a frame turned by that yaw, x running across the screen and z
// towards the viewer, so they open with every piece in view and moving across the screen.
constexpr Real kViewYaw = Real(0.6);
const Quat kFacingView(angleAxis(kViewYaw, Vec3::UnitY()));

Vec3 facingView(Real across, Real height, Real towardsViewer) {
    return kFacingView * Vec3(across, height, towardsViewer);
}

// ---- the gallery: one post per joint type, in a row across the view ----

constexpr Real kPostHeight = Real(2.2);  // m, the posts' centres: the spring's ball clears the ground
constexpr Real kPostSpacing = Real(1.4);
const Vec3 kPostHalf = Vec3::Constant(Real(0.1));
constexpr Real kBarThickness = Real(0.07);  // m, half

/// A bar running across the view from the point `from` (its left end), 0.8 m long unless told.
int addBar(World& world, const std::string& name, const Vec3& from, Real halfLength = Real(0.4)) {
    return addDynamic(world, name, Shape::box(Vec3(halfLength, kBarThickness, kBarThickness)),
                      from + kFacingView * Vec3(halfLength, 0, 0), kFacingView);
}

}  // namespace

void addGround(World& world) { addStaticBox(world, "ground", Vec3(0, Real(-0.5), 0), Vec3(20, Real(0.5), 20)); }

// [ch08-platform]
int addMovingPlatform(World& world, const PlatformSpec& spec) {
    BodyDef platform;
    platform.name = spec.prefix;
    platform.type = BodyType::Kinematic;
    platform.shape = Shape::box(Vec3(1, Real(0.1), Real(0.75)));
    platform.transform.rotation = Quat(angleAxis(spec.heading, Vec3::UnitY()));
    KinematicPath path;
    path.amplitude = platform.transform.rotation * Vec3(spec.amplitude, 0, 0);
    path.period = spec.period;
    path.phase = kPi / 2;  // sin = 1: the far end of the path, at rest
    platform.path = path;
    platform.transform.position = spec.center + path.amplitude;
    const int index = addBody(world, platform);
    // The rider: a 0.6 m box resting on the platform's top face.
    addDynamic(world, spec.prefix + "-rider", Shape::box(Vec3::Constant(Real(0.3))),
               platform.transform.position + Vec3(0, Real(0.1) + Real(0.3), 0), platform.transform.rotation);
    return index;
}
// [ch08-platform]

int addRotator(World& world, const RotatorSpec& spec) {
    BodyDef paddle;
    paddle.name = spec.prefix;
    paddle.type = BodyType::Kinematic;
    paddle.shape = Shape::box(Vec3(spec.paddleHalfLength, Real(0.1), Real(0.08)));
    paddle.transform.position = spec.center + Vec3(0, Real(0.3), 0);  // sweeps 0.2 to 0.4 m up
    paddle.angularVelocity = Vec3(0, spec.spin, 0);
    const int index = addBody(world, paddle);
    // Six targets, 0.3 m tall, on a ring inside the paddle's reach, clear of its starting pose.
    for (int i = 0; i < 6; ++i) {
        const Real angle = (Real(30) + Real(60) * Real(i)) * kDegree;
        const Real radius = Real(0.55) + Real(0.1) * Real(i % 3);
        const Vec3 at = spec.center + Vec3(radius * math::cos(angle), Real(0.15), radius * math::sin(angle));
        const bool ball = i % 2 == 1;
        const Shape shape = ball ? Shape::sphere(Real(0.15)) : Shape::box(Vec3::Constant(Real(0.15)));
        const int target = addDynamic(world, spec.prefix + "-target" + std::to_string(i), shape, at);
        // The contacts have no rolling resistance: a thrown ball would roll out of the picture.
        // Drag on its spin stands in for it.
        if (ball) world.dampings.push_back({target, 0, 2});
    }
    return index;
}

World buildJointsSandbox() {
    World world = emptyWorld("joints-sandbox");
    addGround(world);
    // Facing the view (facingView): the tall pieces stand at the back, the low ones in front, and
    // the chain swings across the screen, not towards it.
    addStack(world, facingView(-3, 0, Real(-0.8)), 5);
    ChainSpec chain;
    chain.links = 10;
    chain.linkRadius = Real(0.1);
    chain.anchor = facingView(-1, 4, Real(-1.6));
    chain.direction = kFacingView * Vec3::UnitX();  // level: it swings down and across
    addChain(world, chain);
    RagdollSpec ragdoll;
    ragdoll.pelvis = facingView(Real(2.2), 3, Real(-0.8));  // feet 2 m up
    ragdoll.orientation = kFacingView * turn(25, Vec3::UnitZ());
    addRagdoll(world, ragdoll);
    PlatformSpec platform;
    platform.center = facingView(Real(-1.5), Real(0.5), Real(1));
    platform.heading = kViewYaw;
    addMovingPlatform(world, platform);
    RotatorSpec rotator;
    rotator.center = facingView(3, 0, Real(1));
    addRotator(world, rotator);
    return world;
}

// [ch08-gallery]
World buildJointGallery() {
    World world = emptyWorld("joints-gallery");
    addGround(world);
    // Posts in a row across the view, turned with it: "across" and "front" are the view's x and z.
    int slot = 0;
    const auto post = [&](const std::string& name) {
        const Vec3 at = facingView(kPostSpacing * (Real(slot++) - 3), kPostHeight, 0);
        return std::pair<int, Vec3>(addStaticBox(world, name + "-post", at, kPostHalf, kFacingView), at);
    };
    const Vec3 across = kFacingView * Vec3::UnitX(), front = kFacingView * Vec3::UnitZ();
    const Vec3 below(0, -kPostHalf.y(), 0), beside = across * kPostHalf.x();
    {   // A ball on a spring 1 m long, let go 30 cm stretched: it bounces, and settles g / omega^2
        // (6 cm) longer than its rest length.
        const auto [p, at] = post("spring");
        const int ball = addDynamic(world, "spring-ball", Shape::sphere(Real(0.15)), at + below + Vec3(0, Real(-1.3), 0));
        JointDesc& joint = join(world, JointType::Distance, p, ball, at + below);
        joint.localAnchorB = Vec3::Zero();
        joint.length = 1;
        joint.springHertz = 2;
        joint.springDampingRatio = Real(0.2);
    }
    {   // A bar on a ball socket, tilted across the view and set swinging about that axis: it
        // circles under its post.
        const auto [p, at] = post("ball-socket");
        const Vec3 pivot = at + below;
        const Quat tilt = Quat(angleAxis(35 * kDegree, front)) * kFacingView;
        const int bar = addDynamic(world, "ball-socket-bar", Shape::box(Vec3(kBarThickness, Real(0.4), kBarThickness)),
                                   pivot + tilt * Vec3(0, Real(-0.4), 0), tilt);
        join(world, JointType::BallSocket, p, bar, pivot);
        Motion& motion = *world.motionOf(bar);
        motion.angularVelocity = across * 3;
        motion.linearVelocity = motion.angularVelocity.cross(worldCenterOfMass(world, bar) - pivot);
    }
    {   // A level bar on a hinge facing the viewer: it falls and rests on its -45 degree limit.
        const auto [p, at] = post("hinge-limits");
        const int bar = addBar(world, "hinge-limits-bar", at + beside);
        join(world, JointType::Hinge, p, bar, at + beside, front).limits = {{-45 * kDegree, 45 * kDegree}};
    }
    {   // A propeller hinged at its middle in front of its post: the motor turns it at 2 rad/s.
        const auto [p, at] = post("hinge-motor");
        const Vec3 hub = at + front * Real(0.25);
        const int blade = addDynamic(world, "hinge-motor-blade", Shape::box(Vec3(Real(0.5), kBarThickness, kBarThickness)),
                                     hub, kFacingView);
        join(world, JointType::Hinge, p, blade, hub, front).motor = JointMotor{2, 50};
    }
    {   // A level bar on a cone-twist along its length, spun about it: it droops onto its 30 degree
        // cone, and the spin runs into the twist limits.
        const auto [p, at] = post("cone-twist");
        const int bar = addBar(world, "cone-twist-bar", at + beside);
        JointDesc& joint = join(world, JointType::ConeTwist, p, bar, at + beside, across);
        joint.coneAngle = 30 * kDegree;
        joint.twistLimits = {{-20 * kDegree, 20 * kDegree}};
        world.motionOf(bar)->angularVelocity = across * 4;
    }
    {   // A 2 kg block on a slider across the view, thrown left: it stops at -0.5 m, then its motor
        // (0.5 m/s, 5 N) drives it to the +0.5 m end and holds it there.
        const auto [p, at] = post("slider");
        BodyDef block;
        block.name = "slider-block";
        block.shape = Shape::box(Vec3::Constant(Real(0.12)));
        block.mass = 2;
        block.transform = Transform{at + front * Real(0.35), kFacingView};
        block.linearVelocity = across * -2;
        const int b = addBody(world, block);
        JointDesc& joint = join(world, JointType::Slider, p, b, block.transform.position, across);
        joint.limits = {{Real(-0.5), Real(0.5)}};
        joint.motor = JointMotor{Real(0.5), 5};
    }
    {   // A block welded to its post's side: it holds, level, against gravity.
        const auto [p, at] = post("fixed");
        const int block = addBar(world, "fixed-block", at + beside, Real(0.3));
        join(world, JointType::Fixed, p, block, at + beside);
    }
    return world;
}
// [ch08-gallery]

World buildPlatformScene() {
    World world = emptyWorld("joints-platform");
    addGround(world);
    addMovingPlatform(world, PlatformSpec{});
    return world;
}

World buildRotatorScene() {
    World world = emptyWorld("joints-rotator");
    addGround(world);
    addRotator(world, RotatorSpec{});
    return world;
}

World buildRagdollPile(int ragdolls, unsigned seed) {
    World world = emptyWorld("joints-ragdoll-pile");
    addGround(world);
    Random random(seed);
    for (int i = 0; i < ragdolls; ++i) {
        RagdollSpec spec;
        spec.prefix = "ragdoll" + std::to_string(i);
        // [reliability-one-draw]
        // One draw per statement (z, then x): two draws among one call's arguments come in an
        // order the compiler picks (GCC right to left, Clang left to right).
        const Real z = random.uniformReal(Real(-0.3), Real(0.3));
        const Real x = random.uniformReal(Real(-0.3), Real(0.3));
        spec.pelvis = Vec3(x, Real(1.2) + Real(1.0) * Real(i), z);
        // [reliability-one-draw]
        // Lying down, turned about the vertical at random: limbs cross the ones below.
        spec.orientation = Quat(angleAxis(random.uniformReal(0, 2 * kPi), Vec3::UnitY())) *
                           Quat(angleAxis(kPi / 2, Vec3::UnitX()));
        addRagdoll(world, spec);
    }
    return world;
}

void addChapter08Scenes(Registry& registry) {
    const char* const category = "Joints";
    // The first scene is the one the demo opens on and the render test photographs.
    registry.addScene({"joints-sandbox", 8, category, prose(R"(
        the stack stands, the chain swings from its anchor, the blue platform carries its box by friction,
        the paddle throws the small bodies and the ragdoll falls and settles; a joint more than 1 cm off
        turns red)"),
        buildJointsSandbox, jointView()});
    registry.addScene({"joints-gallery", 8, category, prose(R"(
        one joint of each type on its post: the spring bounces, the ball socket circles, one hinge rests on
        its -45 degree limit while the motor turns the other at 2 rad/s, the cone-twist droops onto its 30
        degree cone, the slider hits -0.5 m and its motor takes it to +0.5 m, the weld holds)"),
        buildJointGallery, jointView(true)});
    registry.addScene({"joints-ragdoll-pile", 8, category, prose(R"(
        ten ragdolls fall in a heap and come to rest, joints holding)"),
        [] { return buildRagdollPile(); }, jointView()});
    registry.addScene({"joints-platform", 8, category, prose(R"(
        the kinematic platform slides 2 m each way every 4 s; friction alone carries the box, which never
        slips)"),
        buildPlatformScene, jointView()});
    registry.addScene({"joints-rotator", 8, category, prose(R"(
        the kinematic paddle spins at 3 rad/s and throws the small boxes and spheres out of its sweep)"),
        buildRotatorScene, jointView()});
}

}  // namespace stepwise
