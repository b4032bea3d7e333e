#include "11_wide_solve/joint_hand_on.h"
#include "math/same_bits.h"
#include "world/heap_bytes.h"

#include <cmath>
#include <utility>

namespace stepwise {

namespace {

bool sameMotor(const std::optional<JointMotor>& a, const std::optional<JointMotor>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->speed == b->speed && a->maxForce == b->maxForce);
}

// Every field chapter 8's rules read of a joint.
bool sameJoint(const JointDesc& a, const JointDesc& b) {
    return a.type == b.type && a.bodyA == b.bodyA && a.bodyB == b.bodyB && sameBits(a.localAnchorA, b.localAnchorA) &&
           sameBits(a.localAnchorB, b.localAnchorB) && sameBits(a.axis, b.axis) &&
           sameBits(a.referenceRotation, b.referenceRotation) && a.length == b.length && a.springHertz == b.springHertz &&
           a.springDampingRatio == b.springDampingRatio && a.limits == b.limits && a.coneAngle == b.coneAngle &&
           a.twistLimits == b.twistLimits && sameMotor(a.motor, b.motor) && a.frictionTorque == b.frictionTorque &&
           a.collideConnected == b.collideConnected;
}

HandedBody bodyNow(const World& world, int body) {
    HandedBody now;
    now.body = body;
    now.pose = world.bodies[static_cast<std::size_t>(body)].transform;
    if (const Motion* motion = world.motionOf(body)) {
        now.inverseMass = motion->inverseMass;
        now.localCenter = motion->localCenter;
        now.inverseInertiaLocal = motion->inverseInertiaLocal;
    }
    return now;
}

// Whether `was` is how the body stands in the World now, bit for bit.
bool unchangedBody(const World& world, const HandedBody& was) {
    const Transform& pose = world.bodies[static_cast<std::size_t>(was.body)].transform;
    if (!sameBits(pose.position, was.pose.position) || !sameBits(pose.rotation, was.pose.rotation)) return false;
    const Motion* motion = world.motionOf(was.body);
    if (!motion) return was.inverseMass == 0;
    return sameBits(motion->inverseMass, was.inverseMass) && sameBits(motion->localCenter, was.localCenter) && sameBits(motion->inverseInertiaLocal, was.inverseInertiaLocal);
}

bool sameRoom(const JointRoom& a, const JointRoom& b) {
    return a.joint == b.joint && a.rows == b.rows && a.block == b.block && a.keepable == b.keepable &&
           a.slotA == b.slotA && a.slotB == b.slotB;
}

// Whether the piece lays its joints out as the last one did: the same joints in the same slots,
// the same substep and feedback.
bool sameLayout(const World& world, Real h, const JointPass& pass, const HandedJointRows& handed) {
    const Settings& settings = world.settings;
    if (handed.h != h || handed.jointHertz != settings.jointHertz || handed.jointDampingRatio != settings.jointDampingRatio ||
        handed.warmStarting != settings.warmStarting)
        return false;
    if (handed.joints != pass.joints || handed.rooms.size() != pass.rooms.size() ||
        handed.bodies.size() != pass.worldBody.size() || handed.packed.joints.size() != pass.joints.size())
        return false;
    for (std::size_t i = 0; i < pass.rooms.size(); ++i)
        if (!sameRoom(handed.rooms[i], pass.rooms[i])) return false;
    return true;
}

// What the handed rows hold, their vectors' room included.
std::size_t handedBytes(const HandedJointRows& handed) {
    std::size_t bytes = sizeof(HandedJointRows) + capacityBytes(handed.packed.joints) + capacityBytes(handed.packed.groups) +
                        capacityBytes(handed.packedEntry) + capacityBytes(handed.joints) + capacityBytes(handed.rooms) +
                        capacityBytes(handed.descs) + capacityBytes(handed.impulses) + capacityBytes(handed.bodies);
    for (const JointLaneGroup& group : handed.packed.groups) bytes += capacityBytes(group.rows);
    return bytes;
}

}  // namespace

// [ch11-take-handed]
void takeHandedJointRows(World& world, Real h, JointPass& pass) {
    // pass.laidOut is false from prepareJointPass until the layout is found to stand.
    std::shared_ptr<HandedJointRows>& held = world.step.jointRows;
    if (!held) return;
    const bool layoutStands = sameLayout(world, h, pass, *held);
    // This World's alone: taken as it is. Shared with a copy of the World (a snapshot, a rewind):
    // copied first, and only if its rows can be kept.
    if (held.use_count() == 1)
        pass.handOn = std::move(held);
    else if (layoutStands)
        pass.handOn = std::make_shared<HandedJointRows>(*held);
    held.reset();
    world.step.jointRowsBytes = 0;
    if (!pass.handOn) return;
    HandedJointRows& handed = *pass.handOn;
    std::swap(pass.packed, handed.packed);  // the layout's room, whatever comes of the rest
    if (!layoutStands) return;
    pass.laidOut = true;
    pass.packedEntry = handed.packedEntry;
    pass.handedLanes.assign(static_cast<std::size_t>(pass.packed.groupCount), 0u);
    pass.descHanded.resize(pass.joints.size());
    std::vector<char>& unchanged = pass.bodyUnchanged;
    unchanged.resize(handed.bodies.size());
    for (std::size_t e = 0; e < handed.bodies.size(); ++e)
        unchanged[e] = handed.bodies[e].body == pass.worldBody[e] && unchangedBody(world, handed.bodies[e]) ? 1 : 0;
    for (std::size_t i = 0; i < pass.joints.size(); ++i) {
        const JointDesc& joint = world.joints[static_cast<std::size_t>(pass.joints[i])];
        pass.descHanded[i] = sameJoint(joint, handed.descs[i]) ? 1 : 0;
        if (!pass.descHanded[i] || !unchanged[static_cast<std::size_t>(pass.entryA[i])] ||
            !unchanged[static_cast<std::size_t>(pass.entryB[i])] || !sameBits(pass.carried[i], handed.impulses[i]))
            continue;
        const PackedJoint& packed = pass.packed.joints[i];
        pass.handedLanes[static_cast<std::size_t>(packed.group)] |= 1u << packed.lane;
    }
}
// [ch11-take-handed]

void handJointRowsOn(World& world, const SolverBodies& bodies, Real h, JointPass& pass) {
    if (!pass.handOn) pass.handOn = std::make_shared<HandedJointRows>();
    HandedJointRows& handed = *pass.handOn;
    rebaseBuiltTurns(pass.packed, bodies.states.data());  // packed_joint_rows.h
    handed.packedEntry = pass.packedEntry;
    if (!pass.laidOut) {  // else the same already (sameLayout)
        handed.joints = pass.joints;
        handed.rooms = pass.rooms;
    }
    handed.descs.resize(pass.joints.size());
    handed.impulses.resize(pass.joints.size());
    for (std::size_t i = 0; i < pass.joints.size(); ++i) {
        const auto j = static_cast<std::size_t>(pass.joints[i]);
        if (!pass.laidOut || !pass.descHanded[i]) handed.descs[i] = world.joints[j];  // else the same already
        handed.impulses[i] = j < world.jointImpulses.size() ? world.jointImpulses[j] : JointImpulses{};
    }
    handed.bodies.resize(pass.worldBody.size());
    for (std::size_t e = 0; e < pass.worldBody.size(); ++e) {
        if (pass.laidOut && pass.bodyUnchanged[e])  // its masses the same already: its pose moved
            handed.bodies[e].pose = world.bodies[static_cast<std::size_t>(pass.worldBody[e])].transform;
        else
            handed.bodies[e] = bodyNow(world, pass.worldBody[e]);
    }
    const Settings& settings = world.settings;
    handed.h = h;
    handed.jointHertz = settings.jointHertz;
    handed.jointDampingRatio = settings.jointDampingRatio;
    handed.warmStarting = settings.warmStarting;
    std::swap(pass.packed, handed.packed);
    world.step.jointRowsBytes = handedBytes(handed);
    world.step.jointRows = std::move(pass.handOn);
}

}  // namespace stepwise
